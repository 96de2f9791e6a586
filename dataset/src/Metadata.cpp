#include <dataset/Metadata.h>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace sdfwb::dataset {
namespace {

std::string trim(const std::string& s) {
    std::size_t begin = s.find_first_not_of(" \t\r");
    if (begin == std::string::npos) return {};
    std::size_t end = s.find_last_not_of(" \t\r");
    return s.substr(begin, end - begin + 1);
}

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

} // namespace

std::string overlayText(const Metadata& metadata) { return metadata.name + "\n" + metadata.author + " - " + metadata.license; }

const char* declaredTypeName(DeclaredType type) {
    switch (type) {
    case DeclaredType::Exact:
        return "exact";
    case DeclaredType::Conservative:
        return "conservative";
    }
    return "?";
}

Expected<Metadata> parseMetadata(const std::string& text, const std::string& fileName) {
    std::size_t start = text.find_first_not_of(" \t\r\n");
    if (start == std::string::npos || text.compare(start, 8, "/* sdfwb") != 0)
        return makeError(fileName + ":1: missing metadata block: the file must start with `/* sdfwb`");
    std::size_t end = text.find("*/", start);
    if (end == std::string::npos) return makeError(fileName + ":1: metadata block is not closed with `*/`");

    Metadata metadata;
    bool seen[8] = {};
    std::string* lastValue = nullptr;
    int lineNumber = 1 + int(std::count(text.begin(), text.begin() + long(start), '\n'));
    std::istringstream block(text.substr(start, end - start));
    std::string line;
    std::getline(block, line); // "/* sdfwb"
    while (std::getline(block, line)) {
        ++lineNumber;
        if (trim(line).empty()) continue;
        auto where = [&] { return fileName + ":" + std::to_string(lineNumber) + ": "; };
        if ((line.rfind("  ", 0) == 0 || line.rfind("\t", 0) == 0) && lastValue) {
            *lastValue += " " + trim(line); // continuation
            continue;
        }
        std::size_t colon = line.find(':');
        if (colon == std::string::npos) return makeError(where() + "expected `key: value`, got `" + trim(line) + "`");
        std::string key = lower(trim(line.substr(0, colon)));
        std::string value = trim(line.substr(colon + 1));
        static const char* const keys[] = {"name", "category", "type", "animated", "author", "license", "notes", "entry"};
        int keyIndex = -1;
        for (int i = 0; i < 8; ++i)
            if (key == keys[i]) keyIndex = i;
        if (keyIndex < 0)
            return makeError(where() + "unknown metadata key '" + key +
                             "' (name, category, type, animated, author, license, notes, entry)");
        if (seen[keyIndex]) return makeError(where() + "metadata key '" + key + "' given twice");
        seen[keyIndex] = true;
        lastValue = nullptr;
        switch (keyIndex) {
        case 0:
            metadata.name = value;
            lastValue = &metadata.name;
            break;
        case 1:
            metadata.category = value;
            break;
        case 2:
            if (lower(value) == "exact")
                metadata.type = DeclaredType::Exact;
            else if (lower(value) == "conservative")
                metadata.type = DeclaredType::Conservative;
            else
                return makeError(where() + "unknown type '" + value + "' (exact|conservative)");
            break;
        case 3:
            if (lower(value) == "yes" || lower(value) == "true")
                metadata.animated = true;
            else if (lower(value) == "no" || lower(value) == "false")
                metadata.animated = false;
            else
                return makeError(where() + "animated must be yes or no, got '" + value + "'");
            break;
        case 4:
            metadata.author = value;
            lastValue = &metadata.author;
            break;
        case 5:
            metadata.license = value;
            lastValue = &metadata.license;
            break;
        case 6:
            metadata.notes = value;
            lastValue = &metadata.notes;
            break;
        case 7: {
            // The SDF's function when it is not sdf(); shaders::metadataEntry reads the same line.
            bool identifier = !value.empty() && !std::isdigit(static_cast<unsigned char>(value[0]));
            for (char c : value) identifier = identifier && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
            if (!identifier) return makeError(where() + "entry must be a GLSL function name, got '" + value + "'");
            metadata.entry = value;
            break;
        }
        }
    }
    static const char* const required[] = {"name", "category", "type", "animated", "author", "license"};
    for (int i = 0; i < 6; ++i)
        if (!seen[i]) return makeError(fileName + ":1: metadata block lacks '" + required[i] + "'");
    if (metadata.name.empty()) return makeError(fileName + ":1: metadata 'name' is empty");
    return metadata;
}

} // namespace sdfwb::dataset
