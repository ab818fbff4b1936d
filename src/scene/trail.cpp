#include "scene/trail.hpp"

namespace epviz::scene {

TrailHistory::TrailHistory(double sphere_px_per_unit, double plane_px_per_unit, double min_px)
    : sphere_px_(sphere_px_per_unit), plane_px_(plane_px_per_unit), min_px_(min_px) {}

bool TrailHistory::offer(const HistoryPoint& p) {
  if (!points_.empty()) {
    const auto& last = points_.back();
    const double sphere_px = (p.sphere - last.sphere).norm() * sphere_px_;
    // A change of plane visibility (to or from the south pole) is always kept.
    const double plane_px = (p.plane && last.plane) ? double((*p.plane - *last.plane).norm()) * plane_px_
                            : (p.plane.has_value() != last.plane.has_value()) ? 1e9
                                                                              : 0.0;
    if (sphere_px < min_px_ && plane_px < min_px_) return false;
  }
  points_.push_back(p);
  return true;
}

void TrailHistory::forget_before(double t_oldest) {
  while (points_.size() > 1 && points_[1].t <= t_oldest) points_.pop_front();
}

}  // namespace epviz::scene
