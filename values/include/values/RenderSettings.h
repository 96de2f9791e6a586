#pragma once
// GL-free settings that widgets and the CLI edit and the renderer consumes.

#include <core/NameTable.h>
#include <shaders/TracerComposer.h>

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sdfwb::values {

struct TraceSettings {
    int maxSteps = 256;          // step budget per ray; a ray that runs out counts as a miss
    float stepFactor = 1.0f;     // multiply each step; 1/L for an L-Lipschitz field
    float epsilonScale = 0.5f;   // hit when |f| < epsilonScale * (pixel footprint at the hit distance)
    float boxMargin = 0.05f;     // rays are clipped to [-1-margin, 1+margin]^3 before marching
    float overRelaxation = 1.0f; // omega > 1 enables over-relaxed steps with fallback (e.g. 1.6)
    // A cone pass per tile of coneTile x coneTile pixels first finds where their marches may start
    // (fewer steps per pixel for a second draw and a texture fetch per pixel). Auto: tried at rest
    // and kept when the full frame is faster (SdfRenderer::settleMarch).
    enum class Cones { Auto, Off, On };
    Cones cones = Cones::Auto;
    int coneTile = 4;
    // Trace only the pixels whose ray meets the box (its faces drawn as geometry over a cleared
    // background) where the picture shows only the background outside it. Off: every pixel runs
    // the tracer (for measurements against a full-frame reference).
    bool boxProxy = true;
    // Which program draws the picture: the fragment tracer or the compute tracer (8x8 tiles into
    // an image, blitted; shaders::computeTracerApplies). Auto: the fragment tracer, and at rest the
    // compute tracer is tried once and kept when a full frame is faster (SdfRenderer::settleMarch).
    enum class Tracer { Auto, Fragment, Compute };
    Tracer tracer = Tracer::Auto;
    bool operator==(const TraceSettings&) const = default;
};

// The names of the tracer and cone-pass choices (the CLI's --tracer and --cones, the job files'
// trace.tracer and trace.cones).
inline constexpr std::pair<TraceSettings::Tracer, const char*> kTracerNames[] = {{TraceSettings::Tracer::Auto, "auto"},
                                                                                 {TraceSettings::Tracer::Fragment, "fragment"},
                                                                                 {TraceSettings::Tracer::Compute, "compute"}};
inline constexpr std::pair<TraceSettings::Cones, const char*> kConesNames[] = {
    {TraceSettings::Cones::Auto, "auto"}, {TraceSettings::Cones::Off, "off"}, {TraceSettings::Cones::On, "on"}};
inline const char* tracerName(TraceSettings::Tracer tracer) { return nameOf(kTracerNames, tracer); }
inline std::optional<TraceSettings::Tracer> parseTracer(std::string_view name) { return valueNamed(kTracerNames, name); }
inline const char* conesName(TraceSettings::Cones cones) { return nameOf(kConesNames, cones); }
inline std::optional<TraceSettings::Cones> parseCones(std::string_view name) { return valueNamed(kConesNames, name); }

struct ShadingSettings {
    shaders::ShadingMode mode = shaders::ShadingMode::Normals;
    bool ambientOcclusion = false;
    glm::vec3 background{0.16f, 0.17f, 0.19f};      // RGB where rays miss (values above 1 reach .exr files)
    std::string backgroundImage;                    // an image file behind the shape instead (cover-fit); empty: none
    glm::vec3 lightDirection{-0.05f, 0.87f, 0.49f}; // towards the key light (Gooch): upper left of the default view
    float curvatureScale = 5.0f;                    // |mean curvature| drawn full red
    std::string matcap = "clay";                    // name in resources/matcaps or a path to an image
    bool statsOutput = false;                       // write (steps, t, |f(hit)|) per pixel: see OffscreenRenderer::renderStats
    bool probe = false;                             // record the march of one pixel: see OffscreenRenderer::probe
    std::vector<glm::vec3> markers;                 // points ringed over the picture (at most 16; "show where")
    bool operator==(const ShadingSettings&) const = default;
};

// The cutting plane dot(normal, p) = offset and how it is drawn.
struct CuttingPlane {
    bool enabled = false;
    glm::vec3 normal{0.0f, 0.0f, 1.0f}; // normalised on use; the side it points to is cut away when clipping
    float offset = 0.0f;
    float contourSpacing = 1.0f / 64.0f; // isocontours every this much distance
    float rampDistance = 1.0f;           // outside ramp: yellow at 0, blue at this distance
    bool clipSurface = true;             // cut the surface away in front of the plane
    bool lipschitzOverlay = true;        // red where |grad f| > 1, grey where ~0 away from the surface
    bool operator==(const CuttingPlane&) const = default;
};

} // namespace sdfwb::values
