// `epviz render`: job errors, PNG sequences, resume, video and galleries,
// through the real binary.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"
#include "support/render_job.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

// Six frames.
nlohmann::json small_job(const fs::path& out) { return test::small_render_job(out); }

// The small job drawing into {dir}/frames, changed by `edit`, and run with `args`.
test::RefusedCase bad_job(const std::string& name, const std::function<void(nlohmann::json&)>& edit,
                          const std::string& args, const std::string& must_name) {
  auto j = small_job("{dir}/frames");
  edit(j);
  return {name, args, must_name, j.dump(2)};
}

class RenderRejects : public ::testing::TestWithParam<test::RefusedCase> {};

TEST_P(RenderRejects, WithOneLineExitTwoAndNoOutput) {
  const auto& c = GetParam();
  test::TempDir dir;
  test::expect_render_refused(dir, dir.expand(c.job), c.args, dir / "frames", c.must_name);
}

INSTANTIATE_TEST_SUITE_P(
    BadInputs, RenderRejects,
    ::testing::Values(
        bad_job(
            "unknown_key", [](auto& j) { j["colour"] = "red"; }, "",
            "job.json: key 'colour': unknown key"),
        bad_job(
            "unknown_nested_key",
            [](auto& j) {
              j["layers"] = {{"bodies", true}};
            },
            "", "key 'layers.bodies': unknown key"),
        bad_job(
            "bad_view", [](auto& j) { j["view"] = "top"; }, "",
            "key 'view': 'top' is not one of: body, space"),
        bad_job(
            "bad_colour",
            [](auto& j) {
              j["colours"] = {{"body", "orange"}};
            },
            "", "key 'colours.body': expected a colour"),
        bad_job(
            "bad_theme", [](auto& j) { j["theme"] = "sepia"; }, "",
            "key 'theme': 'sepia' is not one of: dark, light"),
        bad_job(
            "missing_simulation", [](auto& j) { j.erase("simulation"); }, "",
            "key 'simulation': missing"),
        bad_job(
            "bad_case", [](auto& j) { j["simulation"]["case"] = "top"; }, "",
            "key 'simulation.case': unknown case"),
        bad_job(
            "bad_tol", [](auto& j) { j["simulation"]["tol"] = "fine"; }, "",
            "key 'simulation.tol': expected a number"),
        bad_job(
            "space_needs_spinor",
            [](auto& j) {
              j["view"] = "space";
              j["simulation"]["formulation"] = "direct";
            },
            "", "needs its attitude"),
        bad_job(
            "odd_video_size",
            [](auto& j) {
              j["output"]["format"] = "mp4";
              j["width"] = 161;
            },
            "", "even width and height"),
        bad_job(
            "bad_format_option", [](auto&) {}, "--format avi", "--format: unknown format 'avi'"),
        bad_job(
            "frames_out_of_range", [](auto&) {}, "--frames 3:99", "--frames"),
        bad_job(
            "unknown_gl", [](auto&) {}, "--gl vulkan", "unknown GL backend 'vulkan'"),
        bad_job(
            "resume_video", [](auto& j) { j["output"]["format"] = "mp4"; }, "--resume",
            "--resume: applies to PNG"),
        bad_job(
            "all_layers_off",
            [](auto& j) {
              j["layers"] = {
                  {"body", false}, {"sphere", false}, {"riccati", false}, {"overlay", false}};
            },
            "", "nothing to draw")),
    test::case_name);

TEST(Render, MissingJobFileIsNamed) {
  test::TempDir dir;
  test::expect_bad_input(test::run_epviz("render " + (dir / "none.json").string(), dir),
                         "none.json: cannot open");
}

TEST(Render, PngSequenceWithZeroPaddedNamesAndResume) {
  test::TempDir dir;
  const auto job = dir.write("job.json", small_job(dir / "frames").dump(2));
  const auto report = dir / "report.json";
  auto r = test::run_epviz("render " + job.string() + " --report-json " + report.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (int i = 0; i < 6; ++i) {
    const auto f = dir / "frames" / ("frame_000" + std::to_string(i) + ".png");
    EXPECT_TRUE(fs::exists(f)) << f;
    EXPECT_GT(fs::file_size(f), 1000u) << f;
  }
  EXPECT_FALSE(fs::exists(dir / "frames" / "frame_0006.png"));
  auto rep = nlohmann::json::parse(test::slurp(report));
  EXPECT_EQ(rep["frames_drawn"], 6);
  EXPECT_NE(rep["accuracy"].get<std::string>().find("auto"), std::string::npos);

  // Remove one frame and damage another: --resume redraws exactly those two.
  fs::remove(dir / "frames" / "frame_0002.png");
  std::ofstream(dir / "frames" / "frame_0004.png", std::ios::trunc) << "not a png";
  r = test::run_epviz("render " + job.string() + " --resume --report-json " + report.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  rep = nlohmann::json::parse(test::slurp(report));
  EXPECT_EQ(rep["frames_drawn"], 2);
  EXPECT_EQ(rep["frames_skipped"], 4);
  EXPECT_GT(fs::file_size(dir / "frames" / "frame_0004.png"), 1000u);
}

TEST(Render, FrameRangeDrawsOnlyThoseFrames) {
  test::TempDir dir;
  const auto job = dir.write("job.json", small_job(dir / "frames").dump(2));
  const auto r = test::run_epviz("render " + job.string() + " --frames 2:3", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "frames" / "frame_0001.png"));
  EXPECT_TRUE(fs::exists(dir / "frames" / "frame_0002.png"));
  EXPECT_TRUE(fs::exists(dir / "frames" / "frame_0003.png"));
  EXPECT_FALSE(fs::exists(dir / "frames" / "frame_0004.png"));
}

TEST(Render, Mp4IsPlayableWithTheExpectedFramesAndSize) {
  test::TempDir dir;
  auto j = small_job(dir / "video");
  j["output"]["format"] = "mp4";
  j["output"]["name"] = "clip";
  const auto job = dir.write("job.json", j.dump(2));
  const auto r = test::run_epviz("render " + job.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto mp4 = dir / "video" / "clip.mp4";
  ASSERT_TRUE(fs::exists(mp4));
  const std::string probe =
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=nb_read_frames,width,height -of json " +
      mp4.string() + " > " + (dir / "probe.json").string();
  ASSERT_EQ(std::system(probe.c_str()), 0);
  const auto p = nlohmann::json::parse(test::slurp(dir / "probe.json"));
  EXPECT_EQ(p["streams"][0]["nb_read_frames"], "6");
  EXPECT_EQ(p["streams"][0]["width"], 160);
  EXPECT_EQ(p["streams"][0]["height"], 120);
}

// GIF takes any size (no yuv420p): an odd-sized GIF is drawn at exactly that size.
TEST(Render, OddSizedGifIsDrawnAtThatSize) {
  if (std::system("command -v ffprobe >/dev/null 2>&1") != 0) GTEST_SKIP() << "no ffprobe";
  test::TempDir dir;
  auto j = small_job(dir / "video");
  j["output"]["format"] = "gif";
  j["output"]["name"] = "clip";
  j["width"] = 161;
  j["height"] = 121;
  const auto r = test::run_epviz("render " + dir.write("job.json", j.dump(2)).string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto gif = dir / "video" / "clip.gif";
  const std::string probe =
      "ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of json " +
      gif.string() + " > " + (dir / "probe.json").string();
  ASSERT_EQ(std::system(probe.c_str()), 0);
  const auto p = nlohmann::json::parse(test::slurp(dir / "probe.json"));
  EXPECT_EQ(p["streams"][0]["width"], 161);
  EXPECT_EQ(p["streams"][0]["height"], 121);
}

TEST(Render, NumericalFailureStopsWithTimeAndMethodAndKeepsNoVideo) {
  // A steady rotation carries gamma exactly through the south pole; the north
  // Riccati chart alone cannot follow it.
  test::TempDir dir;
  auto j = small_job(dir / "video");
  j["simulation"] = {{"case", "euler"},          {"omega", {1, 0, 0}},    {"gamma", {0, 0.6, 0.8}},
                     {"formulation", "riccati"}, {"chart_switch", false}, {"t_end", 6.0}};
  j["output"]["format"] = "mp4";
  j["output"]["name"] = "clip";
  const auto r = test::run_epviz("render " + dir.write("job.json", j.dump(2)).string(), dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("dop853 failed at t = "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "video" / "clip.mp4"));
  for (const auto& e : fs::directory_iterator(dir / "video"))
    ADD_FAILURE() << "left behind: " << e.path();
}

TEST(Render, BenchFiguresJobRunsTheStudyAndDrawsItsCharts) {
  test::TempDir dir;
  const nlohmann::json job = {{"bench", {{"quick", true}, {"cases", {"kovalevskaya"}}}},
                              {"dir", (dir / "figures").string()}};
  const auto r = test::run_epviz("render " + dir.write("bench.json", job.dump(2)).string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"bench.json", "work_precision_kovalevskaya.png", "stability.png"})
    EXPECT_TRUE(fs::exists(dir / "figures" / f)) << f;

  const nlohmann::json typo = {{"bench", {{"quik", true}}}};
  const auto bad = test::run_epviz("render " + dir.write("typo.json", typo.dump(2)).string(), dir);
  test::expect_bad_input(bad, "key 'bench.quik': unknown key");
}

TEST(Render, GalleryTilesOneStillPerJob) {
  test::TempDir dir;
  dir.write("a.json", small_job(dir / "unused").dump(2));
  auto b = small_job(dir / "unused");
  b["simulation"]["case"] = "kovalevskaya";
  dir.write("b.json", b.dump(2));
  const nlohmann::json gallery = {{"jobs", {"a.json", "b.json"}},
                                  {"tile", {{"width", 160}, {"height", 120}, {"columns", 2}}},
                                  {"videos", "none"},
                                  {"dir", (dir / "gallery").string()}};
  const auto g = dir.write("gallery.json", gallery.dump(2));
  const auto r = test::run_epviz("render " + g.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "gallery" / "gallery.png"));
  EXPECT_FALSE(fs::exists(dir / "unused"));
}

}  // namespace
}  // namespace epviz

namespace epviz {
namespace {

// The width and height of a video's first stream, by ffprobe.
std::pair<int, int> video_size(const test::TempDir& dir, const fs::path& video) {
  const std::string probe =
      "ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of json " +
      video.string() + " > " + (dir / "probe.json").string();
  if (std::system(probe.c_str()) != 0) return {0, 0};
  const auto p = nlohmann::json::parse(test::slurp(dir / "probe.json"));
  return {p["streams"][0]["width"].get<int>(), p["streams"][0]["height"].get<int>()};
}

// A gallery's videos come out at the size each job asks for; its tiles at the
// tile size. --width and --height size both.
TEST(Render, GalleryVideosAreAtTheirJobsSize) {
  if (std::system("command -v ffprobe >/dev/null 2>&1") != 0) GTEST_SKIP() << "no ffprobe";
  test::TempDir dir;
  auto a = small_job(dir / "unused");
  a["width"] = 200;
  a["height"] = 150;
  a["duration"] = 1;
  dir.write("a.json", a.dump(2));
  auto b = a;
  b["width"] = 240;
  b["height"] = 136;
  dir.write("b.json", b.dump(2));
  const nlohmann::json gallery = {{"jobs", {"a.json", "b.json"}},
                                  {"tile", {{"width", 160}, {"height", 120}, {"columns", 2}}},
                                  {"videos", "mp4"},
                                  {"dir", (dir / "gallery").string()}};
  const auto g = dir.write("gallery.json", gallery.dump(2));
  auto r = test::run_epviz("render " + g.string() + " --quiet", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(video_size(dir, dir / "gallery" / "a.mp4"), std::make_pair(200, 150));
  EXPECT_EQ(video_size(dir, dir / "gallery" / "b.mp4"), std::make_pair(240, 136));
  // The summary line says so too.
  EXPECT_NE((r.out + r.err).find("200x150"), std::string::npos) << r.out << r.err;
  r = test::run_epviz("render " + g.string() + " --quiet --width 96 --height 64", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(video_size(dir, dir / "gallery" / "a.mp4"), std::make_pair(96, 64));
}

}  // namespace
}  // namespace epviz
