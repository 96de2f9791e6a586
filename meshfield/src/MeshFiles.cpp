// Reading triangle meshes through assimp (a well-kept library Debian packages; it reads OBJ, PLY,
// STL, OFF, glTF and more).
#include <meshfield/MeshField.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <array>
#include <map>

namespace sdfwb::meshfield {

Expected<TriangleMesh> readTriangleMesh(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return Error{path.string() + ": no such file"};
    Assimp::Importer importer;
    // Node transforms are baked in (a glTF's parts sit where its scene puts them).
    const aiScene* scene = importer.ReadFile(path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                                                aiProcess_PreTransformVertices);
    if (!scene) return Error{path.string() + ": cannot read the mesh: " + importer.GetErrorString()};
    // Equal positions become one vertex (STL stores each triangle's corners apart, and assimp keeps
    // vertices apart when their normals differ), so shared edges share indices.
    TriangleMesh mesh;
    std::map<std::array<float, 3>, std::uint32_t> index;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* in = scene->mMeshes[m];
        std::vector<std::uint32_t> merged(in->mNumVertices);
        for (unsigned v = 0; v < in->mNumVertices; ++v) {
            const std::array<float, 3> p = {in->mVertices[v].x, in->mVertices[v].y, in->mVertices[v].z};
            auto [it, inserted] = index.try_emplace(p, std::uint32_t(mesh.vertices.size()));
            if (inserted) mesh.vertices.emplace_back(p[0], p[1], p[2]);
            merged[v] = it->second;
        }
        for (unsigned f = 0; f < in->mNumFaces; ++f) {
            if (in->mFaces[f].mNumIndices != 3) continue; // points and lines
            for (int k = 0; k < 3; ++k) mesh.indices.push_back(merged[in->mFaces[f].mIndices[k]]);
        }
    }
    if (mesh.indices.empty()) return Error{path.string() + ": the file holds no triangles"};
    return mesh;
}

} // namespace sdfwb::meshfield
