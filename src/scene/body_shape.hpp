#pragma once
#include "physics/body.hpp"
#include "scene/frame.hpp"

namespace epviz::scene {

// The uniform box with the body's principal moments (unit mass: side_i^2 =
// 6 (I_j + I_k - I_i)), centred on the centre of mass, scaled so that box and
// centre of mass fit well inside the unit sphere. A non-physical body (which
// breaks a triangle inequality) gets a thin side instead of an imaginary one.
BodyShape body_shape(const physics::Body& body);

}  // namespace epviz::scene
