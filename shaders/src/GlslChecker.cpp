#include <shaders/GlslChecker.h>

#include <shaders/DiagnosticParser.h>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <mutex>

namespace sdfwb::shaders {
namespace {

EShLanguage toLanguage(Stage stage) {
    switch (stage) {
    case Stage::Vertex:
        return EShLangVertex;
    case Stage::Fragment:
        return EShLangFragment;
    case Stage::Compute:
        return EShLangCompute;
    }
    return EShLangFragment;
}

} // namespace

// FinalizeProcess is left to process exit.
void ensureGlslangInitialised() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

std::vector<Diagnostic> checkWithGlslang(const ComposedShader& composed) {
    ensureGlslangInitialised();
    EShLanguage language = toLanguage(composed.stage);
    glslang::TShader shader(language);
    // With its length: a NUL byte in the code (a pasted file's stray byte) is an error at its line,
    // not the end of the text.
    const char* text = composed.text.c_str();
    const int length = int(composed.text.size());
    shader.setStringsWithLengths(&text, &length, 1);
    // No client/target environment: plain desktop GLSL rules, as a GL driver applies them
    // (an OpenGL/SPIR-V environment would demand explicit uniform locations).
    // Cascading errors: report every error, not just the first.
    auto messages = static_cast<EShMessages>(EShMsgDefault | EShMsgCascadingErrors);
    bool parsed = shader.parse(GetDefaultResources(), 430, ECoreProfile, false, false, messages);
    std::vector<Diagnostic> diagnostics = parseInfoLog(shader.getInfoLog(), composed.map);
    if (parsed) {
        // Linking finds what a single stage parse does not (e.g. a missing main()).
        glslang::TProgram program;
        program.addShader(&shader);
        if (!program.link(messages)) {
            auto linkDiagnostics = parseInfoLog(program.getInfoLog(), composed.map);
            diagnostics.insert(diagnostics.end(), linkDiagnostics.begin(), linkDiagnostics.end());
        }
    } else if (!hasErrors(diagnostics)) {
        diagnostics.push_back({composed.map.fileName(0), 0, 0, Severity::Error,
                               std::string("glslang rejected the shader: ") + shader.getInfoLog()});
    }
    return diagnostics;
}

} // namespace sdfwb::shaders
