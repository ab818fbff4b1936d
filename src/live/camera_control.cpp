#include "live/camera_control.hpp"

#include <algorithm>
#include <cmath>

namespace epviz::live {

scene::CameraSettings orbit_by_drag(scene::CameraSettings c, float dx_px, float dy_px,
                                    float view_height_px) {
  const double deg_per_px = 180.0 / std::max(1.0f, view_height_px);
  // Dragging right turns the scene right: the camera moves the other way.
  c.azimuth_deg = std::remainder(c.azimuth_deg - dx_px * deg_per_px, 360.0);
  // The same limits the job loader accepts (strictly inside +-90 degrees).
  c.elevation_deg = std::clamp(c.elevation_deg + dy_px * deg_per_px, -89.0, 89.0);
  return c;
}

scene::CameraSettings zoom_by_wheel(scene::CameraSettings c, float notches) {
  // The job loader needs more than 1.2 sphere radii; 20 is far enough to see nothing.
  c.distance = std::clamp(c.distance * std::pow(0.9, double(notches)), 1.5, 20.0);
  return c;
}

}  // namespace epviz::live
