#pragma once
// The history a frame draws: trail points kept only where the screen can tell
// them apart, and only over the trail's time window, so memory is bounded by
// the picture, not by the number of frames.
#include <deque>
#include <optional>

#include <Eigen/Core>

namespace epviz::scene {

struct HistoryPoint {
  double t;
  Eigen::Vector3f sphere;               // the point drawn on the sphere
  std::optional<Eigen::Vector2f> plane; // (a, b); empty at the south pole
  float gamma3;                         // to tell a pass through infinity
};

class TrailHistory {
 public:
  // A point is kept when it is at least `min_px` pixels from the last kept one
  // on the sphere or on the plane.
  TrailHistory(double sphere_px_per_unit, double plane_px_per_unit, double min_px = 1.0);

  // Offers the newest point; returns true if it was kept.
  bool offer(const HistoryPoint& p);
  // Drops points older than t_oldest (keeping one before it, so the trail
  // starts exactly at the window's edge rather than a gap after it).
  void forget_before(double t_oldest);

  const std::deque<HistoryPoint>& points() const { return points_; }

 private:
  double sphere_px_, plane_px_, min_px_;
  std::deque<HistoryPoint> points_;
};

}  // namespace epviz::scene
