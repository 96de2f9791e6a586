#include "FieldFrame.h"

#include <core/Log.h>
#include <renderer/HeadlessContext.h>
#include <sampling/FieldEvaluator.h>
#include <sampling/SurfaceBox.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace sdfwb::jobs {
namespace {

std::vector<float> boxNumbers(const std::string& text) {
    std::vector<float> numbers;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        char* end = nullptr;
        const float value = std::strtof(item.c_str(), &end);
        if (item.empty() || end == item.c_str() || *end != '\0' || !std::isfinite(value)) return {};
        numbers.push_back(value);
    }
    return numbers;
}

// The field's surface box at time 0 (sampling::findSurfaceBox). With `outsideOnly`, none where the
// surface crosses [-1, 1]^3: that cube alone is searched first, so a field whose surface crosses it
// (every dataset file, most pasted scenes) costs one lattice, not one of each size (a floor
// reaches every cube's faces). One compile either way.
Expected<std::optional<sampling::SurfaceBox>> searchSurface(const shaders::PreparedSdf& sdf,
                                                            const std::vector<shaders::ParameterSetting>& parameters,
                                                            sampling::FieldRange* range = nullptr) {
    sampling::FieldEvaluator evaluator;
    if (shaders::hasErrors(evaluator.build(sdf))) return makeError("the field does not compile for the surface search");
    sampling::FieldSettings settings;
    settings.parameters = parameters;
    return sampling::findSurfaceBox(evaluator, settings, 64.0f, range); // the evaluator releases its GL objects
}

// Never negative and near 0 somewhere: a distance to thin lines or sheets, floored or taken with
// abs(). Near means within what the lattice can see (a distance above sqrt(3)/2 of its spacing at
// every lattice point has no zero in its cube): a glow's density stays further off.
// A constant (a stub `map` returning 0, the shader's picture drawn by other code) is no distance.
bool looksUnsigned(const sampling::FieldRange& range) {
    return !range.negative && range.least <= 0.87f * range.finest && range.most > range.least;
}

// Why a field whose search found no surface has none, from the values the lattices held; for an
// unsigned field, the level its own march stops at where that is known.
std::string noSurfaceText(const sampling::FieldRange& range, const shaders::PreparedSdf& sdf) {
    if (range.finite == 0) return "the field is not finite anywhere within [-64, 64]^3";
    char text[600];
    if (range.most == range.least)
        std::snprintf(text, sizeof text,
                      "the field is %.4g everywhere within [-64, 64]^3: a constant, with no surface (is %s the "
                      "function the shader draws? --entry NAME picks another)",
                      double(range.least), sdf.signature.entry.c_str());
    else if (looksUnsigned(range) && sdf.marchThreshold > 0.0f)
        std::snprintf(text, sizeof text,
                      "the field is never negative within [-64, 64]^3 and its least value is %.3g: an unsigned "
                      "distance, with no inside, so samples never change sign and there is nothing to mesh; the "
                      "tracer shows where rays come within its tolerance. Its own march stops where the field drops "
                      "below %.7g (line %d): --level %.7g takes that level set as the surface",
                      double(range.least), double(sdf.marchThreshold), sdf.marchThresholdLine, double(sdf.marchThreshold));
    else if (looksUnsigned(range))
        std::snprintf(text, sizeof text,
                      "the field is never negative within [-64, 64]^3 and its least value is %.3g: an unsigned "
                      "distance, with no inside, so samples never change sign and there is nothing to mesh; the "
                      "tracer shows where rays come within its tolerance. --level L takes f = L as the surface "
                      "(a shader's own march stops where f drops below its hit threshold, often 0.001)",
                      double(range.least));
    else
        std::snprintf(text, sizeof text,
                      "the field has no surface within [-64, 64]^3: its values run from %.4g to %.4g with no change of "
                      "sign between neighbours of a 40^3 lattice (a glow's density, or a field drawn from the pixel)",
                      double(range.least), double(range.most));
    return text;
}

// What stands on a floor (SurfaceBox::onFloor) as a box of its own; `box` itself where there is none.
sampling::SurfaceBox framedPart(const sampling::SurfaceBox& box) {
    if (!box.onFloor) return box;
    sampling::SurfaceBox part = box;
    part.low = box.onFloorLow, part.high = box.onFloorHigh;
    float squared = 0.0f;
    for (std::size_t a = 0; a < 3; ++a) {
        part.centre[a] = 0.5f * (part.low[a] + part.high[a]);
        squared += 0.25f * (part.high[a] - part.low[a]) * (part.high[a] - part.low[a]);
    }
    part.radius = std::sqrt(squared);
    return part;
}

// Half the longest side of `box`: the scale that frames it as [-1, 1]^3.
float halfSide(const sampling::SurfaceBox& box) {
    float half = 0.0f;
    for (std::size_t a = 0; a < 3; ++a) half = std::max(half, 0.5f * (box.high[a] - box.low[a]));
    return half;
}

// The box X0,Y0,Z0,X1,Y1,Z1 (as --normalize takes it) centred on `box` with its longest side.
std::string boxText(const sampling::SurfaceBox& box) {
    const float half = halfSide(box);
    char text[200];
    std::snprintf(text, sizeof text, "%.5g,%.5g,%.5g,%.5g,%.5g,%.5g", box.centre[0] - half, box.centre[1] - half,
                  box.centre[2] - half, box.centre[0] + half, box.centre[1] + half, box.centre[2] + half);
    return text;
}

std::string formatted(const char* format, double a, double b, double c) {
    char text[160];
    std::snprintf(text, sizeof text, format, a, b, c);
    return text;
}

// The plane a floor lies in (SurfaceBox::onFloor), as messages name it: "y = 0".
std::string floorText(const sampling::SurfaceBox& box) {
    char text[64];
    std::snprintf(text, sizeof text, "%c = %.4g", "xyz"[box.floorAxis], double(box.floorAt));
    return text;
}

} // namespace

bool isFrameBox(const std::string& normalize) { return normalize.find(',') != std::string::npos; }

std::optional<std::string> frameBoxProblem(const std::string& normalize) {
    const std::vector<float> n = boxNumbers(normalize);
    if (n.size() != 6)
        return "'" + normalize + "': expected none, unit-cube, unit-sphere or a box X0,Y0,Z0,X1,Y1,Z1 (six finite numbers)";
    for (int a = 0; a < 3; ++a)
        if (!(n[std::size_t(a)] < n[std::size_t(a) + 3]))
            return "'" + normalize + "': each low corner's number must be below the high corner's";
    return std::nullopt;
}

std::optional<JobError> frameField(shaders::PreparedSdf& sdf, const std::string& normalize,
                                   const std::vector<shaders::ParameterSetting>& parameters, const std::string& label,
                                   const std::string& what) {
    if (normalize.empty() || normalize == "none") return std::nullopt;
    shaders::PreparedSdf::Frame frame;
    frame.level = sdf.frame.level; // --level is set first: the search looks for f = level
    if (isFrameBox(normalize)) {
        if (auto problem = frameBoxProblem(normalize)) return usageError(key("normalize") + ": " + *problem);
        const std::vector<float> n = boxNumbers(normalize);
        frame.scale = 0.0f;
        for (std::size_t a = 0; a < 3; ++a) {
            frame.centre[a] = 0.5f * (n[a] + n[a + 3]);
            frame.scale = std::max(frame.scale, 0.5f * (n[a + 3] - n[a]));
        }
    } else {
        const auto start = std::chrono::steady_clock::now();
        if (!renderer::HeadlessContext::anyCurrent())
            return workError(KeyedText(what + ": " + label + ": ") + key("normalize") + " " + normalize +
                             " searches the field's values and needs a GL context");
        sampling::FieldRange range;
        auto found = searchSurface(sdf, parameters, &range);
        if (!found) return workError(KeyedText(what + ": " + label + ": ") + key("normalize") + ": " + found.error().message);
        if (!*found)
            return workError(KeyedText(what + ": " + label + ": ") + key("normalize") + " " + normalize + ": " +
                             noSurfaceText(range, sdf) + "; or give the box to frame as X0,Y0,Z0,X1,Y1,Z1");
        const sampling::SurfaceBox box = framedPart(**found);
        frame.centre = box.centre;
        frame.scale = halfSide(box);
        if (normalize == "unit-sphere") frame.scale = box.radius;
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        log::info(
            what,
            label + ": the surface lies in [" + formatted("%.4g, %.4g, %.4g", box.low[0], box.low[1], box.low[2]) + "] - [" +
                formatted("%.4g, %.4g, %.4g", box.high[0], box.high[1], box.high[2]) + "] (" + std::to_string(box.points) +
                " crossings of a 40^3 lattice over [-" + formatted("%g, %g]^3, %.2f s)", box.searched, box.searched, seconds) +
                (box.onFloor ? ": what stands on the plane " + floorText(box) + " that [-1, 1]^3 holds alone" : std::string()));
    }
    sdf.frame = frame;
    char line[200];
    std::snprintf(line, sizeof line, "(%.6g, %.6g, %.6g) + %.6g p, its values divided by %.6g", frame.centre[0], frame.centre[1],
                  frame.centre[2], frame.scale, frame.scale);
    log::info(what, label + ": framed (normalize " + normalize + "): [-1, 1]^3 shows the field at " + line);
    return std::nullopt;
}

PastedView decidePastedView(const shaders::PreparedSdf& sdf, const std::vector<shaders::ParameterSetting>& parameters) {
    PastedView view;
    if (sdf.mesh || !sdf.ok() || !renderer::HeadlessContext::anyCurrent()) return view;
    sampling::FieldRange range;
    auto found = searchSurface(sdf, parameters, &range);
    if (!found) return view;
    if (*found) {
        // Held whole by a cube larger than [-1, 1]^3 (searched > 1): none inside the unit box, or a
        // scene the unit box cuts. One [-1, 1]^3 holds whole, or a floor every cube cuts, is shown as it is.
        if (const sampling::SurfaceBox& box = **found; box.searched > 1.0f) {
            view.box = boxText(box);
            view.cut = true;
            for (std::size_t a = 0; a < 3; ++a) view.cut = view.cut && box.low[a] < 1.0f && box.high[a] > -1.0f;
        } else if (box.onFloor) { // [-1, 1]^3 holds only the floor the scene stands on
            view.box = boxText(framedPart(box));
            view.floor = floorText(box);
        }
    } else if (range.finite > 0) {
        view.noSurface = noSurfaceText(range, sdf);
        if (looksUnsigned(range)) view.level = sdf.marchThreshold;
    }
    return view;
}

std::string noSurfaceReason(const shaders::PreparedSdf& sdf, const std::vector<shaders::ParameterSetting>& parameters) {
    if (sdf.mesh || !sdf.ok() || !renderer::HeadlessContext::anyCurrent()) return {};
    sampling::FieldRange range;
    auto found = searchSurface(sdf, parameters, &range);
    return found && !*found ? noSurfaceText(range, sdf) : std::string();
}

} // namespace sdfwb::jobs
