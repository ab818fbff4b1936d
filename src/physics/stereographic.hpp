#pragma once
// Stereographic coordinates of the unit sphere (docs/math.md eq. 3.4):
//   gamma1 = -2 a / (1 + a^2 + b^2), gamma2 = -2 b / (1 + a^2 + b^2),
//   gamma3 = (1 - a^2 - b^2) / (1 + a^2 + b^2).
// The projection is from the south pole gamma = (0, 0, -1), which maps to infinity.
#include <Eigen/Core>
#include <optional>

namespace epviz::physics {

// (a, b) of a unit gamma; nullopt when 1 + gamma3 <= 1e-15 (at the south pole).
inline std::optional<Eigen::Vector2d> stereographic(const Eigen::Vector3d& gamma) {
  const double d = 1.0 + gamma.z();
  if (!(d > 1e-15)) return std::nullopt;
  return Eigen::Vector2d(-gamma.x() / d, -gamma.y() / d);
}

// gamma of (a, b); always a unit vector (up to round-off).
inline Eigen::Vector3d from_stereographic(double a, double b) {
  const double r2 = a * a + b * b;
  const double inv = 1.0 / (1.0 + r2);
  return Eigen::Vector3d(-2.0 * a * inv, -2.0 * b * inv, (1.0 - r2) * inv);
}

}  // namespace epviz::physics
