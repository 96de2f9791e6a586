#pragma once
// The metadata block every dataset SDF starts with: a block comment of `key: value` lines.
//
//   /* sdfwb
//   name: Torus
//   category: Geometry
//   type: exact            (exact | conservative)
//   animated: no           (yes | no)
//   author: sdfwb authors
//   license: CC0-1.0
//   notes: free text; lines indented by two spaces continue the value
//   entry: map             (optional: the SDF's function when it is not sdf)
//   */
//
// One parser, used by the dataset browser, the CLI and the reports.

#include <core/Expected.h>

#include <string>

namespace sdfwb::dataset {

enum class DeclaredType { Exact, Conservative };

struct Metadata {
    std::string name;
    std::string category;
    DeclaredType type = DeclaredType::Exact;
    bool animated = false;
    std::string author;
    std::string license;
    std::string notes;
    std::string entry; // empty: sdf (or a conventional name; see shaders::SdfSignature)
};

// Parses the leading `/* sdfwb ... */` block of `text`. `fileName` names the file in errors,
// which also give the line: "Torus.glsl:4: unknown type 'exactish' (exact|conservative)".
Expected<Metadata> parseMetadata(const std::string& text, const std::string& fileName);

const char* declaredTypeName(DeclaredType type);

// "Name\nauthor - license": the overlay the workbench and exports draw over a frame.
std::string overlayText(const Metadata& metadata);

} // namespace sdfwb::dataset
