#pragma once
// Validates composed GLSL with glslang in process (no GL needed) and returns diagnostics mapped
// to the user's files. Thread-safe: may run on a worker thread while the UI types.

#include <shaders/Diagnostic.h>
#include <shaders/ShaderComposer.h>

#include <vector>

namespace sdfwb::shaders {

std::vector<Diagnostic> checkWithGlslang(const ComposedShader& shader);

// glslang's one process-wide initialisation (every in-process use of glslang calls this first).
void ensureGlslangInitialised();

} // namespace sdfwb::shaders
