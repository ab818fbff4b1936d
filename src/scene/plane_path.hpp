#pragma once
// The (a, b) path on the Riccati panel, honest about where it leaves the panel
// and where it passes through infinity (gamma at or near the south pole).
#include <deque>
#include <optional>
#include <vector>

#include "scene/frame.hpp"
#include "scene/trail.hpp"

namespace epviz::scene {

struct PlanePath {
  std::vector<PlanePoint> points;
  std::vector<PlaneMark> marks;
};

// `age(t)` maps a time to [0, 1] (0 = now). The panel is [-extent, extent]^2.
template <class AgeFn>
PlanePath build_plane_path(const std::deque<HistoryPoint>& history, float extent, AgeFn age);

// Where the segment p -> q crosses the border of [-e, e]^2 (p inside, q outside).
Eigen::Vector2f border_crossing(const Eigen::Vector2f& inside, const Eigen::Vector2f& outside,
                                float e);

bool inside_panel(const Eigen::Vector2f& p, float e);

// The (a, b) of gamma's direction; empty at the south pole. A run whose
// |gamma| drifted from 1 is projected along its direction: near the pole,
// gamma itself would land near the origin (1 + gamma3 is then no measure of
// the distance from the pole) and draw a chord across the panel.
std::optional<Eigen::Vector2f> plane_point(const Eigen::Vector3d& gamma);

// A step between two samples that goes around through infinity rather than
// across the plane: both near the south pole and the direction flips.
bool through_infinity(const HistoryPoint& p, const HistoryPoint& q);

template <class AgeFn>
PlanePath build_plane_path(const std::deque<HistoryPoint>& history, float extent, AgeFn age) {
  PlanePath path;
  const HistoryPoint* prev = nullptr;
  for (const auto& h : history) {
    const float a = age(h.t);
    if (!h.plane) {  // exactly at the south pole: (a, b) is infinite
      prev = &h;
      continue;
    }
    PlanePoint pt{*h.plane, a, false};
    if (prev) {
      if (!prev->plane || through_infinity(*prev, h)) {
        pt.break_before = true;
        const Eigen::Vector2f from = prev->plane ? *prev->plane : *h.plane;
        path.marks.push_back({from.normalized() * extent, PlaneMark::Kind::through_infinity, a});
      }
      if (prev->plane && !pt.break_before) {
        const bool in_prev = inside_panel(*prev->plane, extent),
                   in_now = inside_panel(pt.ab, extent);
        if (in_prev && !in_now)
          path.marks.push_back(
              {border_crossing(*prev->plane, pt.ab, extent), PlaneMark::Kind::leaves_panel, a});
        else if (!in_prev && in_now)
          path.marks.push_back(
              {border_crossing(pt.ab, *prev->plane, extent), PlaneMark::Kind::enters_panel, a});
      }
    }
    path.points.push_back(pt);
    prev = &h;
  }
  return path;
}

}  // namespace epviz::scene
