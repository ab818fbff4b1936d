// Comparison scenes (several runs in one picture) and the pixel-true horizon
// of each run, estimated against its shadow run.
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "physics/cases.hpp"
#include "scene/frame_source.hpp"
#include "sim/simulate.hpp"
#include "true_error.hpp"

namespace epviz {
namespace {

sim::RunSpec preset(physics::Case c, sim::Method m, double t_end) {
  return sim::preset_run(c, m, sim::Formulation::direct, t_end, 1);
}

scene::SceneSettings small_settings() {
  scene::SceneSettings s;
  s.width = 640, s.height = 360, s.fps = 10, s.duration = 3;
  return s;
}

TEST(ComparisonPlan, RunsShareTheFrameTimesAndKeepTheirOwnAccuracy) {
  auto s = small_settings();
  auto fixed = preset(physics::Case::kovalevskaya, sim::Method::rk4, 99.0);  // t_end: the first's
  fixed.step = 0.25;
  const auto plan = scene::plan_scene(
      {{preset(physics::Case::kovalevskaya, sim::Method::dop853, 20.0), "ref", false, true},
       {fixed, "coarse", false, true}},
      s);
  ASSERT_TRUE(plan.comparison());
  ASSERT_EQ(plan.others.size(), 1u);
  EXPECT_EQ(plan.label, "ref");
  EXPECT_EQ(plan.others[0].label, "coarse");
  EXPECT_EQ(plan.others[0].run.t_end, 20.0);
  EXPECT_EQ(plan.others[0].run.samples, plan.run.samples);
  EXPECT_EQ(plan.others[0].run.step, 0.25);
  EXPECT_EQ(plan.others[0].accuracy_note, "step 0.25");
  EXPECT_NE(plan.accuracy_note.find("(auto)"), std::string::npos);
  // The separation chart takes room under the plane.
  ASSERT_TRUE(plan.layout.chart_area);
  EXPECT_GE(plan.layout.chart_area->y, plan.layout.plot_area->bottom());
  const auto single = scene::plan_scene(plan.run, s);
  EXPECT_FALSE(single.comparison());
  EXPECT_FALSE(single.layout.chart_area);
}

TEST(ComparisonFrames, IdenticalRunsCoincideAndDifferentOnesPart) {
  auto s = small_settings();
  const auto ref = preset(physics::Case::kovalevskaya, sim::Method::dop853, 20.0);
  auto coarse = preset(physics::Case::kovalevskaya, sim::Method::rk4, 20.0);
  coarse.step = 0.5;
  const auto plan = scene::plan_scene(
      {{ref, "a", false, true}, {ref, "b", false, true}, {coarse, "", false, true}}, s);
  scene::FrameSource src(plan, s);
  const auto f = src.frame(src.frame_count() - 1);
  ASSERT_TRUE(f.comparison);
  const auto& c = *f.comparison;
  ASSERT_EQ(c.others.size(), 2u);
  ASSERT_EQ(c.labels.size(), 3u);
  EXPECT_EQ(c.labels[2], "rk4, step 0.5");
  EXPECT_NE(c.colours[0], c.colours[1]);
  // The identical run: the same trail, point for point, and no separation.
  const auto& same = c.others[0];
  ASSERT_EQ(same.trail.size(), f.trail.size());
  for (std::size_t i = 0; i < f.trail.size(); ++i) EXPECT_EQ(same.trail[i].p, f.trail[i].p);
  ASSERT_FALSE(same.separation.empty());
  for (const auto& p : same.separation) EXPECT_EQ(p.y(), 0.0f);
  // The coarse run parts from the first, more and more.
  const auto& sep = c.others[1].separation;
  EXPECT_GT(sep.back().y(), 1e-3f);
  EXPECT_LT(sep.front().y(), sep.back().y());
  // One drift row per run: its largest drift among |γ|², C₀, C₁ and K, named.
  EXPECT_EQ(int(f.overlay.drifts.size()), scene::overlay_drift_rows(std::vector{ref, ref, coarse}));
  ASSERT_EQ(f.overlay.drifts.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const auto& d = src.run(i).drifts().output;
    const double largest = std::max({d.gamma_norm2, d.area, d.energy, d.extra.value_or(0.0)});
    const auto& [name, value] = f.overlay.drifts[std::size_t(i)];
    EXPECT_EQ(value, largest) << name;
    const std::string expected = largest == d.gamma_norm2 ? "|γ|²"
                                 : largest == d.area      ? "C₀"
                                 : largest == d.energy    ? "C₁"
                                                          : "K";
    EXPECT_EQ(name, std::to_string(i + 1) + ": " + expected);
  }
}

TEST(ComparisonFrames, ASingleRunHasNoComparison) {
  auto s = small_settings();
  scene::FrameSource src(
      scene::plan_scene(preset(physics::Case::lagrange, sim::Method::dop853, 5.0), s), s);
  EXPECT_FALSE(src.frame(5).comparison);
}

// The frames of a 1280x720 job to its last one; the first run's track.
struct Rendered {
  scene::ScenePlan plan;
  std::optional<double> until;
  double max_error_px = 0.0;
};
Rendered render_to_end(const sim::RunSpec& run) {
  scene::SceneSettings s;
  s.width = 1280, s.height = 720, s.fps = 10, s.duration = 6;
  Rendered r;
  r.plan = scene::plan_scene(run, s);
  scene::FrameSource src(r.plan, s);
  const auto f = src.frame(src.frame_count() - 1);
  r.until = src.run(0).pixel_true_until();
  r.max_error_px = src.run(0).max_error_px();
  EXPECT_EQ(f.pixel_true_until, r.until);
  return r;
}

using testing::true_error_px;

// Long enough that no tolerance keeps the generic body's picture true to the end.
constexpr double kPastEveryHorizon = 300.0;

TEST(PixelTrue, AChaoticRunIsTrueUntilItsHorizonAndSaysSo) {
  const auto r =
      render_to_end(preset(physics::Case::generic, sim::Method::dop853, kPastEveryHorizon));
  ASSERT_TRUE(r.until) << "max error " << r.max_error_px << " px";
  EXPECT_LT(*r.until, kPastEveryHorizon);
  EXPECT_GT(*r.until, 1.0);
  // "auto" went as tight as it goes: the horizon is as late as the numbers allow.
  EXPECT_EQ(r.plan.run.tol, scene::kTightestAutoTolerance);
  // Independently: the auto-tolerance run against DOP853 at tol 1e-13 stays
  // within half a pixel up to the horizon.
  double worst_before = 0.0, worst_after = 0.0;
  for (const auto& [t, e] : true_error_px(r.plan)) {
    double& worst = t <= *r.until ? worst_before : worst_after;
    worst = std::max(worst, e);
  }
  EXPECT_LT(worst_before, 0.5);
  // And the horizon is not needlessly early: the true error does pass half a pixel.
  EXPECT_GT(worst_after, 0.5);
}

TEST(PixelTrue, AutoTightensAChaoticRunUntilItsPictureIsTrueToTheEnd) {
  // At the resolution's tolerance the generic body's picture parts from the
  // truth by t = 60 (chaos); a tighter tolerance keeps it true to the end.
  const auto run = preset(physics::Case::generic, sim::Method::dop853, 60.0);
  scene::SceneSettings s;
  s.width = 1280, s.height = 720, s.fps = 10, s.duration = 6;
  const auto resolution = scene::plan_scene(run, s, scene::Horizon::none);
  const auto r = render_to_end(run);
  EXPECT_LT(r.plan.run.tol, resolution.run.tol);
  EXPECT_NE(r.plan.accuracy_note.find("tightened"), std::string::npos) << r.plan.accuracy_note;
  EXPECT_FALSE(r.until) << "until " << *r.until;
  {
    // The resolution's tolerance alone would not have been true to the end.
    scene::FrameSource src(resolution, s);
    src.frame(src.frame_count() - 1);
    EXPECT_TRUE(src.run(0).pixel_true_until());
  }
  // Independently: the drawn run against DOP853 at tol 1e-13, over the whole run.
  double worst = 0.0;
  for (const auto& [t, e] : true_error_px(r.plan)) worst = std::max(worst, e);
  EXPECT_LT(worst, 0.5);
}

TEST(PixelTrue, AnIntegrableRunIsTrueThroughout) {
  const auto r = render_to_end(preset(physics::Case::kovalevskaya, sim::Method::dop853, 40.0));
  EXPECT_FALSE(r.until) << "until " << *r.until;
  EXPECT_LT(r.max_error_px, 0.5);
  EXPECT_GT(r.max_error_px, 0.0);  // the shadow did measure
}

TEST(PixelTrue, ACoarseFixedStepIsCaughtByItsHalfStepShadow) {
  auto run = preset(physics::Case::kovalevskaya, sim::Method::rk4, 40.0);
  run.step = 0.5;
  const auto r = render_to_end(run);
  ASSERT_TRUE(r.until);
  EXPECT_LT(*r.until, 40.0);
}

}  // namespace
}  // namespace epviz
