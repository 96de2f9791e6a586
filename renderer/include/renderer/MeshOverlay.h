#pragma once
// A triangle mesh drawn over the traced frame, through the same camera, coloured per pixel by the
// SDF's value at the mesh's own point there: where the mesh strays from the zero set shows at a
// glance (an exported mesh, or any mesh a user loads, graded against the field it came from).
// Every method needs the GL context that was current at the first call; releaseGl() before that
// context goes away.

#include <shaders/Diagnostic.h>
#include <shaders/Parameters.h>
#include <shaders/SdfSource.h>
#include <values/Camera.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace sdfwb::renderer {

class MeshOverlay {
public:
    MeshOverlay();
    ~MeshOverlay();
    MeshOverlay(const MeshOverlay&) = delete;
    MeshOverlay& operator=(const MeshOverlay&) = delete;

    // Compiles the deviation shader for this SDF. On failure returns the diagnostics and keeps
    // the last good one.
    std::vector<shaders::Diagnostic> setSdf(const shaders::PreparedSdf& sdf);
    // 3 floats per vertex, 3 indices per triangle (counter-clockwise or not: both sides are drawn).
    void setMesh(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices);
    void clearMesh();
    bool hasMesh() const;
    std::uint64_t triangleCount() const;

    // Draws over the framebuffer bound now (it needs no depth buffer: the overlay has its own):
    // grey where |f| is 0, red (f > 0) or blue (f < 0) reaching full colour at |f| = scale.
    void draw(int width, int height, const values::Camera& camera, float time,
              const std::vector<shaders::ParameterSetting>& parameters, float scale);

    void releaseGl();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace sdfwb::renderer
