#pragma once
// A cloud of sample points drawn over the traced frame through the same camera, each point
// coloured by its gradient's direction (the paper's Figure 15): a sampling run previewed in the
// viewport, or any .bin/.npz/.ply sample file looked at over the surface it came from. Points
// hide each other by depth (the overlay has its own depth buffer), not the surface.
// Every method that draws or frees needs the GL context that was current at the first draw.

#include <values/Camera.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace sdfwb::renderer {

class PointCloudOverlay {
public:
    PointCloudOverlay();
    ~PointCloudOverlay();
    PointCloudOverlay(const PointCloudOverlay&) = delete;
    PointCloudOverlay& operator=(const PointCloudOverlay&) = delete;

    // 3 floats per point each; rows with a NaN or Inf position are left out (the caller counts
    // them). No GL call: the upload happens at the next draw.
    void setPoints(const std::vector<float>& positions, const std::vector<float>& gradients);
    void clear();
    bool hasPoints() const;
    std::uint64_t pointCount() const; // points that will be drawn

    // Draws over the framebuffer bound now; pointSize in pixels (1..64).
    void draw(int width, int height, const values::Camera& camera, float pointSize);

    void releaseGl();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace sdfwb::renderer
