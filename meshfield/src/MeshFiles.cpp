// Reading triangle meshes: PLY by a reader of our own, everything else through assimp (a well-kept
// library Debian packages; it reads OBJ, STL, OFF, glTF and more).
//
// Why PLY is read here: assimp 5.2 skips every whitespace byte after a binary PLY's `end_header`
// line, so a file whose first data byte is 0x09-0x0d or 0x20 (about one in 40 meshes) is read out
// of step: garbage indices, and a crash in its own post-processing.
#include <meshfield/MeshField.h>
#include <meshfield/PlyHeader.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

namespace sdfwb::meshfield {
namespace {

// Equal positions become one vertex (STL stores each triangle's corners apart, and assimp keeps
// vertices apart when their normals differ), so shared edges share indices.
class Welder {
public:
    std::uint32_t add(const std::array<float, 3>& p) {
        auto [it, inserted] = m_index.try_emplace(p, std::uint32_t(mesh.vertices.size()));
        if (inserted) mesh.vertices.emplace_back(p[0], p[1], p[2]);
        return it->second;
    }
    TriangleMesh mesh;

private:
    std::map<std::array<float, 3>, std::uint32_t> m_index;
};

// --- PLY (ascii, binary_little_endian, binary_big_endian) ---

// Reads the values of one element's rows from the body, in whichever format.
class PlyBody {
public:
    PlyBody(std::string data, std::size_t at, std::string format)
        : m_data(std::move(data)), m_at(at), m_format(std::move(format)) {
        if (m_format == "ascii") m_text.str(m_data.substr(m_at));
    }
    // The next value of `type`, as a double; false at the end of the data or on a malformed number.
    bool next(PlyType type, double& value) {
        if (m_format == "ascii") return bool(m_text >> value);
        const int size = plySize(type);
        if (m_at + std::size_t(size) > m_data.size()) return false;
        unsigned char bytes[8];
        std::memcpy(bytes, m_data.data() + m_at, std::size_t(size));
        m_at += std::size_t(size);
        const bool swap = (m_format == "binary_big_endian") == (std::endian::native == std::endian::little);
        if (swap) std::reverse(bytes, bytes + size);
        switch (type) {
        case PlyType::Float32: {
            float f;
            std::memcpy(&f, bytes, 4);
            value = f;
            break;
        }
        case PlyType::Float64:
            std::memcpy(&value, bytes, 8);
            break;
        case PlyType::Int8:
            value = double(std::int8_t(bytes[0]));
            break;
        case PlyType::UInt8:
            value = double(bytes[0]);
            break;
        case PlyType::Int16:
        case PlyType::UInt16: {
            std::uint16_t v;
            std::memcpy(&v, bytes, 2);
            value = type == PlyType::Int16 ? double(std::int16_t(v)) : double(v);
            break;
        }
        case PlyType::Int32:
        case PlyType::UInt32: {
            std::uint32_t v;
            std::memcpy(&v, bytes, 4);
            value = type == PlyType::Int32 ? double(std::int32_t(v)) : double(v);
            break;
        }
        case PlyType::None:
            return false;
        }
        return true;
    }

private:
    std::string m_data;
    std::size_t m_at;
    std::string m_format;
    std::istringstream m_text;
};

Expected<TriangleMesh> readPly(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::ifstream file(path, std::ios::binary);
    std::string data((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (!file && !file.eof()) return Error{name + ": cannot read the file"};
    auto header = parsePlyHeader(data, name);
    if (!header) return header.error();
    const std::string& format = header->format;
    const std::vector<PlyElement>& elements = header->elements;
    const std::size_t bodyAt = header->bodyOffset;
    PlyBody body(std::move(data), bodyAt, format);
    Welder welder;
    std::vector<std::uint32_t> vertexIndex; // the file's vertex number -> the welded vertex
    bool sawVertices = false;
    for (const PlyElement& element : elements) {
        const bool isVertex = element.name == "vertex", isFace = element.name == "face";
        int axisOf[3] = {-1, -1, -1};
        int indexList = -1;
        for (std::size_t p = 0; p < element.properties.size(); ++p) {
            const PlyProperty& property = element.properties[p];
            for (int a = 0; a < 3; ++a)
                if (isVertex && !property.isList() && property.name == std::string(1, char('x' + a))) axisOf[a] = int(p);
            if (isFace && property.isList() && (property.name == "vertex_indices" || property.name == "vertex_index"))
                indexList = int(p);
        }
        if (isVertex && (axisOf[0] < 0 || axisOf[1] < 0 || axisOf[2] < 0))
            return Error{name + ": the PLY vertex element has no x, y and z"};
        if (isFace && !sawVertices) return Error{name + ": the PLY faces come before the vertices"};
        std::vector<double> polygon;
        for (std::uint64_t row = 0; row < element.count; ++row) {
            std::array<float, 3> position{};
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                const PlyProperty& property = element.properties[p];
                double value = 0.0;
                const bool isList = property.isList();
                if (!body.next(isList ? property.countType : property.type, value))
                    return Error{name + ": the PLY data ends early, in " + element.name + " " + std::to_string(row)};
                if (!isList) {
                    for (int a = 0; a < 3; ++a)
                        if (axisOf[a] == int(p)) position[std::size_t(a)] = float(value);
                    continue;
                }
                if (!(value >= 0.0) || value > 1e6)
                    return Error{name + ": a PLY list of " + std::to_string(value) + " items in " + element.name + " " +
                                 std::to_string(row)};
                polygon.assign(std::size_t(value), 0.0);
                for (double& item : polygon)
                    if (!body.next(property.type, item))
                        return Error{name + ": the PLY data ends early, in " + element.name + " " + std::to_string(row)};
                if (int(p) != indexList) continue;
                for (double item : polygon)
                    if (!(item >= 0.0) || item >= double(vertexIndex.size()))
                        return Error{name + ": face " + std::to_string(row) + " names vertex " +
                                     std::to_string(std::int64_t(item)) + " of " + std::to_string(vertexIndex.size())};
                for (std::size_t k = 2; k < polygon.size(); ++k) // a polygon as a fan of triangles
                    for (double corner : {polygon[0], polygon[k - 1], polygon[k]})
                        welder.mesh.indices.push_back(vertexIndex[std::size_t(corner)]);
            }
            if (isVertex) {
                if (!std::isfinite(position[0]) || !std::isfinite(position[1]) || !std::isfinite(position[2]))
                    return Error{name + ": vertex " + std::to_string(row) + " is not finite"};
                vertexIndex.push_back(welder.add(position));
            }
        }
        sawVertices = sawVertices || isVertex;
    }
    if (welder.mesh.indices.empty()) return Error{name + ": the file holds no triangles"};
    return std::move(welder.mesh);
}

} // namespace

Expected<TriangleMesh> readTriangleMesh(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return Error{path.string() + ": no such file"};
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".ply") return readPly(path);
    Assimp::Importer importer;
    // Read first, check, then post-process: a scene whose faces name missing vertices would crash
    // assimp's own steps. Node transforms are baked in (a glTF's parts sit where its scene puts them).
    const aiScene* scene = importer.ReadFile(path.string(), 0);
    if (!scene) return Error{path.string() + ": cannot read the mesh: " + importer.GetErrorString()};
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* in = scene->mMeshes[m];
        for (unsigned f = 0; f < in->mNumFaces; ++f)
            for (unsigned k = 0; k < in->mFaces[f].mNumIndices; ++k)
                if (in->mFaces[f].mIndices[k] >= in->mNumVertices)
                    return Error{path.string() + ": face " + std::to_string(f) + " names vertex " +
                                 std::to_string(in->mFaces[f].mIndices[k]) + " of " + std::to_string(in->mNumVertices)};
    }
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_PreTransformVertices);
    if (!scene) return Error{path.string() + ": cannot read the mesh: " + importer.GetErrorString()};
    Welder welder;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* in = scene->mMeshes[m];
        std::vector<std::uint32_t> merged(in->mNumVertices);
        for (unsigned v = 0; v < in->mNumVertices; ++v)
            merged[v] = welder.add({in->mVertices[v].x, in->mVertices[v].y, in->mVertices[v].z});
        for (unsigned f = 0; f < in->mNumFaces; ++f) {
            if (in->mFaces[f].mNumIndices != 3) continue; // points and lines
            for (int k = 0; k < 3; ++k) welder.mesh.indices.push_back(merged[in->mFaces[f].mIndices[k]]);
        }
    }
    if (welder.mesh.indices.empty()) return Error{path.string() + ": the file holds no triangles"};
    return std::move(welder.mesh);
}

} // namespace sdfwb::meshfield
