#pragma once
// A whole Shadertoy shader's own picture: the file's mainImage(out vec4, in vec2) run over the
// bound draw framebuffer with Shadertoy's inputs for one frame, so that the author's picture can
// be set beside sdfwb's tracer (View > Shadertoy picture, `--batch render --shadertoy-picture`).
// Every method needs the GL context that was current at the first call; call releaseGl() before
// that context goes away.

#include <shaders/Diagnostic.h>
#include <shaders/Parameters.h>
#include <shaders/SdfSource.h>

#include <glm/vec4.hpp>

#include <memory>
#include <vector>

namespace sdfwb::renderer {

// Shadertoy's per-frame inputs (iResolution is the frame's size).
struct ShadertoyInputs {
    float time = 0.0f;                             // iTime, seconds
    float timeDelta = 1.0f / 60.0f;                // iTimeDelta; iFrameRate is its inverse
    int frame = 0;                                 // iFrame
    glm::vec4 mouse{0.0f};                         // iMouse: xy while pressed, zw the click (negative once released)
    glm::vec4 date{2026.0f, 0.0f, 1.0f, 43200.0f}; // iDate: year, month - 1, day, seconds since midnight
};

class ShadertoyPicture {
public:
    ShadertoyPicture();
    ~ShadertoyPicture();
    ShadertoyPicture(const ShadertoyPicture&) = delete;
    ShadertoyPicture& operator=(const ShadertoyPicture&) = delete;

    // Compiles the file's mainImage. An SDF without one is an error naming the form expected; on
    // any error the last good program stays.
    std::vector<shaders::Diagnostic> setSdf(const shaders::PreparedSdf& sdf);
    void setParameters(std::vector<shaders::ParameterSetting> parameters);
    bool hasProgram() const;
    // Draws width x height pixels into the bound draw framebuffer. Returns the milliseconds it
    // took on the CPU; with `finish` that includes glFinish, so it is the frame's whole cost.
    double render(int width, int height, const ShadertoyInputs& inputs, bool finish = false);
    void releaseGl();

private:
    void draw(int width, int height, const ShadertoyInputs& inputs);
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace sdfwb::renderer
