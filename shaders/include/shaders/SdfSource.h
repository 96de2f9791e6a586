#pragma once
// An SDF as the rest of the program sees it: its text with includes expanded, which signature
// it defines, which parts of the G3D compat prelude it needs, and the problems found so far.

#include <shaders/Diagnostic.h>
#include <shaders/IncludeResolver.h>
#include <shaders/Parameters.h>

#include <meshfield/MeshField.h>

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sdfwb::shaders {

// The SDF's entry point: `sdf` unless the user names another function (--entry, an `entry:` line in
// the metadata block, the GUI's entry field, Python's entry=), or, when the file defines no sdf(),
// the first of the names public ray-marching code uses for it (map, scene, sceneSDF, sdScene, de,
// DE). It returns float, or vec2/vec3/vec4 with the distance in .x (Shadertoy's material ids).
// A parameter of the marching function that a field's arguments read, and the expression mainImage
// passes for it (`vec3 rd` = `normalize(vec3(uv, 1.5))`).
struct TracedValue {
    std::string type, name, value;
};

struct SdfSignature {
    bool found = false;    // a definition of ENTRY(vec3) or ENTRY(vec3, float) exists
    bool animated = false; // ENTRY(vec3 p, float time)
    std::string entry = "sdf";
    std::string returnType = "float"; // float | vec2 | vec3 | vec4, or a struct's name (see member)
    // A struct return (`Hit map(vec3 p)`, found from a whole shader's march): the float member the
    // march steps by is the distance. A vector return whose march steps by its y, z or w
    // (`t += ds.w`): that component. Empty otherwise.
    std::string member;
    // The types of `out`/`inout` parameters after the point (and the time), in order
    // (`float sdf(vec3 p, out Material m)`): the wrapper passes locals of these types.
    std::vector<std::string> outParameters;
    // The point itself declared `out` (`float DE(out vec3 p)`, read before it is written): such code
    // was written on a driver where an out parameter holds the caller's value; composed `inout`.
    bool pointOut = false;
    // A field with parameters after the point whose values mainImage computes (a whole shader's
    // march, shaders/MarchAnalysis.h): once per invocation the wrapper runs `prelude` (mainImage's
    // code before the march, its parameters declared first) and keeps each `traced` value; every
    // call then declares the traced parameters from them and calls ENTRY(p`arguments`).
    // A `prelude` alone (no `arguments`): statements the wrapper runs once per invocation before
    // calling ENTRY(p) (Fragmentarium's init(), which computes globals from its uniforms).
    std::string prelude, arguments;
    std::vector<TracedValue> traced;
    // A field a whole shader's march writes inline (shaders::InlineMarch): the wrapper runs
    // `prelude` and then this block, which returns the field at sdfwb_point. Empty otherwise.
    std::string inlineBody;
    // A whole shader whose primary ray marches two functions of a point as often (dr2's cave and
    // boats, each marched by the scene it draws, the nearer hit shown): the others, each a name
    // and how its distance is read (".x", ".d" or empty); the wrapper returns the least of all.
    std::vector<std::pair<std::string, std::string>> unionWith;
};

// Where the entry point came from: `sdf` (Default), --entry or the GUI (Requested), an `entry:`
// metadata line, the function a whole shader's own march steps by (March, shaders/MarchAnalysis.h),
// or the first conventional name defined (Convention).
enum class EntrySource { Default, Requested, Metadata, March, Convention };

// Shadertoy's texture inputs iChannel0..3.
constexpr int kShadertoyChannels = 4;

// Names the text uses without declaring them at file scope that sdfwb provides: the original
// sdf-explorer's G3D dialect, Shadertoy's inputs (iTime, iResolution, iMouse, iChannel0..3, ...),
// GLSL ES's texture2D, and derivatives outside fragment shaders (compatCandidates() lists them).
// Each becomes a `#define SDFWB_COMPAT_<NAME>` that selects a section of prelude/g3d_compat.glsl.
struct CompatNeeds {
    std::vector<std::string> symbols; // e.g. "pi", "saturate", "float3", "g3d_SceneTime", "iMouse"
    // Those of them the file's own macro wraps (`#define iTime (iTime - 25.)`): the macro still
    // needs what it wraps, so the prelude declares it as a variable rather than a macro.
    std::vector<std::string> wrapped;
    // Functions the file defines under the names of GLSL's deprecated noise1..noise4 (GLSL ES has
    // none, so Shadertoy code uses the names freely; glslang refuses a definition with another
    // return type): the composer renames them in the file's code (sdfwb_noise2).
    std::vector<std::string> renamed;
    // Channels the code reads with a direction (`texture(iChannel0, rd)`): Shadertoy's cube maps,
    // declared samplerCube (chosen by glslang in prepareSdf: the declaration that compiles).
    std::vector<std::string> cubeChannels;
    bool any() const { return !symbols.empty(); }
    bool usesTimeSymbol() const;       // g3d_SceneTime or Shadertoy's iTime
    bool usesShadertoyChannel() const; // iChannel0..3
};

// Every name detectCompatNeeds() looks for, in the order it reports them.
const std::vector<std::string>& compatCandidates();

struct PreparedSdf {
    ResolvedSource source;
    SdfSignature signature;
    CompatNeeds compat;
    std::vector<Diagnostic> diagnostics; // resolver errors + a missing/ill-typed entry point
    EntrySource entrySource = EntrySource::Default;
    // Why an automatic entry was chosen ("Map, called by the march at line 123"); empty otherwise.
    std::string entryReason;
    // Functions equally likely to be the field (the march steps by each as often): the error
    // names them and the workbench offers them; empty otherwise.
    std::vector<std::string> entryCandidates;
    // Names the file (with its includes) #defines. The composer #undefs them after the SDF, so a
    // user's `#define normal ...` cannot reach the workbench's code composed after it.
    std::vector<std::string> macros;
    // The root file's annotated uniforms (Parameters.h); their problems are in `diagnostics`.
    std::vector<Parameter> parameters;
    // Images for Shadertoy's iChannel0..3 (--channel N=FILE, the GUI's channel pickers); an empty
    // one reads the noise texels (see prelude/g3d_compat.glsl).
    std::array<std::string, kShadertoyChannels> channels;
    // The file defines Shadertoy's `void mainImage(out vec4, in vec2)`: a whole shader, whose own
    // picture renderer/ShadertoyPicture.h can draw.
    bool shadertoyMainImage = false;
    // The host a whole shader was written for, where it is not Shadertoy or sdfwb ("glslViewer",
    // "GLSL Sandbox", "Bonzomatic", "a WebGL page", "Fragmentarium", ...): its text was read in
    // that host's terms (shaders/src/ForeignHosts.h); empty otherwise.
    std::string host;
    // A triangle mesh the text's sdfwb_meshSdf() reads (the SDF is a mesh file: prepareMeshSdf).
    // The composer adds shaders/mesh/mesh_field.glsl and the GL side binds its buffers.
    std::shared_ptr<const meshfield::MeshField> mesh;
    // The SDF is the mesh's own field (its generated text, unedited): its zero set is the mesh's
    // triangles, so the surface and near samplers draw points on them instead of marching rays.
    bool meshIsTheField = false;
    // The constant a whole shader's own march stops at (`if (d < 0.001) break;`, MarchedFunction),
    // where the entry was found from that march; 0 otherwise. An unsigned field's surface there.
    float marchThreshold = 0.0f;
    int marchThresholdLine = 0;
    // A GLSL field seen through a frame (--normalize for a field whose surface lies outside
    // [-1, 1]^3): the field's point is centre + scale * p and its value is divided by scale, so
    // the framed field is still a distance and every command sees it in the unit box.
    struct Frame {
        std::array<float, 3> centre{0.0f, 0.0f, 0.0f};
        float scale = 1.0f;
        float level = 0.0f; // the surface is f = level: the field is (f(centre + scale p) - level) / scale
        bool operator==(const Frame&) const = default;
    };
    Frame frame;

    bool ok() const { return !hasErrors(diagnostics); }
    // Needs a time value each frame: sdf(vec3, float) or the G3D scene time uniform.
    bool usesTime() const { return signature.animated || compat.usesTimeSymbol(); }
};

// What reading a shader as `host`'s (PreparedSdf::host) did, for the log and the status bar:
// "a glslViewer shader: its main() read as Shadertoy's mainImage, its inputs as Shadertoy's".
std::string hostDescription(const std::string& host);

// Returns `text` with comments replaced by spaces (newlines kept, so line numbers still match).
std::string stripComments(const std::string& text);
// A letter, digit or underscore: a character of a GLSL identifier.
bool isWordCharacter(char c);
// Whether `text` holds `name` as a whole word (not inside a longer identifier).
bool mentions(const std::string& text, const std::string& name);

// Finds a definition of `entry` taking (vec3) or (vec3, float) and returning float or vec2-4.
// `returnTypes`: the return types allowed, as a regex alternation; a struct's name among them
// (or \\w+) takes its first float member as the distance.
SdfSignature detectSignature(const std::string& strippedText, const std::string& entry = "sdf",
                             const std::string& returnTypes = "float|vec2|vec3|vec4|\\w+");

// The `entry:` value of the leading `/* sdfwb ... */` metadata block, or "" when it has none.
std::string metadataEntry(const std::string& text);

// The conventional entry names tried, in order, when a file defines no sdf() and names none.
const std::vector<std::string>& conventionalEntries();

// Every `#define NAME` and `#undef NAME` of `strippedText`: the name and its byte offset.
struct MacroDirective {
    std::string name;
    std::size_t offset = 0;
    bool undefine = false;
};
std::vector<MacroDirective> macroDirectives(const std::string& strippedText);

// Names of the macros `strippedText` #defines, each once, in order of first definition.
std::vector<std::string> definedMacros(const std::string& strippedText);

// "name(type a, type b)" for every function defined in `text` (for autocompletion and call tips).
std::vector<std::string> functionSignatures(const std::string& text);
CompatNeeds detectCompatNeeds(const std::string& strippedText);

// Resolves includes and analyses the text. `name` labels diagnostics for the root text; `path`
// may be empty for unsaved text. `entry` names the SDF's function; empty: the metadata block's
// `entry:`, else `sdf`, else a conventional name (see SdfSignature).
PreparedSdf prepareSdf(const std::string& text, const std::string& name, const std::filesystem::path& path,
                       const IncludeOptions& options, const std::string& entry = {});

// A mesh as an SDF: `text` (empty: the mesh's own, MeshField::glslSource()) prepared with `mesh`
// attached, so its sdfwb_meshSdf() reads the mesh.
PreparedSdf prepareMeshSdf(std::shared_ptr<const meshfield::MeshField> mesh, const std::filesystem::path& path,
                           const std::string& text = {}, const std::string& entry = {});

// A mesh file with these options (loaded through meshfield's cache) under `text` (empty: its
// generated text); a file that cannot be read gives a PreparedSdf whose diagnostic says why.
PreparedSdf prepareMeshFile(const std::filesystem::path& path, const meshfield::MeshFieldOptions& options,
                            const std::string& text = {}, const std::string& entry = {});

// Reads `path` and prepares it; an unreadable file gives a diagnostic naming it.
PreparedSdf prepareSdfFile(const std::filesystem::path& path, const IncludeOptions& options, const std::string& entry = {});

} // namespace sdfwb::shaders
