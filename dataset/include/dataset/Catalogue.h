#pragma once
// The dataset: every .glsl file under the dataset root with its metadata, and the lookup that
// turns a command-line <SDF> argument (a dataset name, any case, or a path) into a file.

#include <core/Expected.h>
#include <dataset/Metadata.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sdfwb::dataset {

struct Entry {
    Metadata metadata;
    std::filesystem::path path;
};

class Catalogue {
public:
    // Scans `root` recursively (files in a folder named "lib" are helpers, not SDFs). Files whose
    // metadata does not parse are skipped and listed in problems().
    static Catalogue scan(const std::filesystem::path& root);

    const std::vector<Entry>& entries() const { return m_entries; }
    const std::vector<std::string>& problems() const { return m_problems; }

    // Case-insensitive lookup by metadata name or file stem; null when absent.
    const Entry* find(const std::string& name) const;

private:
    std::vector<Entry> m_entries;
    std::vector<std::string> m_problems;
};

// An <SDF> argument: an existing file path wins, then a dataset name. The error names the
// argument and suggests `sdfwb --batch list`.
Expected<std::filesystem::path> resolveSdfArgument(const std::string& argument, const Catalogue& catalogue);
// The same against the dataset under `root`, reading only what it must: a file whose stem is the
// name (any case) is found from the folder listing alone; only a name that is no file's stem scans
// the metadata (a job that names "Sphere" reads one file, not the 78).
Expected<std::filesystem::path> resolveSdfArgument(const std::string& argument, const std::filesystem::path& root);

// The SDF the workbench opens with no file given.
inline constexpr const char* kDefaultSdfName = "Torus";

} // namespace sdfwb::dataset
