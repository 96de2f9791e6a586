#pragma once
// A manifest: the items of a many-shape run (`sdfwb --batch run`, RunRequest). One item per line,
// in either form:
//  - JSON lines (.jsonl, or any file whose first item starts with '{'):
//      {"sdf": "torus", "pattern": "near", "n": 100000, "seed": 1, "output": "torus.npz"}
//    with any key of a sample request (what `sdfwb --batch sample ... --print-request` prints;
//    "params": {"radius": 0.3}), or a recipe:
//      {"recipe": "deepsdf", "sdf": "torus", "n": 500000, "seed": 1, "output": "torus_deepsdf.npz"}
//    (recipe keys: recipe, sdf, entry, params, n, seed, time, output, and padding for occnet);
//  - CSV (.csv) with a header row naming the same keys; params as NAME=VALUE;NAME=X,Y,Z or a JSON
//    object; an empty cell keeps the default.
// Blank lines and lines starting with '#' are skipped. Relative sdf, pattern-file and output paths
// are taken from the manifest's folder, so a manifest moves with its data.

#include <core/Expected.h>

#include <cstdint>
#include <string>
#include <vector>

namespace sdfwb::jobs {

struct ManifestItem {
    std::uint64_t index = 0; // 0-based, in file order
    int line = 0;            // where it starts in the manifest
    std::string kind;        // "sample", or the recipe's name: deepsdf, occnet
    std::string sdf;
    std::string output; // resolved against the manifest's folder
    // What the child reads on stdin: the sample request's JSON (with "kind"), or the recipe's
    // arguments; paths resolved.
    std::string childInput;
    std::string key; // FNV-1a 64 of childInput in hex: a changed item is run again
};

// The recipes a manifest may name (sdfwb/recipes.py implements them).
const std::vector<std::string>& manifestRecipes();

// Every item, checked (keys, types, required keys); errors name the file, the line and the key.
Expected<std::vector<ManifestItem>> readManifest(const std::string& path);

} // namespace sdfwb::jobs
