#include <dataset/Catalogue.h>

#include <core/TextFile.h>

#include <algorithm>
#include <cctype>

namespace sdfwb::dataset {
namespace fs = std::filesystem;
namespace {

bool equalsIgnoringCase(const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

// The dataset's .glsl files in path order, helpers (a folder named "lib") left out.
std::vector<fs::path> sdfFiles(const fs::path& root) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
        if (it->is_directory() && it->path().filename() == "lib") {
            it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file() && it->path().extension() == ".glsl") files.push_back(it->path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace

Catalogue Catalogue::scan(const fs::path& root) {
    Catalogue catalogue;
    std::error_code ec;
    if (!fs::is_directory(root, ec)) {
        catalogue.m_problems.push_back(root.string() + ": dataset folder not found");
        return catalogue;
    }
    for (const fs::path& file : sdfFiles(root)) {
        auto text = readTextFile(file);
        if (!text) {
            catalogue.m_problems.push_back(text.error().message);
            continue;
        }
        auto metadata = parseMetadata(*text, file.string());
        if (!metadata) {
            catalogue.m_problems.push_back(metadata.error().message);
            continue;
        }
        catalogue.m_entries.push_back({std::move(*metadata), file});
    }
    return catalogue;
}

const Entry* Catalogue::find(const std::string& name) const {
    for (const Entry& entry : m_entries)
        if (equalsIgnoringCase(entry.metadata.name, name) || equalsIgnoringCase(entry.path.stem().string(), name)) return &entry;
    return nullptr;
}

Expected<fs::path> resolveSdfArgument(const std::string& argument, const Catalogue& catalogue) {
    std::error_code ec;
    if (fs::is_regular_file(argument, ec)) return fs::path(argument);
    if (const Entry* entry = catalogue.find(argument)) return entry->path;
    if (argument.find('/') != std::string::npos || (argument.size() > 5 && argument.ends_with(".glsl")))
        return makeError("'" + argument + "': no such file");
    return makeError("'" + argument + "': no such file or dataset SDF (see sdfwb --batch list)");
}

Expected<fs::path> resolveSdfArgument(const std::string& argument, const fs::path& root) {
    std::error_code ec;
    if (fs::is_regular_file(argument, ec)) return fs::path(argument);
    if (fs::is_directory(root, ec))
        for (const fs::path& file : sdfFiles(root))
            if (equalsIgnoringCase(file.stem().string(), argument)) return file;
    return resolveSdfArgument(argument, Catalogue::scan(root)); // by metadata name, or the error
}

} // namespace sdfwb::dataset
