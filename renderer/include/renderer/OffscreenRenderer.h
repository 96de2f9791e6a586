#pragma once
// Renders into an offscreen framebuffer and reads the pixels back: screenshots, MP4 frames,
// headless renders. Needs a current GL context for every call, including destruction.

#include <renderer/Image.h>
#include <renderer/SdfRenderer.h>
#include <renderer/ShadertoyPicture.h>
#include <values/Camera.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace sdfwb::renderer {

class OffscreenRenderer {
public:
    OffscreenRenderer();
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    // Renders one frame at width x height and returns it (top row first). scale < 1 traces fewer
    // pixels and stretches them, as the viewport does while the camera moves.
    Image render(SdfRenderer& renderer, int width, int height, const values::Camera& camera, float time,
                 FrameStats* stats = nullptr, float scale = 1.0f);

    // A whole Shadertoy shader's own picture (its mainImage) at width x height, top row first.
    Image renderPicture(ShadertoyPicture& picture, int width, int height, const ShadertoyInputs& inputs);

    // The same frame in floating point (an RGBA32F target): what the shader wrote, values above 1
    // included, for high-dynamic-range files.
    FloatImage renderFloat(SdfRenderer& renderer, int width, int height, const values::Camera& camera, float time,
                           FrameStats* stats = nullptr);

    // Per-pixel tracing statistics (the renderer's shading must have statsOutput on): for each
    // pixel, top row first, {steps, hit distance t, |f| at the hit, length of the shading normal}.
    // A miss has t < 0 telling why: kLeftBox, kOutOfSteps or kNotFinite.
    struct PixelStats {
        float steps, t, residual, normalLength;
        static constexpr float kLeftBox = -1.0f;    // passed through the box: nothing there
        static constexpr float kOutOfSteps = -2.0f; // the step budget ran out
        static constexpr float kNotFinite = -3.0f;  // f was NaN or Inf along the ray
        bool hit() const { return t >= 0.0f; }
    };
    std::vector<PixelStats> renderStats(SdfRenderer& renderer, int width, int height, const values::Camera& camera, float time,
                                        FrameStats* stats = nullptr);

    // One event of a ray's march, as the tracer's SDFWB_RECORD hooks write it (tracer/probe.glsl).
    struct ProbeEvent {
        enum Kind : int {
            Step = 0,         // a plain step of d
            RelaxedStep = 1,  // an over-relaxed step of omega * d
            Fallback = 2,     // the relaxed step went too far: back by its relaxed part, then plain steps
            Hit = 3,          // |d| fell below the pixel footprint
            RefineKept = 4,   // a refining step after the hit that shrank |f|
            RefineUndone = 5, // a refining step that would have grown |f|: not taken
            LeftBox = 6,      // the ray passed the far side of the box (or the far plane)
            NotFinite = 7,    // f was NaN or Inf
            OutOfSteps = 8,   // the step budget ran out
            MissedBox = 9,    // the ray never entered the box
        };
        Kind kind;
        float t;              // distance along the ray
        float d;              // the value marched: f * step factor
        float gradientLength; // |grad f| (4-tap, the shading normal's step at t)
        glm::vec3 position;
    };
    struct ProbeTrace {
        std::vector<ProbeEvent> events;
        std::uint32_t dropped = 0; // events past the capacity
        PixelStats pixel;          // what the frame drew there (the shading must have statsOutput on)
    };
    // Replays the march of pixel (x, y) (top row 0) of a width x height frame through the very
    // program that draws it: the renderer's shading must have probe and statsOutput on. Records up
    // to `capacity` events.
    ProbeTrace probe(SdfRenderer& renderer, int width, int height, const values::Camera& camera, float time, int x, int y,
                     int capacity = 65536);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace sdfwb::renderer
