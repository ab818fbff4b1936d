#include "scene/trail.hpp"

#include <algorithm>

namespace epviz::scene {
namespace {

// Bounds the deviation test's work and memory whatever the input.
constexpr std::size_t kMaxSkipped = 1024;
// Points closer than this to the last one tested add nothing to the test.
constexpr double kNegligiblePx = 0.05;

// Distance from m to the segment a-b.
template <class V>
double segment_distance(const V& a, const V& m, const V& b) {
  const V ab = b - a;
  const double len2 = double(ab.squaredNorm());
  const double s = len2 > 0 ? std::clamp(double((m - a).dot(ab)) / len2, 0.0, 1.0) : 0.0;
  return double((a + float(s) * ab - m).norm());
}

}  // namespace

TrailHistory::TrailHistory(double sphere_px_per_unit, double plane_px_per_unit, double tolerance_px,
                           double max_gap_px)
    : sphere_px_(sphere_px_per_unit),
      plane_px_(plane_px_per_unit),
      tolerance_px_(tolerance_px),
      max_gap_px_(max_gap_px) {}

double TrailHistory::deviation_px(const HistoryPoint& from, const HistoryPoint& mid,
                                  const HistoryPoint& to) const {
  double d = segment_distance(from.sphere, mid.sphere, to.sphere) * sphere_px_;
  if (from.plane && mid.plane && to.plane)
    d = std::max(d, segment_distance(*from.plane, *mid.plane, *to.plane) * plane_px_);
  return d;
}

double TrailHistory::span_px(const HistoryPoint& a, const HistoryPoint& b) const {
  double d = double((a.sphere - b.sphere).norm()) * sphere_px_;
  if (a.plane && b.plane) d = std::max(d, double((*a.plane - *b.plane).norm()) * plane_px_);
  return d;
}

void TrailHistory::offer(const HistoryPoint& p) {
  if (points_.empty()) {
    points_.push_back(p);
    return;
  }
  if (held_) {
    const HistoryPoint& last = points_.back();
    // A change of plane visibility (to or from the south pole) is always kept.
    bool keep = held_->plane.has_value() != last.plane.has_value() ||
                p.plane.has_value() != held_->plane.has_value() || span_px(last, p) > max_gap_px_ ||
                skipped_.size() >= kMaxSkipped;
    if (skipped_.empty() || span_px(skipped_.back(), *held_) > kNegligiblePx)
      skipped_.push_back(*held_);
    for (std::size_t i = 0; !keep && i < skipped_.size(); ++i)
      keep = deviation_px(last, skipped_[i], p) > tolerance_px_;
    if (keep) {
      points_.push_back(*held_);
      skipped_.clear();
    }
  }
  held_ = p;
}

void TrailHistory::forget_before(double t_oldest) {
  while (points_.size() > 1 && points_[1].t <= t_oldest) points_.pop_front();
}

}  // namespace epviz::scene
