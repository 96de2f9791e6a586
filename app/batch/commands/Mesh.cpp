// `sdfwb --batch mesh`: the zero set as a mesh, with its error against the exact field.
#include "Common.h"

namespace sdfwb::app {

int runMesh(const jobs::MeshRequest& request, const OutputOptions& output) {
    return runWithGl(request, output, [](const jobs::MeshReport& r) {
        std::printf("wrote %s: %llu vertices, %llu triangles at resolution %d, %.2f s\n", r.output.c_str(),
                    (unsigned long long)r.vertices, (unsigned long long)r.triangles, r.resolution, r.meshSeconds);
        std::printf("  topology           %s: %llu boundary edges, %llu non-manifold edges, %llu degenerate triangles\n",
                    r.watertight ? "watertight" : "not watertight", (unsigned long long)r.boundaryEdges,
                    (unsigned long long)r.nonManifoldEdges, (unsigned long long)r.degenerateTriangles);
        std::printf("  skipping           Lipschitz bound %.3g (%s); %llu of %llu blocks of 8^3 cells evaluated, %llu field "
                    "evaluations\n",
                    r.lipschitzBound, r.boundSource.c_str(), (unsigned long long)r.blocksKept, (unsigned long long)r.blocks,
                    (unsigned long long)r.pointsEvaluated);
        if (r.hausdorff)
            std::printf("  error              mesh->surface mean %.3g max %.3g; surface->mesh mean %.3g max %.3g; Hausdorff %.3g "
                        "(%llu points, %.2f s)\n",
                        *r.meshToSurfaceMean, *r.meshToSurfaceMax, *r.surfaceToMeshMean, *r.surfaceToMeshMax, *r.hausdorff,
                        (unsigned long long)r.errorPoints, r.errorSeconds);
    });
}

} // namespace sdfwb::app
