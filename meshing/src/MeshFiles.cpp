// Mesh files through assimp (a well-kept library Debian packages): binary PLY, OBJ, binary STL
// and glTF binary out; anything assimp reads in.
#include <meshing/Mesh.h>

#include <meshfield/MeshField.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace sdfwb::meshing {
namespace fs = std::filesystem;
namespace {
static_assert(sizeof(glm::vec3) == 12, "vertices are written as three floats");

std::string lowerExtension(const fs::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

// assimp's exporter id for an extension.
const char* formatId(const fs::path& path) {
    static const std::map<std::string, const char*> ids = {{".ply", "plyb"}, {".obj", "obj"}, {".stl", "stlb"}, {".glb", "glb2"}};
    auto it = ids.find(lowerExtension(path));
    return it == ids.end() ? nullptr : it->second;
}

// Binary PLY written here: assimp names the face list `vertex_index`, which meshio 7 refuses; the
// PLY definition's name is `vertex_indices`, which meshio, Open3D and assimp all read.
Expected<void> writePly(const fs::path& target, const fs::path& temporary, const Mesh& mesh,
                        const std::vector<std::string>& comments) {
    std::ofstream out(temporary, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\ncomment sdfwb dual contouring\n";
    for (const std::string& comment : comments) out << "comment " << comment << '\n';
    out << "element vertex " << mesh.vertices.size() << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
        << mesh.triangleCount() << "\nproperty list uchar int vertex_indices\nend_header\n";
    out.write(reinterpret_cast<const char*>(mesh.vertices.data()), std::streamsize(mesh.vertices.size() * sizeof(glm::vec3)));
    std::vector<char> faces(13 * std::min<std::size_t>(mesh.triangleCount(), 1 << 16)); // (3, a, b, c), packed
    for (std::size_t f = 0; f < mesh.triangleCount();) {
        std::size_t n = 0;
        for (; n < faces.size() / 13 && f < mesh.triangleCount(); ++n, ++f) {
            faces[13 * n] = 3;
            std::memcpy(&faces[13 * n + 1], &mesh.indices[3 * f], 3 * sizeof(std::uint32_t));
        }
        out.write(faces.data(), std::streamsize(13 * n));
    }
    out.flush();
    if (!out) return makeError(target.string() + ": cannot write the mesh (disk full or not writable)");
    return {};
}

// OBJ written here as well: assimp's OBJ carries normals indexed apart from the positions, which
// meshio 7 refuses (it expects one normal per vertex).
Expected<void> writeObj(const fs::path& target, const fs::path& temporary, const Mesh& mesh,
                        const std::vector<std::string>& comments) {
    std::ofstream out(temporary, std::ios::binary);
    out << "# sdfwb dual contouring: " << mesh.vertices.size() << " vertices, " << mesh.triangleCount() << " triangles\n";
    for (const std::string& comment : comments) out << "# " << comment << '\n';
    char line[96];
    for (const glm::vec3& v : mesh.vertices) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(v.x), double(v.y), double(v.z));
        out << line;
    }
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f)
        out << "f " << mesh.indices[3 * f] + 1 << ' ' << mesh.indices[3 * f + 1] + 1 << ' ' << mesh.indices[3 * f + 2] + 1
            << '\n';
    out.flush();
    if (!out) return makeError(target.string() + ": cannot write the mesh (disk full or not writable)");
    return {};
}

// STL and glTF binary through assimp's exporter.
Expected<void> exportWithAssimp(const fs::path& target, const fs::path& temporary, const char* id, const Mesh& mesh) {
    // A scene of one mesh, one default material, one node: what every exporter expects. The scene
    // owns what it points to (its destructor frees it).
    auto scene = std::make_unique<aiScene>();
    scene->mRootNode = new aiNode();
    scene->mRootNode->mNumMeshes = 1;
    scene->mRootNode->mMeshes = new unsigned int[1]{0};
    scene->mNumMaterials = 1;
    scene->mMaterials = new aiMaterial* [1] { new aiMaterial() };
    scene->mNumMeshes = 1;
    auto* out = new aiMesh();
    scene->mMeshes = new aiMesh* [1] { out };
    out->mMaterialIndex = 0;
    out->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    out->mNumVertices = unsigned(mesh.vertices.size());
    out->mVertices = new aiVector3D[mesh.vertices.size()];
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        out->mVertices[v] = aiVector3D(mesh.vertices[v].x, mesh.vertices[v].y, mesh.vertices[v].z);
    out->mNumFaces = unsigned(mesh.triangleCount());
    out->mFaces = new aiFace[mesh.triangleCount()];
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
        out->mFaces[f].mNumIndices = 3;
        out->mFaces[f].mIndices = new unsigned int[3]{mesh.indices[3 * f], mesh.indices[3 * f + 1], mesh.indices[3 * f + 2]};
    }
    if (Assimp::Exporter exporter; exporter.Export(scene.get(), id, temporary.string()) != aiReturn_SUCCESS)
        return makeError(target.string() + ": cannot write the mesh: " + exporter.GetErrorString());
    return {};
}

} // namespace

bool canWriteMesh(const fs::path& path) { return formatId(path) != nullptr; }

Expected<void> writeMesh(const fs::path& path, const Mesh& mesh, const std::vector<std::string>& comments) {
    const char* id = formatId(path);
    if (!id) return makeError(path.string() + ": unsupported mesh type (use .ply, .obj, .stl or .glb)");
    // Written beside the target under a hidden name (keeping the extension), then renamed.
    const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    const fs::path temporary =
        folder / ("." + path.stem().string() + ".partial-" + std::to_string(::getpid()) + path.extension().string());
    const std::string format = id;
    const Expected<void> written = format == "plyb"  ? writePly(path, temporary, mesh, comments)
                                   : format == "obj" ? writeObj(path, temporary, mesh, comments)
                                                     : exportWithAssimp(path, temporary, id, mesh);
    std::error_code ec;
    if (!written) {
        fs::remove(temporary, ec);
        return written;
    }
    fs::rename(temporary, path, ec);
    if (ec) {
        fs::remove(temporary, ec);
        return makeError(path.string() + ": cannot write the mesh: " + ec.message());
    }
    return {};
}

Expected<Mesh> readMesh(const fs::path& path) { return meshfield::readTriangleMesh(path); }

} // namespace sdfwb::meshing
