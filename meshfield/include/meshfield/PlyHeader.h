#pragma once
// One reader of PLY headers for every module: meshes (meshfield/src/MeshFiles.cpp) and sample
// files (sampling/src/PlyFile.cpp) parse the same header here and read their bodies their own way.

#include <core/Expected.h>

#include <cstdint>
#include <string>
#include <vector>

namespace sdfwb::meshfield {

enum class PlyType : std::uint8_t { None, Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

// "float", "float32", "uchar", ...: the type, or None.
PlyType plyType(const std::string& name);
// Bytes of one value in a binary body (0 for None).
int plySize(PlyType type);

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::None;      // scalar type, or the list's item type
    PlyType countType = PlyType::None; // None for a scalar
    bool isList() const { return countType != PlyType::None; }
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyHeader {
    std::string format; // ascii, binary_little_endian or binary_big_endian
    std::vector<PlyElement> elements;
    std::vector<std::string> comments; // each `comment` line's text after the keyword
    std::size_t bodyOffset = 0;        // the first byte after the `end_header` line
};

// The header at the start of `data` (which may hold only its first bytes). Errors name the file
// `name` and the header line ("mesh.ply:4: unknown property type: 'property half x'").
Expected<PlyHeader> parsePlyHeader(const std::string& data, const std::string& name);

} // namespace sdfwb::meshfield
