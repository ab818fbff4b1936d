// Runs compared in the browser: added and removed from the panel, drawn as a
// render of a job with "runs" draws them (legend rows, |delta gamma| chart),
// and a run that fails named in its legend row and in the report.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "io/data_dir.hpp"
#include "job/job_file.hpp"
#include "job/job_plan.hpp"
#include "live/job_file.hpp"
#include "scene/run_palette.hpp"
#include "session_driver.hpp"
#include "support/temp_dir.hpp"

namespace epviz::live::testing {
namespace {

constexpr double kNudge = 1e-6;  // the panel's default

// Whether some pixel of `r` in the picture is within `tolerance` of `c` in every channel.
bool has_colour(const render::RgbaImage& image, const scene::Rect& r, const scene::Rgba& c,
                int tolerance = 12) {
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x) {
      const std::uint8_t* p = &image.pixels[(std::size_t(y) * image.width + x) * 4];
      bool near = true;
      for (int k = 0; k < 3; ++k)
        near &= std::abs(int(p[k]) - int(std::lround(c[k] * 255.0f))) <= tolerance;
      if (near) return true;
    }
  return false;
}

// Opens the runs section and adds an RK4 run and a nudged one, as a user would.
void add_two_runs(SessionDriver& d) {
  d.click("header:runs");
  d.click("new_method");
  d.click("new_method:rk4");
  d.click("add_run");
  d.click("add_nudged");
}

TEST(LiveCompare, ThreeRunsFromThePanelAreDrawnWithTheirLegendAndSeparationChart) {
  SessionDriver d(starting_with(physics::Case::generic), 1280, 720);
  add_two_runs(d);
  const LiveScene& scene = d.session->scene();
  ASSERT_EQ(scene.run_count(), 3);
  d.click("play");
  d.frames(40);
  d.click("play");
  ASSERT_GT(scene.time(), 1.0);

  // The frame carries the three runs: two beyond the first, each with its separation.
  const auto& c = scene.frame().comparison;
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->labels.size(), 3u);
  ASSERT_EQ(c->others.size(), 2u);
  EXPECT_EQ(c->labels[1].rfind("rk4, step", 0), 0u) << c->labels[1];
  // As drawn: the nudge in print (paint/frame_typesetting.hpp).
  EXPECT_EQ(c->labels[2].rfind("nudged 10⁻⁶: dop853", 0), 0u) << c->labels[2];
  for (const auto& other : c->others) EXPECT_FALSE(other.separation.empty());
  // The nudged run starts |delta gamma| = 2 sin(nudge / 2) from the first
  // (one sample later it has not moved away yet).
  const auto& nudged = c->others[1].separation;
  EXPECT_NEAR(nudged.front().y(), 2.0 * std::sin(kNudge / 2.0), 1e-2 * kNudge);
  // The chart's time axis ends now.
  EXPECT_DOUBLE_EQ(c->t_end, scene.time());
  // ... and has a span before anything was played (a step's worth: 1/30 s at the speed).
  const LiveScene fresh(scene.setup());
  ASSERT_TRUE(fresh.frame().comparison.has_value());
  EXPECT_DOUBLE_EQ(fresh.frame().comparison->t_end, fresh.setup().speed / 30.0);

  // The picture: a legend row per run, and each further run's line in the chart.
  const auto& image = d.session->render();
  int rows = 0;
  for (const auto& l : d.session->annotations().legend)
    for (int i = 0; i < 3; ++i)
      rows += l.text == std::to_string(i + 1) + "  " + c->labels[std::size_t(i)];
  EXPECT_EQ(rows, 3);
  const auto& chart = d.session->layout().chart_area;
  ASSERT_TRUE(chart.has_value());
  for (int i = 1; i < 3; ++i)
    EXPECT_TRUE(has_colour(image, *chart, scene::run_colour(i, false))) << "run " << i + 1;

  // Removing a run leaves the others.
  d.click("remove:2");
  ASSERT_EQ(scene.run_count(), 2);
  ASSERT_EQ(scene.setup().compared.size(), 1u);
  EXPECT_EQ(scene.setup().compared.front().nudge, kNudge);
}

TEST(LiveCompare, NoMoreRunsThanAJobHolds) {
  SessionDriver d(starting_with(physics::Case::lagrange), 1280, 720);
  d.click("header:case");  // closed: room for six legend rows
  d.click("header:runs");
  for (int i = 0; i < kMaxLiveRuns + 2; ++i) d.click("add_nudged");
  EXPECT_EQ(d.session->scene().run_count(), kMaxLiveRuns);
}

TEST(LiveCompare, ARunThatFailsIsNamedInItsLegendRowAndTheReport) {
  LiveSetup s = preset_setup(physics::Case::generic);
  s.speed = 1000.0;
  // RK4 steps of 2 are far beyond its stability for this body (samples 1000/240 apart).
  s.compared.push_back(with_method(sim::Method::rk4, 2.0, 0.0));
  LiveScene scene(s);
  scene.set_playing(true);
  for (int i = 0; i < 120 && !scene.failure(); ++i) scene.step();
  ASSERT_TRUE(scene.failure().has_value()) << "still running at t = " << scene.time();
  EXPECT_FALSE(scene.playing());

  // The same RK4 run alone stops with the same report.
  LiveSetup alone = s;
  alone.compared.clear();
  alone.run.method = sim::Method::rk4;
  alone.run.step = 2.0;
  LiveScene single(alone);
  single.set_playing(true);
  for (int i = 0; i < 120 && !single.failure(); ++i) single.step();
  ASSERT_TRUE(single.failure().has_value());
  EXPECT_EQ(*scene.failure(), "run 2: " + *single.failure());

  // Its legend row says so; the first run's does not.
  const auto& c = scene.frame().comparison;
  ASSERT_TRUE(c.has_value());
  EXPECT_NE(c->labels[1].find(" - failed at t = "), std::string::npos) << c->labels[1];
  EXPECT_EQ(c->labels[0].find("failed"), std::string::npos) << c->labels[0];
  EXPECT_TRUE(std::isfinite(c->others[0].current.norm()));
}

TEST(LiveCompare, TheSeparationChartKeepsABoundedNumberOfPointsAndTheLargest) {
  LiveSetup s = preset_setup(physics::Case::generic);
  s.speed = 1000.0;  // about 8 samples a frame
  s.compared.push_back(nudged_by(1e-3));
  LiveScene scene(s);
  // The largest separation so far, from each frame's newest point (never thinned).
  float largest = 0.0f;
  for (int i = 0; i < 400; ++i) {
    scene.step();
    ASSERT_FALSE(scene.failure()) << *scene.failure();
    largest = std::max(largest, scene.frame().comparison->others[0].separation.back().y());
  }
  const auto& sep = scene.frame().comparison->others[0].separation;
  EXPECT_LE(sep.size(), LiveScene::kChartPoints);
  EXPECT_GT(sep.size(), LiveScene::kChartPoints / 2);
  float shown = 0.0f;
  for (std::size_t i = 1; i < sep.size(); ++i) {
    EXPECT_GT(sep[i].x(), sep[i - 1].x()) << i;
    shown = std::max(shown, sep[i].y());
  }
  EXPECT_GE(shown, largest);
  EXPECT_NEAR(sep.back().x(), scene.time(), 0.01 * scene.time());
}

TEST(LiveCompare, AServedJobWithRunsIsComparedAndSavedWithItsRuns) {
  // Three formulations, one with its chart switch: runs a job gives in full.
  const auto file = io::find_data_path("render_jobs/compare_formulations.json");
  ASSERT_FALSE(file.empty());
  const LiveSetup s = setup_from_job_file(file);
  ASSERT_EQ(s.compared.size(), 2u);
  LiveScene scene(s);
  scene.step();
  const auto& c = scene.frame().comparison;
  ASSERT_TRUE(c.has_value());
  ASSERT_EQ(c->labels.size(), 3u);
  EXPECT_EQ(c->labels[0].rfind("(omega, gamma): dop853", 0), 0u) << c->labels[0];
  EXPECT_EQ(c->labels[1].rfind("(omega, a, b), chart switch: dop853", 0), 0u) << c->labels[1];
  EXPECT_EQ(c->labels[2].rfind("(omega, spinor): dop853", 0), 0u) << c->labels[2];

  // Saved, the job reads back (through the job reader) as the same runs.
  test::TempDir dir;
  const auto saved = dir / "saved.json";
  std::ofstream(saved) << render_job_json(s, "saved", {scene.time(), scene.tolerance()});
  const auto loaded = job::load_job_file(saved);
  ASSERT_TRUE(loaded.single.has_value());
  const auto original = job::run_requests(*job::load_job_file(file).single);
  const auto again = job::run_requests(*loaded.single);
  ASSERT_EQ(again.size(), original.size());
  for (std::size_t i = 0; i < again.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(again[i].label, original[i].label);
    EXPECT_EQ(again[i].run.formulation, original[i].run.formulation);
    EXPECT_EQ(again[i].run.chart_switch, original[i].run.chart_switch);
    EXPECT_EQ(again[i].run.method, original[i].run.method);
    EXPECT_EQ(again[i].run.initial.gamma, original[i].run.initial.gamma);
    EXPECT_EQ(again[i].run.body.inertia, original[i].run.body.inertia);
    // The automatic tolerance as the number the live scene used.
    EXPECT_EQ(again[i].run.tol, scene.tolerance());
  }
}

TEST(LiveCompare, AnotherCaseKeepsTheRunsRelativeToTheFirstAndDropsThoseAJobGave) {
  SessionOptions o;
  o.initial = setup_from_job_file(io::find_data_path("render_jobs/compare_methods.json"));
  ASSERT_EQ(o.initial.compared.size(), 2u);
  o.initial.compared.push_back(nudged_by(1e-3));
  SessionDriver d(o);
  d.click("case");
  d.click("case:lagrange");
  const LiveSetup& s = d.session->scene().setup();
  ASSERT_EQ(s.run.case_id, physics::Case::lagrange);
  ASSERT_EQ(s.compared.size(), 1u);
  EXPECT_EQ(s.compared.front().nudge, 1e-3);
  EXPECT_EQ(d.session->scene().run_count(), 2);
}

}  // namespace
}  // namespace epviz::live::testing
