#include <meshfield/PlyHeader.h>

#include <map>
#include <sstream>

namespace sdfwb::meshfield {

PlyType plyType(const std::string& name) {
    static const std::map<std::string, PlyType> types = {
        {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},    {"uint8", PlyType::UInt8},
        {"short", PlyType::Int16},   {"int16", PlyType::Int16},     {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},
        {"int", PlyType::Int32},     {"int32", PlyType::Int32},     {"uint", PlyType::UInt32},    {"uint32", PlyType::UInt32},
        {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64}, {"float64", PlyType::Float64}};
    const auto it = types.find(name);
    return it == types.end() ? PlyType::None : it->second;
}

int plySize(PlyType type) {
    switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
        return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
        return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
        return 4;
    case PlyType::Float64:
        return 8;
    case PlyType::None:
        return 0;
    }
    return 0;
}

Expected<PlyHeader> parsePlyHeader(const std::string& data, const std::string& name) {
    // The header: lines up to `end_header`; the body starts right after its line break.
    const std::size_t end = data.find("end_header");
    if (data.compare(0, 3, "ply") != 0 || end == std::string::npos)
        return makeError(name + ": not a PLY file (no 'ply' ... 'end_header')");
    std::size_t bodyAt = data.find('\n', end);
    if (bodyAt == std::string::npos) return makeError(name + ": the PLY header has no line break after 'end_header'");
    ++bodyAt;
    std::istringstream header(data.substr(0, end));
    PlyHeader out;
    out.bodyOffset = bodyAt;
    std::string& format = out.format;
    std::vector<PlyElement>& elements = out.elements;
    std::string line;
    int lineNumber = 0;
    while (std::getline(header, line)) {
        ++lineNumber;
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        auto bad = [&](const std::string& what) {
            return makeError(name + ":" + std::to_string(lineNumber) + ": " + what + ": '" + line + "'");
        };
        if (keyword == "comment") {
            std::string text;
            std::getline(words >> std::ws, text);
            out.comments.push_back(std::move(text));
            continue;
        }
        if (keyword.empty() || keyword == "ply" || keyword == "obj_info") continue;
        if (keyword == "format") {
            words >> format;
            if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
                return bad("unknown PLY format");
        } else if (keyword == "element") {
            PlyElement element;
            if (!(words >> element.name >> element.count)) return bad("malformed element line");
            elements.push_back(std::move(element));
        } else if (keyword == "property") {
            if (elements.empty()) return bad("a property before any element");
            PlyProperty property;
            std::string type;
            words >> type;
            if (type == "list") {
                std::string countType, itemType;
                words >> countType >> itemType >> property.name;
                property.countType = plyType(countType);
                property.type = plyType(itemType);
                if (!property.isList() || property.type == PlyType::None) return bad("unknown list types");
            } else {
                property.type = plyType(type);
                words >> property.name;
                if (property.type == PlyType::None) return bad("unknown property type");
            }
            elements.back().properties.push_back(std::move(property));
        } else {
            return bad("unknown header line");
        }
    }
    if (format.empty()) return makeError(name + ": the PLY header names no format");
    return out;
}

} // namespace sdfwb::meshfield
