#include "scene/body_shape.hpp"

#include <algorithm>
#include <cmath>

namespace epviz::scene {

BodyShape body_shape(const physics::Body& body) {
  const Eigen::Vector3d& I = body.inertia;
  Eigen::Vector3d half;
  for (int i = 0; i < 3; ++i) {
    const double side2 = 6.0 * (I.sum() - 2.0 * I[i]);
    half[i] = 0.5 * std::sqrt(std::max(side2, 1e-4 * I.maxCoeff()));
  }
  // The box's far corner from the fixed point stays at 0.75 of the sphere.
  const double reach = (body.com.cwiseAbs() + half).norm();
  const double scale = 0.75 / reach;
  BodyShape shape;
  shape.half_extents = (half * scale).cast<float>();
  shape.centre_of_mass = (body.com * scale).cast<float>();
  return shape;
}

}  // namespace epviz::scene
