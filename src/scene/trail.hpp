#pragma once
// The history a frame draws: trail points kept only where the screen can tell
// them apart, and only over the trail's time window, so memory is bounded by
// the picture, not by the number of frames.
#include <deque>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace epviz::scene {

struct HistoryPoint {
  double t;
  Eigen::Vector3f sphere;                // the point drawn on the sphere
  std::optional<Eigen::Vector2f> plane;  // (a, b); empty at the south pole
  float gamma3;                          // to tell a pass through infinity
};

class TrailHistory {
 public:
  // The kept points, joined by straight lines, pass within `tolerance_px` of
  // every offered point on the sphere and on the plane; no two kept points are
  // more than `max_gap_px` apart (so that the time colouring stays smooth).
  TrailHistory(double sphere_px_per_unit, double plane_px_per_unit, double tolerance_px = 0.3,
               double max_gap_px = 16.0);

  // Offers the newest point. It is held back until the next offer shows
  // whether the line can skip it; the caller draws the newest point itself.
  void offer(const HistoryPoint& p);
  // Drops points older than t_oldest (keeping one before it, so the trail
  // starts exactly at the window's edge rather than a gap after it).
  void forget_before(double t_oldest);

  const std::deque<HistoryPoint>& points() const { return points_; }

 private:
  // How far (pixels) `mid` lies from the straight line from `from` to `to`.
  double deviation_px(const HistoryPoint& from, const HistoryPoint& mid,
                      const HistoryPoint& to) const;
  double span_px(const HistoryPoint& a, const HistoryPoint& b) const;

  double sphere_px_, plane_px_, tolerance_px_, max_gap_px_;
  std::deque<HistoryPoint> points_;
  std::optional<HistoryPoint> held_;  // the newest point, not yet decided
  // Every point offered since the last kept one, for the deviation test: a
  // line that skips several points must pass near all of them.
  std::vector<HistoryPoint> skipped_;
};

}  // namespace epviz::scene
