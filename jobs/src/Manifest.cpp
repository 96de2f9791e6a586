// Reads many-shape manifests (Manifest.h), JSON lines or CSV, into checked items. The second file
// here that includes nlohmann/json: a CSV cell becomes the JSON value its key takes in a request.
#include <jobs/Manifest.h>

#include <jobs/JobJson.h>

#include <core/TextFile.h>
#include <shaders/Parameters.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

namespace sdfwb::jobs {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

const std::set<std::string> kRecipeKeys = {"recipe", "sdf", "entry", "params", "n", "seed", "time", "output", "padding"};

std::string fnv1a(const std::string& text) {
    std::uint64_t hash = 1469598103934665603ull;
    for (unsigned char c : text) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

std::string joined(const std::set<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

// A relative path is taken from the manifest's folder; for inputs only when a file is there (a
// dataset name, or a path relative to the working folder, stays as given).
std::string besideManifest(const fs::path& folder, const std::string& path, bool input) {
    if (path.empty() || fs::path(path).is_absolute()) return path;
    fs::path candidate = (folder / path).lexically_normal();
    std::error_code ec;
    if (!input || fs::is_regular_file(candidate, ec)) return candidate.string();
    return path;
}

Expected<ManifestItem> recipeItem(json in, const fs::path& folder, const std::string& where) {
    const json& recipe = in["recipe"];
    const auto& recipes = manifestRecipes();
    if (!recipe.is_string() || std::find(recipes.begin(), recipes.end(), recipe.get<std::string>()) == recipes.end()) {
        std::string names;
        for (const std::string& name : recipes) names += (names.empty() ? "" : ", ") + name;
        return makeError(where + "'recipe': expected one of " + names + ", got " + recipe.dump());
    }
    for (const auto& [key, value] : in.items())
        if (!kRecipeKeys.count(key))
            return makeError(where + "'" + key + "': unknown key for a recipe (known: " + joined(kRecipeKeys) + ")");
    for (const char* key : {"sdf", "output"})
        if (!in.contains(key) || !in[key].is_string() || in[key].get<std::string>().empty())
            return makeError(where + "'" + key + "': a recipe needs a non-empty string");
    for (const char* key : {"n", "seed"})
        if (in.contains(key) && !in[key].is_number_unsigned())
            return makeError(where + "'" + key + "': expected a non-negative integer, got " + in[key].dump());
    for (const char* key : {"time", "padding"})
        if (in.contains(key) && (!in[key].is_number() || !std::isfinite(in[key].get<double>())))
            return makeError(where + "'" + key + "': expected a finite number, got " + in[key].dump());
    if (in.contains("params") && !in["params"].is_object())
        return makeError(where + "'params': expected an object of parameter values, got " + in["params"].dump());
    if (in.contains("entry") && !in["entry"].is_string()) return makeError(where + "'entry': expected a string");
    if (fs::path(in["output"].get<std::string>()).extension() != ".npz")
        return makeError(where + "'output': a recipe writes .npz, got '" + in["output"].get<std::string>() + "'");
    in["sdf"] = besideManifest(folder, in["sdf"].get<std::string>(), true);
    in["output"] = besideManifest(folder, in["output"].get<std::string>(), false);
    ManifestItem item;
    item.kind = recipe.get<std::string>();
    item.sdf = in["sdf"].get<std::string>();
    item.output = in["output"].get<std::string>();
    item.childInput = in.dump();
    return item;
}

Expected<ManifestItem> sampleItem(const json& given, const fs::path& folder, const std::string& where) {
    for (const char* key : {"sweep", "randomize"})
        if (given.contains(key))
            return makeError(where + "'" + std::string(key) +
                             "': a family writes many files; give each instance a line of its own");
    for (const char* key : {"sdf", "pattern", "n", "output"})
        if (!given.contains(key))
            return makeError(where + "missing \"" + std::string(key) + "\" (a sample item needs sdf, pattern, n and output)");
    json in = {{"kind", "sample"}};
    for (const auto& [key, value] : given.items()) in[key] = value;
    for (const char* key : {"sdf", "pattern", "output"})
        if (in[key].is_string()) in[key] = besideManifest(folder, in[key].get<std::string>(), key != std::string("output"));
    auto request = requestFromJson(in.dump());
    if (!request) return makeError(where + request.error().message);
    const auto& sample = std::get<values::SampleRequest>(*request);
    ManifestItem item;
    item.kind = "sample";
    item.sdf = sample.sdf.sdf;
    item.output = sample.output;
    item.childInput = toJson(*request);
    return item;
}

Expected<ManifestItem> itemFromJson(const json& in, const fs::path& folder, const std::string& where) {
    if (!in.is_object()) return makeError(where + "expected a JSON object (one item per line)");
    if (in.contains("kind"))
        return makeError(where + "'kind': not used in a manifest (a line is a sample item, or has \"recipe\")");
    return in.contains("recipe") ? recipeItem(in, folder, where) : sampleItem(in, folder, where);
}

bool skipped(const std::string& line) {
    const auto first = line.find_first_not_of(" \t\r");
    return first == std::string::npos || line[first] == '#';
}

struct Record {
    int line = 0;
    std::vector<std::string> cells;
};

// RFC 4180: commas separate, "..." quotes (with "" for a quote, and line breaks inside).
Expected<std::vector<Record>> splitCsv(const std::string& text, const std::string& file) {
    std::vector<Record> records;
    Record record{1, {}};
    std::string cell;
    bool quoted = false, cellWasQuoted = false;
    int line = 1, quoteLine = 0;
    auto endRecord = [&] {
        record.cells.push_back(cell);
        const bool blank = record.cells.size() == 1 && record.cells[0].find_first_not_of(" \t") == std::string::npos;
        const bool comment = !record.cells.empty() && !cellWasQuoted && skipped(record.cells[0]) && !blank;
        if (!blank && !comment) records.push_back(record);
        record = Record{line + 1, {}};
        cell.clear();
        cellWasQuoted = false;
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
                cell += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                if (c == '\n') ++line;
                cell += c;
            }
        } else if (c == '"' && cell.find_first_not_of(" \t") == std::string::npos) {
            quoted = cellWasQuoted = true;
            quoteLine = line;
            cell.clear();
        } else if (c == ',') {
            record.cells.push_back(cell);
            cell.clear();
        } else if (c == '\n') {
            endRecord();
            ++line;
        } else if (c != '\r') {
            cell += c;
        }
    }
    if (quoted) return makeError(file + ":" + std::to_string(quoteLine) + ": unterminated \" quote");
    if (!cell.empty() || !record.cells.empty()) endRecord();
    return records;
}

std::string trimmed(const std::string& text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// "radius=0.3;offset=1,2,0" (or a JSON object) -> {"radius": 0.3, "offset": [1, 2, 0]}
Expected<json> paramsCell(const std::string& cell) {
    if (cell.front() == '{') {
        try {
            return json::parse(cell);
        } catch (const json::exception& e) { return makeError(std::string("not valid JSON: ") + e.what()); }
    }
    json out = json::object();
    std::size_t start = 0;
    while (start <= cell.size()) {
        const std::size_t end = std::min(cell.find(';', start), cell.size());
        const std::string text = trimmed(cell.substr(start, end - start));
        start = end + 1;
        if (text.empty()) continue;
        auto value = shaders::parseParameterValue(text);
        if (!value) return makeError(value.error().message);
        if (value->value.size() == 1)
            out[value->name] = value->value[0];
        else
            out[value->name] = value->value;
    }
    return out;
}

// A cell as the JSON value `example` (the key's default) has the type of.
Expected<json> typedCell(const std::string& cell, const json& example) {
    if (example.is_string()) return json(cell);
    if (example.is_boolean()) {
        if (cell == "true" || cell == "1") return json(true);
        if (cell == "false" || cell == "0") return json(false);
        return makeError("expected true or false, got '" + cell + "'");
    }
    if (example.is_number_integer()) {
        if (cell.find_first_not_of("0123456789") != std::string::npos || cell.size() > 19)
            return makeError("expected a non-negative integer, got '" + cell + "'");
        return json(std::stoull(cell));
    }
    if (example.is_number()) {
        char* end = nullptr;
        const double value = std::strtod(cell.c_str(), &end);
        if (end == cell.c_str() || *end != '\0' || !std::isfinite(value))
            return makeError("expected a finite number, got '" + cell + "'");
        return json(value);
    }
    return makeError("not supported in CSV (use JSON lines for this key)");
}

Expected<std::vector<json>> csvItems(const std::string& text, const std::string& file, std::vector<int>& lines) {
    auto records = splitCsv(text, file);
    if (!records) return records.error();
    if (records->empty()) return std::vector<json>{};
    std::vector<std::string> header;
    for (const std::string& name : records->front().cells) {
        header.push_back(trimmed(name));
        if (header.back().empty())
            return makeError(file + ":" + std::to_string(records->front().line) + ": an empty column name");
        if (std::count(header.begin(), header.end(), header.back()) > 1)
            return makeError(file + ":" + std::to_string(records->front().line) + ": column '" + header.back() +
                             "' appears twice");
    }
    const json sampleDefaults = json::parse(toJson(values::Request(values::SampleRequest{})));
    const json recipeTypes = {{"n", 0}, {"seed", 0}, {"time", 0.5}, {"padding", 0.5}};
    std::vector<json> items;
    for (std::size_t r = 1; r < records->size(); ++r) {
        const Record& record = (*records)[r];
        const std::string where = file + ":" + std::to_string(record.line) + ": ";
        if (record.cells.size() > header.size())
            return makeError(where + std::to_string(record.cells.size()) + " cells, but the header names " +
                             std::to_string(header.size()) + " columns");
        bool recipe = false;
        for (std::size_t c = 0; c < record.cells.size(); ++c)
            recipe = recipe || (header[c] == "recipe" && !trimmed(record.cells[c]).empty());
        json item = json::object();
        for (std::size_t c = 0; c < record.cells.size(); ++c) {
            const std::string cell = trimmed(record.cells[c]);
            if (cell.empty()) continue;
            const std::string& key = header[c];
            Expected<json> value = json();
            if (key == "params")
                value = paramsCell(cell);
            else if (recipe)
                value = typedCell(cell, recipeTypes.contains(key) ? recipeTypes[key] : json(""));
            else
                value = typedCell(cell, sampleDefaults.contains(key) ? sampleDefaults[key] : json(""));
            if (!value) return makeError(where + "'" + key + "': " + value.error().message);
            item[key] = *value;
        }
        items.push_back(std::move(item));
        lines.push_back(record.line);
    }
    return items;
}

} // namespace

const std::vector<std::string>& manifestRecipes() {
    static const std::vector<std::string> names = {"deepsdf", "occnet"};
    return names;
}

Expected<std::vector<ManifestItem>> readManifest(const std::string& path) {
    auto text = readTextFile(path);
    if (!text) return makeError("manifest: " + text.error().message);
    const fs::path folder = fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
    const std::string extension = fs::path(path).extension().string();
    bool jsonLines = extension == ".jsonl" || extension == ".ndjson" || extension == ".json";
    if (extension != ".csv" && !jsonLines) {
        std::size_t start = 0;
        while (start < text->size()) {
            const std::size_t end = std::min(text->find('\n', start), text->size());
            const std::string line = text->substr(start, end - start);
            start = end + 1;
            if (skipped(line)) continue;
            jsonLines = line[line.find_first_not_of(" \t\r")] == '{';
            break;
        }
    }
    std::vector<json> objects;
    std::vector<int> lines;
    if (jsonLines) {
        std::size_t start = 0;
        int number = 0;
        while (start < text->size()) {
            const std::size_t end = std::min(text->find('\n', start), text->size());
            const std::string line = text->substr(start, end - start);
            start = end + 1;
            ++number;
            if (skipped(line)) continue;
            try {
                objects.push_back(json::parse(line));
            } catch (const json::exception& e) {
                return makeError(path + ":" + std::to_string(number) + ": not valid JSON: " + e.what());
            }
            lines.push_back(number);
        }
    } else {
        auto items = csvItems(*text, path, lines);
        if (!items) return items.error();
        objects = std::move(*items);
    }
    if (objects.empty()) return makeError(path + ": the manifest has no items");
    std::vector<ManifestItem> items;
    std::map<std::string, int> outputs;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const std::string where = path + ":" + std::to_string(lines[i]) + ": ";
        auto item = itemFromJson(objects[i], folder, where);
        if (!item) return item.error();
        item->index = i;
        item->line = lines[i];
        item->key = fnv1a(item->childInput);
        std::error_code ec;
        const std::string output = fs::weakly_canonical(item->output, ec).string();
        if (auto [it, added] = outputs.emplace(output, lines[i]); !added)
            return makeError(where + "'output': '" + item->output + "' is also the output of line " + std::to_string(it->second));
        items.push_back(std::move(*item));
    }
    return items;
}

} // namespace sdfwb::jobs
