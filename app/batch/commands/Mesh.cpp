// `sdfwb --batch mesh`: the zero set as a mesh, with its error against the exact field.
#include "Common.h"

namespace sdfwb::app {

int runMesh(const values::MeshRequest& request, const OutputOptions& output) {
    return runWithGl(request, output, [](const values::MeshReport& r) {
        std::printf("wrote %s: %llu vertices, %llu triangles at resolution %d, %.2f s\n", r.output.c_str(),
                    (unsigned long long)r.vertices, (unsigned long long)r.triangles, r.resolution, r.meshSeconds);
        std::printf("  topology           %s: %llu boundary edges, %llu non-manifold edges, %llu non-manifold vertices, "
                    "%llu misoriented edges, %llu degenerate triangles\n",
                    r.manifold ? "manifold" : (r.watertight ? "watertight, not manifold" : "not watertight"),
                    (unsigned long long)r.boundaryEdges, (unsigned long long)r.nonManifoldEdges,
                    (unsigned long long)r.nonManifoldVertices, (unsigned long long)r.misorientedEdges,
                    (unsigned long long)r.degenerateTriangles);
        if (r.selfIntersections)
            std::printf("  self-crossing      %llu pairs of triangles cross each other\n",
                        (unsigned long long)*r.selfIntersections);
        if (r.boundsCutPoints > 0)
            std::printf(
                "  bounds             the shape leaves the bounds (%llu grid points inside it beyond them): closed by flat "
                "caps half a cell outside; the error below is against the field cut there\n",
                (unsigned long long)r.boundsCutPoints);
        std::printf("  skipping           Lipschitz bound %.3g (%s); %llu of %llu blocks of 8^3 cells evaluated (%llu of "
                    "them because the surface crosses into them from a kept block), %llu field evaluations\n",
                    r.lipschitzBound, r.boundSource.c_str(), (unsigned long long)r.blocksKept, (unsigned long long)r.blocks,
                    (unsigned long long)r.blocksGrown, (unsigned long long)r.pointsEvaluated);
        if (r.hausdorff)
            std::printf("  error              mesh->surface mean %.3g max %.3g; surface->mesh mean %.3g max %.3g; Hausdorff %.3g "
                        "(%llu points, %.2f s)\n",
                        *r.meshToSurfaceMean, *r.meshToSurfaceMax, *r.surfaceToMeshMean, *r.surfaceToMeshMax, *r.hausdorff,
                        (unsigned long long)r.errorPoints, r.errorSeconds);
        if (r.hausdorff)
            std::printf("  mesh->surface by    %s; field audited %s\n", r.meshToSurfaceMethod.c_str(),
                        r.fieldVerdict ? values::findingName(*r.fieldVerdict) : "not");
    });
}

} // namespace sdfwb::app

namespace sdfwb::app {

int runEval(const values::EvalRequest& request, const OutputOptions& output) {
    return runWithGl(request, output, [](const values::EvalReport& r) {
        std::printf("%s against %s: %llu vertices, %llu triangles (%s), %.2f s\n", r.mesh.c_str(), r.sdf.c_str(),
                    (unsigned long long)r.vertices, (unsigned long long)r.triangles, r.closed ? "closed" : "open", r.seconds);
        std::printf("  Chamfer L1         %.4g  (mean of accuracy %.4g and completeness %.4g; not squared)\n", r.chamferL1,
                    r.accuracyMean, r.completenessMean);
        std::printf("  Chamfer L2         %.4g  (mean of the squared distances, both ways)\n", r.chamferL2);
        std::printf("  F-score at %-7.3g %.4f (precision %.4f, recall %.4f)\n", r.tau, r.fscore, r.precision, r.recall);
        std::printf("  normal consistency %.4f\n", r.normalConsistency);
        std::printf("  Hausdorff          %.4g  (accuracy max %.4g, completeness max %.4g)\n", r.hausdorff, r.accuracyMax,
                    r.completenessMax);
        if (r.iou) std::printf("  volume IoU         %.4f  (%llu grid points)\n", *r.iou, (unsigned long long)r.occupancyPoints);
        if (r.edges)
            std::printf("  near creases       Chamfer L1 %.4g, F-score %.4f, Hausdorff %.4g  (%llu mesh and %llu surface points "
                        "within %.3g of a turn over %.3g degrees)\n",
                        r.edges->chamferL1, r.edges->fscore, r.edges->hausdorff, (unsigned long long)r.edges->meshPoints,
                        (unsigned long long)r.edges->surfacePoints, r.edgeRadius, r.edgeAngle);
        else if (r.edgeRadius > 0.0f)
            std::printf("  near creases       none: the exact surface turns by less than %.3g degrees within %.3g\n", r.edgeAngle,
                        r.edgeRadius);
        std::printf("  points             %llu on the mesh, %llu on the exact surface; distances in the SDF's units\n",
                    (unsigned long long)r.meshPoints, (unsigned long long)r.surfacePoints);
    });
}

} // namespace sdfwb::app
