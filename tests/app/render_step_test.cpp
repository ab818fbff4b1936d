// `epviz render` integrates a fixed-step method at the step the job asks for,
// as `epviz simulate` does: both binaries report the same step, steps and
// drift at the steps. And a comparison job reports each of its runs.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

nlohmann::json kovalevskaya_job(const fs::path& out, double step) {
  return {{"simulation",
           {{"case", "kovalevskaya"}, {"t_end", 20.0}, {"method", "rk4"}, {"step", step}}},
          {"width", 160},
          {"height", 120},
          {"fps", 5},
          {"duration", 3},
          {"output", {{"dir", out.string()}, {"format", "png"}}}};
}

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(test::slurp(p)); }

class RenderStep : public ::testing::TestWithParam<double> {};

TEST_P(RenderStep, MatchesSimulateWithTheSameStep) {
  const double step = GetParam();
  test::TempDir dir;
  const auto job = dir / "job.json";
  std::ofstream(job) << kovalevskaya_job(dir / "frames", step).dump();
  auto r = test::run_epviz("render " + job.string() + " --frames 14 --quiet --report-json " +
                               (dir / "render.json").string(),
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // simulate samples every step (its own output spacing, unlike the render's).
  const long steps = std::lround(20.0 / step);
  char args[256];
  std::snprintf(args, sizeof args,
                "simulate --case kovalevskaya --method rk4 --step %.17g --t-end 20 --samples %ld "
                "--report-json %s",
                step, steps, (dir / "simulate.json").c_str());
  r = test::run_epviz(args, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const auto render = read_json(dir / "render.json");
  auto simulate = read_json(dir / "simulate.json");
  if (simulate.is_array()) simulate = simulate[0];
  ASSERT_TRUE(render.contains("runs")) << render.dump(2);
  const auto& run = render["runs"][0];
  EXPECT_EQ(run["effective_step"].get<double>(), step);
  EXPECT_EQ(render["effective_step"].get<double>(), step);
  EXPECT_EQ(simulate["effective_step"].get<double>(), step);
  EXPECT_EQ(run["steps"], steps);
  EXPECT_EQ(run["steps"], simulate["steps"]);
  EXPECT_EQ(run["rhs_evals"], simulate["rhs_evals"]);
  for (const char* k : {"gamma_norm2", "area", "energy", "extra_integral"})
    EXPECT_DOUBLE_EQ(run["step_drift"][k].get<double>(), simulate["step_drift"][k].get<double>())
        << k;
  // The overlay's accuracy note is the step used.
  char note[32];
  std::snprintf(note, sizeof note, "step %.3g", step);
  EXPECT_EQ(render["accuracy"], note);
}

// 0.05 and 1.0 gave the same drifts when the render shortened every step to
// fit its sample spacing; now they are the steps' own.
INSTANTIATE_TEST_SUITE_P(Steps, RenderStep, ::testing::Values(0.05, 0.4, 1.0));

TEST(RenderStep, CoarserStepsDriftMore) {
  test::TempDir dir;
  double energy[2];
  int i = 0;
  for (double step : {0.05, 1.0}) {
    const auto job = dir / "job.json";
    std::ofstream(job) << kovalevskaya_job(dir / "frames", step).dump();
    const auto r =
        test::run_epviz("render " + job.string() + " --frames 14 --quiet --report-json " +
                            (dir / "render.json").string(),
                        dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    energy[i++] = read_json(dir / "render.json")["runs"][0]["max_relative_drift"]["energy"];
  }
  EXPECT_GT(energy[1], 1000.0 * energy[0]);
}

TEST(RenderRuns, ReportsEachRunOfAComparison) {
  test::TempDir dir;
  auto j = kovalevskaya_job(dir / "frames", 0.25);
  j["runs"] = nlohmann::json::parse(
      R"([{"label": "coarse"}, {"label": "fine", "method": "dop853", "tol": 1e-10}])");
  const auto job = dir / "job.json";
  std::ofstream(job) << j.dump();
  const auto r = test::run_epviz(
      "render " + job.string() + " --frames 14 --quiet --report-json " + (dir / "r.json").string(),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = read_json(dir / "r.json");
  ASSERT_EQ(report["runs"].size(), 2u);
  EXPECT_EQ(report["runs"][0]["label"], "coarse");
  EXPECT_EQ(report["runs"][0]["effective_step"].get<double>(), 0.25);
  EXPECT_TRUE(report["runs"][0]["tol"].is_null());
  EXPECT_EQ(report["runs"][1]["label"], "fine");
  EXPECT_EQ(report["runs"][1]["tol"].get<double>(), 1e-10);
  EXPECT_TRUE(report["runs"][1]["effective_step"].is_null());
  EXPECT_GT(report["runs"][1]["steps"].get<long>(), 0);
  EXPECT_LT(report["runs"][1]["max_relative_drift"]["energy"].get<double>(),
            report["runs"][0]["max_relative_drift"]["energy"].get<double>());
}

// The summary line names every run's method and accuracy, not the first
// run's alone: a reader of the log sees what was compared.
TEST(RenderRuns, SummaryNamesEveryRunsMethod) {
  test::TempDir dir;
  auto j = kovalevskaya_job(dir / "frames", 0.25);
  j["runs"] = nlohmann::json::parse(
      R"([{"label": "coarse"}, {"label": "fine", "method": "dop853", "tol": 1e-10},
          {"method": "gauss4", "step": 0.1}])");
  const auto job = dir / "job.json";
  std::ofstream(job) << j.dump();
  const auto r = test::run_epviz("render " + job.string() + " --frames 6 --quiet", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string summary = r.out + r.err;
  for (const char* run :
       {"run 1 rk4 step 0.25", "; run 2 dop853 tol 1e-10", "; run 3 gauss4 step 0.1"})
    EXPECT_NE(summary.find(run), std::string::npos) << run << " not in:\n" << summary;
}

TEST(RenderRuns, RefusesAnUnknownKeyInARunWithExitTwo) {
  test::TempDir dir;
  auto j = kovalevskaya_job(dir / "frames", 0.25);
  j["runs"] = nlohmann::json::parse(R"([{"label": "a"}, {"methd": "dop853"}])");
  test::expect_render_refused(dir, j.dump(), "", dir / "frames", "runs[1].methd");
}

// A gallery's grid video: every job's frames tiled side by side in one MP4.
nlohmann::json grid_gallery(const test::TempDir& dir, int tile_width, int columns) {
  for (const char* name : {"a.json", "b.json"}) {
    auto j = kovalevskaya_job(dir / "unused", 0.25);
    j["duration"] = 1;
    std::ofstream(dir / name) << j.dump();
  }
  return {{"jobs", {"a.json", "b.json"}},
          {"tile", {{"width", tile_width}, {"height", 120}, {"columns", columns}}},
          {"grid_video", true},
          {"dir", (dir / "gallery").string()}};
}

TEST(GalleryGrid, TilesEveryJobIntoOneVideo) {
  test::TempDir dir;
  if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0) GTEST_SKIP() << "no ffmpeg";
  std::ofstream(dir / "g.json") << grid_gallery(dir, 160, 2).dump();
  const auto r = test::run_epviz("render " + (dir / "g.json").string() + " --quiet", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(fs::file_size(dir / "gallery" / "grid.mp4"), 1000u);
  EXPECT_NE(r.out.find("5 frames of 2 jobs"), std::string::npos) << r.out;
}

TEST(GalleryGrid, RefusesAnOddGridBeforeAnyWork) {
  test::TempDir dir;
  std::ofstream(dir / "g.json") << grid_gallery(dir, 161, 1).dump();  // 8 + 161 pixels wide
  const auto r = test::run_epviz("render " + (dir / "g.json").string(), dir);
  test::expect_bad_input(r, "grid_video");
  EXPECT_FALSE(fs::exists(dir / "gallery"));
}

}  // namespace
}  // namespace epviz
