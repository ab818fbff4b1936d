#include "scene/plane_path.hpp"

#include <algorithm>
#include <cmath>

#include "physics/stereographic.hpp"

namespace epviz::scene {

bool inside_panel(const Eigen::Vector2f& p, float e) {
  return std::abs(p.x()) <= e && std::abs(p.y()) <= e;
}

Eigen::Vector2f border_crossing(const Eigen::Vector2f& in, const Eigen::Vector2f& out, float e) {
  // Largest s in [0, 1] with in + s (out - in) inside the square.
  const Eigen::Vector2f d = out - in;
  float s = 1.0f;
  for (int i = 0; i < 2; ++i) {
    if (d[i] > 0.0f) s = std::min(s, (e - in[i]) / d[i]);
    if (d[i] < 0.0f) s = std::min(s, (-e - in[i]) / d[i]);
  }
  return in + std::max(s, 0.0f) * d;
}

std::optional<Eigen::Vector2f> plane_point(const Eigen::Vector3d& gamma) {
  const double n = gamma.norm();
  if (!(n > 0.0)) return std::nullopt;
  if (auto ab = physics::stereographic(gamma / n)) return ab->cast<float>();
  return std::nullopt;
}

bool through_infinity(const HistoryPoint& p, const HistoryPoint& q) {
  if (!p.plane || !q.plane) return true;
  // gamma3 < -0.6 means |eta| > 2: far out on the plane, near the south pole.
  return p.gamma3 < -0.6f && q.gamma3 < -0.6f && p.plane->dot(*q.plane) < 0.0f;
}

}  // namespace epviz::scene
