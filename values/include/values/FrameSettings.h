#pragma once
// How a picture is made, apart from its SDF, size, time and plane (those are the document's): the
// shading, the march, the camera and whether the SDF's credits are drawn. The workbench's viewport
// owns the one on screen and draws with it; screenshots, videos and the probe take that value whole
// (a FrameRequest is one, with the document's part beside it).

#include <values/Camera.h>
#include <values/RenderSettings.h>

namespace sdfwb::values {

struct FrameSettings {
    values::ShadingSettings shading;
    values::TraceSettings trace;
    values::Camera camera;
    bool overlay = false; // the SDF's name, author and license in the lower-left corner (its metadata block)
    bool operator==(const FrameSettings&) const = default;
};

} // namespace sdfwb::values
