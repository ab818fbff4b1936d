#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <vector>

#include "physics/body.hpp"
#include "scene/body_shape.hpp"
#include "scene/plane_path.hpp"
#include "scene/trail.hpp"

namespace epviz {
namespace {

scene::HistoryPoint on_circle(double t, double radius_angle = 0.5) {
  const double s = std::sin(radius_angle), c = std::cos(radius_angle);
  scene::HistoryPoint p;
  p.t = t;
  p.sphere = Eigen::Vector3f(float(s * std::cos(t)), float(s * std::sin(t)), float(c));
  p.plane = Eigen::Vector2f(float(s * std::cos(t) / (1 + c)), float(s * std::sin(t) / (1 + c)));
  p.gamma3 = float(c);
  return p;
}

// Distance (in units) from q to the polyline through `pts`.
double distance_to_polyline(const std::deque<scene::HistoryPoint>& pts, const Eigen::Vector3f& q) {
  double best = 1e9;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const Eigen::Vector3f a = pts[i - 1].sphere, ab = pts[i].sphere - a;
    const float s = std::clamp((q - a).dot(ab) / std::max(ab.squaredNorm(), 1e-20f), 0.0f, 1.0f);
    best = std::min(best, double((a + s * ab - q).norm()));
  }
  return best;
}

TEST(TrailHistory, KeepsOnlyWhatThePixelsCanTellApart) {
  // 100 px per unit: a circle of radius sin(0.5) ~ 0.48 is ~300 px around.
  scene::TrailHistory h(100.0, 1.0, 0.3, 16.0);
  std::vector<scene::HistoryPoint> offered;
  for (double t = 0; t < 2 * M_PI; t += 1e-3) {
    offered.push_back(on_circle(t));
    h.offer(offered.back());
  }
  const auto& kept = h.points();
  // Far fewer points than offered, but at least what a 16 px gap limit needs.
  EXPECT_LT(kept.size(), 60u);
  EXPECT_GE(kept.size(), 300u / 16u);
  // The line through the kept points (and the newest point, drawn by the
  // caller) passes within the tolerance of every offered point.
  auto with_newest = kept;
  with_newest.push_back(offered.back());
  double worst = 0.0;
  for (const auto& p : offered)
    worst = std::max(worst, distance_to_polyline(with_newest, p.sphere) * 100.0);
  EXPECT_LT(worst, 0.3 + 1e-3);
  // Stricter tolerance, more points: the test can tell.
  scene::TrailHistory strict(100.0, 1.0, 0.02, 16.0);
  for (const auto& p : offered) strict.offer(p);
  EXPECT_GT(strict.points().size(), 2 * kept.size());
}

TEST(TrailHistory, AStillPointKeepsMemoryBounded) {
  scene::TrailHistory h(100.0, 1.0);
  for (int k = 0; k < 100000; ++k) {
    auto p = on_circle(0.0);
    p.t = k;
    h.offer(p);
  }
  h.forget_before(100000 - 10);
  EXPECT_LE(h.points().size(), 2u);
}

TEST(TrailHistory, MemoryDoesNotGrowWithTimeForAFixedWindow) {
  scene::TrailHistory h(100.0, 1.0);
  std::size_t after_short = 0;
  for (int k = 0; k < 200000; ++k) {
    const double t = k * 1e-3;
    h.offer(on_circle(t));
    h.forget_before(t - 5.0);
    if (k == 20000) after_short = h.points().size();
  }
  EXPECT_LE(h.points().size(), after_short + 2);
  EXPECT_GE(h.points().front().t, 200.0 - 5.0 - 0.1);
}

TEST(PlanePath, LeavingAndReenteringThePanelIsMarkedOnTheBorder) {
  std::deque<scene::HistoryPoint> hist;
  for (int i = 0; i <= 40; ++i) {
    scene::HistoryPoint p;
    p.t = i;
    const float x = -3.0f + 0.15f * float(i);  // from -3 to 3 along b = 0.5
    p.plane = Eigen::Vector2f(x, 0.5f);
    p.sphere = Eigen::Vector3f::UnitZ();
    p.gamma3 = 0.0f;
    hist.push_back(p);
  }
  const auto path = scene::build_plane_path(hist, 2.5f, [](double) { return 0.0f; });
  ASSERT_EQ(path.marks.size(), 2u);
  EXPECT_EQ(path.marks[0].kind, scene::PlaneMark::Kind::enters_panel);
  EXPECT_NEAR(path.marks[0].ab.x(), -2.5f, 1e-5);
  EXPECT_EQ(path.marks[1].kind, scene::PlaneMark::Kind::leaves_panel);
  EXPECT_NEAR(path.marks[1].ab.x(), 2.5f, 1e-5);
  for (const auto& p : path.points) EXPECT_FALSE(p.break_before);
}

TEST(PlanePath, PassingThroughInfinityBreaksThePathAndIsMarked) {
  std::deque<scene::HistoryPoint> hist;
  // Towards +infinity along a, then back from -infinity: gamma passed the south pole.
  for (float a : {1.0f, 5.0f, 40.0f, -40.0f, -5.0f, -1.0f}) {
    scene::HistoryPoint p;
    p.t = 0;
    p.plane = Eigen::Vector2f(a, 0.1f);
    const float r2 = a * a + 0.01f;
    p.gamma3 = (1 - r2) / (1 + r2);
    p.sphere = Eigen::Vector3f::UnitZ();
    hist.push_back(p);
  }
  const auto path = scene::build_plane_path(hist, 2.5f, [](double) { return 0.0f; });
  int breaks = 0;
  for (const auto& p : path.points) breaks += p.break_before;
  EXPECT_EQ(breaks, 1);
  int infinities = 0;
  for (const auto& m : path.marks) infinities += m.kind == scene::PlaneMark::Kind::through_infinity;
  EXPECT_EQ(infinities, 1);
}

TEST(BodyShape, UniformBoxHasTheBodysPrincipalMomentRatios) {
  physics::Body b;
  b.inertia = {2.0, 3.0, 4.0};
  b.com = {0.1, 0.2, 0.3};
  const auto s = scene::body_shape(b);
  const Eigen::Vector3d h = s.half_extents.cast<double>();
  // Uniform box: I1 ~ (h2^2 + h3^2), etc.
  const Eigen::Vector3d I(h[1] * h[1] + h[2] * h[2], h[0] * h[0] + h[2] * h[2],
                          h[0] * h[0] + h[1] * h[1]);
  EXPECT_NEAR(I[0] / I[2], 2.0 / 4.0, 1e-5);
  EXPECT_NEAR(I[1] / I[2], 3.0 / 4.0, 1e-5);
  // The box and its centre of mass fit inside the unit sphere.
  EXPECT_LT((s.centre_of_mass.cwiseAbs() + s.half_extents).norm(), 0.8f);
  // The centre of mass keeps its direction.
  EXPECT_NEAR(s.centre_of_mass.normalized().dot(b.com.normalized().cast<float>()), 1.0f, 1e-5);
}

}  // namespace
}  // namespace epviz
