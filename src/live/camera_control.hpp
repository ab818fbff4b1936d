#pragma once
// Mouse control of the 3D view's orbit camera: a drag turns it (half a turn
// across the view's height), the wheel moves it closer or further.
#include "scene/frame.hpp"

namespace epviz::live {

scene::CameraSettings orbit_by_drag(scene::CameraSettings camera, float dx_px, float dy_px,
                                    float view_height_px);
// Positive notches (wheel up) zoom in.
scene::CameraSettings zoom_by_wheel(scene::CameraSettings camera, float notches);

}  // namespace epviz::live
