#include <shaders/ShaderComposer.h>

#include <shaders/BuiltinShaders.h>
#include <shaders/SdfSource.h>

#include "TextEdits.h"
#include "Words.h"
#include "ZeroInit.h"

#include <core/Regex.h>

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace sdfwb::shaders {
namespace {

const char* const kVersionLine = "#version 430 core\n";
// A mesh's field in a fragment shader reads gl_HelperInvocation (GLSL 4.50; mesh_field.glsl).
const char* const kMeshFragmentVersionLine = "#version 450 core\n";

std::string lineDirective(int line, std::size_t fileIndex) {
    return "#line " + std::to_string(line) + " " + std::to_string(fileIndex) + "\n";
}

// Adds `text` as a new source file and appends it to the composed text.
void appendFile(ComposedShader& shader, const std::string& name, const std::string& text) {
    std::size_t index = shader.map.files.size();
    shader.map.files.push_back({name, text});
    shader.text += lineDirective(1, index);
    shader.text += text;
    if (!text.empty() && text.back() != '\n') shader.text += '\n';
}

void appendDefines(ComposedShader& shader, const FeatureDefines& features, bool timeUniform = false) {
    std::size_t index = shader.map.files.size();
    std::string defines;
    for (const auto& [name, value] : features) defines += "#define " + name + (value.empty() ? "" : " " + value) + "\n";
    // Declared before the SDF so that the compat prelude can map g3d_SceneTime and iTime onto it.
    if (timeUniform) defines += "uniform float sdfwb_time;\n";
    shader.map.files.push_back({"<sdfwb feature defines>", defines});
    shader.text += lineDirective(1, index);
    shader.text += defines;
}

// `text` with every whole-word `word` replaced by `replacement`.
std::string renameWord(const std::string& text, const std::string& word, const std::string& replacement) {
    std::string out;
    std::size_t from = 0;
    detail::forEachOccurrence(text, word, [&](std::size_t at) {
        out.append(text, from, at - from);
        out += replacement;
        from = at + word.size();
        return true;
    });
    out.append(text, from, std::string::npos);
    return out;
}

// `text` with every parameter declared `out` declared `inout`. For a file whose field declares its
// point `out` (`float DE(out vec3 p) { return fold(p); }` with `fold(out vec3 z)`): such code was
// written on a driver where an out parameter holds the caller's value, and reads it before writing.
std::string parametersInout(const std::string& text) {
    const std::string stripped = stripComments(text); // same offsets
    std::vector<detail::Edit> edits;
    detail::forEachOccurrence(stripped, "out", [&](std::size_t at) {
        std::size_t before = at;
        while (before > 0 && std::isspace(static_cast<unsigned char>(stripped[before - 1]))) --before;
        if (before > 0 && (stripped[before - 1] == '(' || stripped[before - 1] == ',')) edits.push_back({at, 3, "inout"});
        return true;
    });
    return detail::applyEdits(text, std::move(edits));
}

// `text` with each call of texture, texture2D or textureCube that passes three arguments (the
// bias form) calling sdfwb_textureBias instead. Arguments are counted at the call's own level of
// parentheses and brackets.
std::string renameBiasLookups(const std::string& text) {
    std::string out;
    std::size_t from = 0;
    detail::forEachIdentifier(text, [&](std::size_t at, std::size_t end) {
        const std::string_view word(text.data() + at, end - at);
        std::size_t open = end;
        while (open < text.size() && std::isspace(static_cast<unsigned char>(text[open]))) ++open;
        if ((word == "texture" || word == "texture2D" || word == "textureCube") && open < text.size() && text[open] == '(') {
            int depth = 0, commas = 0;
            for (std::size_t i = open; i < text.size(); ++i) {
                const char c = text[i];
                if (c == '(' || c == '[') ++depth;
                if (c == ')' || c == ']') --depth;
                if (c == ',' && depth == 1) ++commas;
                if (depth == 0) break;
            }
            if (commas == 2) {
                out.append(text, from, at - from);
                out += "sdfwb_textureBias";
                from = end;
            }
        }
        return true;
    });
    out.append(text, from, std::string::npos);
    return out;
}

// Whether `text` (comments stripped first) has a for, while or do keyword: a field without one is
// cheap to inline at every call site (SDFWB_FIELD_WITHOUT_LOOPS, sampling/common.glsl).
bool hasLoopKeyword(const std::string& text) {
    bool found = false;
    detail::forEachIdentifier(text, [&](std::size_t at, std::size_t end) {
        const std::string_view word(text.data() + at, end - at);
        found = word == "for" || word == "while" || word == "do";
        return !found;
    });
    return found;
}

} // namespace

// `statements` run once per invocation, as a shader runs mainImage's statements once per pixel:
// they may add to what they set (`ball.y += 0.3;`) and the wrapper is called many times (the
// gradient's taps, every step of a ray). In a block of their own, so that their names (mainImage's
// `vec2 p`) do not clash with the point's. Needs `bool sdfwb_preludeRun = false;` at file scope.
std::string runOnce(const std::string& statements) {
    return "if (!sdfwb_preludeRun) { sdfwb_preludeRun = true;\n{\n" + statements + "\n}\n}\n";
}

// The `#endif`s a prelude needs: it is mainImage's text up to the march, which may stand in the
// branch of an `#ifdef` (Otavio Good's iceberg: `#else localTime = iGlobalTime; RayTrace(...)`).
std::string closedConditionals(const std::string& prelude) {
    static const std::regex opens(R"(^[ \t]*#[ \t]*if(?:n?def)?\b)", kLinearRegex),
        closes(R"(^[ \t]*#[ \t]*endif\b)", kLinearRegex);
    int open = 0;
    for (std::size_t start = 0; start < prelude.size();) {
        const std::size_t stop = std::min(prelude.find('\n', start), prelude.size());
        const std::size_t k = prelude.find_first_not_of(" \t", start);
        if (k < stop && prelude[k] == '#') {
            const std::string line = prelude.substr(start, stop - start);
            if (std::regex_search(line, opens)) ++open;
            if (std::regex_search(line, closes)) open = std::max(0, open - 1);
        }
        start = stop + 1;
    }
    std::string out = prelude;
    for (int i = 0; i < open; ++i) out += "\n#endif";
    return out;
}

std::string entryWrapper(const PreparedSdf& sdf) {
    SdfSignature signature = sdf.signature;
    signature.prelude = closedConditionals(signature.prelude);
    const std::string value = !signature.member.empty() ? "." + signature.member : signature.returnType == "float" ? "" : ".x";
    std::string text;
    if (!signature.inlineBody.empty() && signature.traced.empty()) {
        // The march's own loop body, run once at the point. Its prelude (the function's statements
        // before the loop) runs at every call: the body updates the locals it declares.
        text = "float sdfwb_sdf(vec3 sdfwb_point) {\n" + signature.prelude + "\n" + signature.inlineBody + "}\n";
    } else if (!signature.arguments.empty() || !signature.inlineBody.empty()) {
        // Parameters after the point (or of the function holding an inline march), computed as
        // mainImage does: once per invocation into globals, declared at every call under the
        // function's names in a block of their own (a parameter may have the name of a local of
        // mainImage). Then the call, or the march's statements.
        std::string kept, assigned, declared;
        for (std::size_t k = 0; k < signature.traced.size(); ++k) {
            const TracedValue& traced = signature.traced[k];
            if (traced.value.empty()) { // a local the field's out parameter writes
                declared += traced.type + " " + traced.name + ";\n";
                continue;
            }
            const std::string global = "sdfwb_traced" + std::to_string(k);
            kept += traced.type + " " + global + ";\n";
            assigned += global + " = " + traced.value + ";\n";
            declared += traced.type + " " + traced.name + " = " + global + ";\n";
        }
        const std::string field = !signature.inlineBody.empty()
                                      ? signature.inlineBody + "\n"
                                      : "return " + signature.entry + "(sdfwb_point" + signature.arguments + ")" + value + ";\n";
        text = kept + "bool sdfwb_preludeRun = false;\nfloat sdfwb_sdf(vec3 sdfwb_point) {\n" +
               runOnce(signature.prelude + "\n" + assigned) + "{\n" + declared + field + "}\n}\n";
    } else {
        // Out parameters get locals; a prelude alone (Fragmentarium's init(), what mainImage sets
        // before its march) runs once per invocation.
        std::string locals, arguments;
        for (std::size_t i = 0; i < signature.outParameters.size(); ++i) {
            locals += signature.outParameters[i] + " sdfwb_out" + std::to_string(i) + "; ";
            arguments += ", sdfwb_out" + std::to_string(i);
        }
        const bool prelude = !signature.prelude.empty();
        const std::string time = signature.animated ? ", sdfwb_time" : "";
        std::string field = signature.entry + "(p" + time + arguments + ")" + value;
        for (const auto& [name, read] : signature.unionWith)
            field = "min(" + field + ", " + name + "(p" + time + ")" + read + ")";
        text = std::string(prelude ? "bool sdfwb_preludeRun = false;\n" : "") + "float sdfwb_sdf(vec3 p) { " +
               (prelude ? runOnce(signature.prelude) : "") + locals + "return " + field + "; }\n";
    }
    // The user's macros end with the user's code: what follows is the workbench's.
    for (const std::string& macro : sdf.macros) text += "#undef " + macro + "\n";
    if (sdf.frame == PreparedSdf::Frame{}) return text;
    // Framed (PreparedSdf::frame): the wrapper above becomes the unframed field.
    text.replace(text.find("float sdfwb_sdf("), 16, "float sdfwb_unframed(");
    auto number = [](float value) { // a GLSL float literal: 4 is written 4.0
        char digits[32];
        std::snprintf(digits, sizeof digits, "%.9g", value);
        std::string literal = digits;
        return literal.find_first_of(".e") == std::string::npos ? literal + ".0" : literal;
    };
    const std::string scale = number(sdf.frame.scale);
    const std::string level = sdf.frame.level == 0.0f ? "" : " - " + number(sdf.frame.level);
    return text + "float sdfwb_sdf(vec3 sdfwb_framed) { return (sdfwb_unframed(vec3(" + number(sdf.frame.centre[0]) + ", " +
           number(sdf.frame.centre[1]) + ", " + number(sdf.frame.centre[2]) + ") + " + scale + " * sdfwb_framed)" + level +
           ") / " + scale + "; }\n";
}

const char* stageName(Stage stage) {
    switch (stage) {
    case Stage::Vertex:
        return "vertex";
    case Stage::Fragment:
        return "fragment";
    case Stage::Compute:
        return "compute";
    }
    return "?";
}

Expected<ShaderPiece> builtinPiece(const std::string& relativePath) {
    auto text = builtinShader(relativePath);
    if (!text) return text.error();
    return ShaderPiece{"sdfwb:" + relativePath, std::move(*text)};
}

Expected<std::vector<ShaderPiece>> samplingStagePieces(const ShaderPiece& sampler) {
    std::vector<std::string> before = {"sampling/bindings.glsl", "common/geometry.glsl", "sampling/common.glsl"};
    // Composed only for a sampler that uses it, so no other stage compiles the chain.
    static const std::regex call(R"(\bsdfwb_metropolisChain\s*\()", kLinearRegex);
    if (std::regex_search(stripComments(sampler.text), call)) before.push_back("sampling/metropolis_chain.glsl");
    std::vector<ShaderPiece> pieces;
    for (const std::string& file : before) {
        auto piece = builtinPiece(file);
        if (!piece) return piece.error();
        pieces.push_back(std::move(*piece));
    }
    pieces.push_back(sampler);
    auto stage = builtinPiece("sampling/sample.comp");
    if (!stage) return stage.error();
    pieces.push_back(std::move(*stage));
    return pieces;
}

ComposedShader composeSdfShader(const PreparedSdf& sdf, Stage stage, const std::vector<ShaderPiece>& pieces,
                                const FeatureDefines& features) {
    FeatureDefines all = features;
    if (sdf.signature.animated) all["SDFWB_ANIMATED"] = "1";
    if (sdf.usesTime()) all["SDFWB_USES_TIME"] = "1";
    for (const std::string& symbol : sdf.compat.symbols) {
        // Fragment shaders have derivatives; the prelude stands in for them in other stages only.
        const bool derivative = symbol == "dFdx" || symbol == "dFdy" || symbol == "fwidth" || symbol == "gl_FragCoord" ||
                                symbol == "texture" || symbol == "discard";
        if (!(derivative && stage == Stage::Fragment)) all["SDFWB_COMPAT_" + symbol] = "1";
    }
    for (const std::string& symbol : sdf.compat.wrapped) all["SDFWB_COMPAT_WRAPPED_" + symbol] = "1";
    for (const std::string& channel : sdf.compat.cubeChannels) all["SDFWB_COMPAT_CUBE_" + channel] = "1";
    if (all.count("SDFWB_COMPAT_g3d_uniformRandom")) all["SDFWB_NOISE_TEXTURE_UNIT"] = std::to_string(kNoiseTextureUnit);
    for (int n = 0; n < kShadertoyChannels; ++n)
        if (all.count("SDFWB_COMPAT_iChannel" + std::to_string(n)))
            all["SDFWB_CHANNEL" + std::to_string(n) + "_UNIT"] = std::to_string(kChannelTextureUnit + n);

    if (!sdf.mesh && !hasLoopKeyword(stripComments(sdf.source.text + sdf.signature.prelude + sdf.signature.inlineBody)))
        all["SDFWB_FIELD_WITHOUT_LOOPS"] = "1";
    if (sdf.mesh) {
        all["SDFWB_MESH_NODES_BINDING"] = std::to_string(kMeshNodesBinding);
        all["SDFWB_MESH_TRIANGLES_BINDING"] = std::to_string(kMeshTrianglesBinding);
        all["SDFWB_MESH_PSEUDONORMALS_BINDING"] = std::to_string(kMeshPseudonormalsBinding);
        all["SDFWB_MESH_NODE"] = std::to_string(meshfield::kNodeFloats / 4) + "u";
        all["SDFWB_MESH_LEAF"] = std::to_string(meshfield::kMaxLeafTriangles) + "u";
        all["SDFWB_MESH_STACK"] = std::to_string(sdf.mesh->depth + 2);
        all["SDFWB_MESH_WIDE"] = std::to_string(sdf.mesh->nodes.size() / 4) + "u";
        // A walk of the four-wide hierarchy leaves at most three siblings a level on its stack,
        // and a last node's four children.
        all["SDFWB_MESH_WIDE_STACK"] = std::to_string(3 * sdf.mesh->wideDepth + 4);
        if (sdf.meshIsTheField) all["SDFWB_MESH_SURFACE"] = "1";
        if (stage == Stage::Fragment) all["SDFWB_MESH_FRAGMENT"] = "1"; // mesh_field.glsl's helper lanes
        char beta[32];
        std::snprintf(beta, sizeof beta, "%.6f", sdf.mesh->options.beta);
        all["SDFWB_MESH_BETA"] = beta;
        switch (sdf.mesh->options.sign) {
        case meshfield::SignMethod::Winding:
            all["SDFWB_MESH_SIGN_WINDING"] = "1";
            // The sign lattice after the nodes, unless the caller uploads none (SDFWB_MESH_NO_LATTICE).
            if (!all.count("SDFWB_MESH_NO_LATTICE"))
                all["SDFWB_MESH_SIGNS"] = std::to_string((sdf.mesh->nodes.size() + sdf.mesh->wideNodes.size()) / 4) + "u";
            break;
        case meshfield::SignMethod::Parity:
            all["SDFWB_MESH_SIGN_PARITY"] = "1";
            break;
        case meshfield::SignMethod::Pseudonormal:
            all["SDFWB_MESH_SIGN_PSEUDONORMAL"] = "1";
            break;
        }
    }

    ComposedShader shader;
    shader.stage = stage;
    // The resolved SDF text numbers its files from 0 with #line directives; keep those indices.
    shader.map = sdf.source.map;
    shader.text = sdf.mesh && stage == Stage::Fragment ? kMeshFragmentVersionLine : kVersionLine;
    for (const std::string& extension : sdf.source.extensions) shader.text += extension + "\n";
    appendDefines(shader, all, sdf.usesTime());
    if (sdf.compat.any()) {
        auto compat = builtinShader("prelude/g3d_compat.glsl");
        // Embedded at build time, so it cannot be missing unless the build is broken.
        appendFile(shader, "sdfwb:prelude/g3d_compat.glsl", compat ? *compat : std::string("#error g3d_compat.glsl missing\n"));
    }
    if (sdf.mesh) {
        auto mesh = builtinShader("mesh/mesh_field.glsl");
        appendFile(shader, "sdfwb:mesh/mesh_field.glsl", mesh ? *mesh : std::string("#error mesh_field.glsl missing\n"));
    }
    // gl_FragCoord is a fragment shader's: elsewhere the code reads the prelude's stand-in (a macro
    // may not take a gl_ name). No line moves, so the source map holds.
    // Variables declared without a value are zero, as WebGL has them (ZeroInit.h): columns move, not lines.
    std::string userText = detail::zeroInitialised(sdf.source.text);
    for (const std::string& name : sdf.compat.renamed) userText = renameWord(userText, name, "sdfwb_" + name);
    if (all.count("SDFWB_COMPAT_gl_FragCoord")) userText = renameWord(userText, "gl_FragCoord", "sdfwb_FragCoord");
    if (all.count("SDFWB_COMPAT_discard")) userText = renameWord(userText, "discard", "sdfwb_discard()");
    // So are texture()'s bias form (g3d_compat.glsl).
    if (all.count("SDFWB_COMPAT_texture")) userText = renameBiasLookups(userText);
    if (sdf.signature.pointOut) userText = parametersInout(userText);
    shader.text += userText;
    if (!sdf.source.text.empty() && sdf.source.text.back() != '\n') shader.text += '\n';
    // No entry yet (the entry's search reads the user's code alone): no wrapper.
    if (!sdf.signature.entry.empty()) {
        // The wrapper runs statements copied from mainImage (an inline field's prelude): renamed alike.
        std::string wrapper = detail::zeroInitialised(entryWrapper(sdf));
        for (const std::string& name : sdf.compat.renamed) wrapper = renameWord(wrapper, name, "sdfwb_" + name);
        if (all.count("SDFWB_COMPAT_gl_FragCoord")) wrapper = renameWord(wrapper, "gl_FragCoord", "sdfwb_FragCoord");
        if (all.count("SDFWB_COMPAT_discard")) wrapper = renameWord(wrapper, "discard", "sdfwb_discard()");
        appendFile(shader, "<sdfwb entry point>", wrapper);
    }
    for (const ShaderPiece& piece : pieces) appendFile(shader, piece.name, piece.text);
    return shader;
}

Expected<ComposedShader> composeSdfShader(const PreparedSdf& sdf, Stage stage, const std::string& stageFile,
                                          const FeatureDefines& features) {
    auto piece = builtinPiece(stageFile);
    if (!piece) return piece.error();
    return composeSdfShader(sdf, stage, std::vector<ShaderPiece>{std::move(*piece)}, features);
}

Expected<ComposedShader> composeBuiltinShader(Stage stage, const std::string& stageFile, const FeatureDefines& features) {
    auto stageText = builtinShader(stageFile);
    if (!stageText) return stageText.error();
    ComposedShader shader;
    shader.stage = stage;
    shader.text = kVersionLine;
    appendDefines(shader, features);
    appendFile(shader, "sdfwb:" + stageFile, *stageText);
    return shader;
}

} // namespace sdfwb::shaders
