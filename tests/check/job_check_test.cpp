// check::JobChecker on goldens in a temporary directory, without GL: frames
// come in as images, results, report images and goldens come out.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "check/golden_record.hpp"
#include "check/job_check.hpp"
#include "io/fnv1a.hpp"
#include "io/png_reader.hpp"
#include "support/cli.hpp"
#include "test_images.hpp"

namespace epviz::check {
namespace {

namespace fs = std::filesystem;

class JobCheck : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream(dir_ / "kov.json") << "{\"a job\": 1}\n";
    job_.shown = "jobs/kov.json";
    job_.job_file = dir_ / "kov.json";
    job_.golden_dir = dir_ / "golden" / "kov";
    job_.frame_count = 270;
    job_.frames = {0, 134, 269};
    job_.width = 40;
    job_.height = 30;
  }

  CheckSettings settings(fs::path report = {}) const {
    CheckSettings s;
    s.report_dir = std::move(report);
    s.environment = {"llvmpipe (LLVM 15)", "4.5 Mesa 22.3.6", "builtin", ""};
    s.epviz_version = "9.8.7";
    s.update_command = [](const GoldenJob& job, const std::vector<int>& frames) {
      std::string list;
      for (const int f : frames) {
        if (!list.empty()) list += ',';
        list += std::to_string(f);
      }
      return "update " + job.shown + " " + list;
    };
    return s;
  }

  // Three frames: a disc, a flat frame and the disc again.
  std::vector<TestImage> frames() const {
    return {disc_image(40, 30), flat_image(40, 30, 9, 9, 9), disc_image(40, 30)};
  }
  static std::vector<ImageView> views(const std::vector<TestImage>& images) {
    std::vector<ImageView> v;
    for (const auto& im : images) v.push_back(im.view());
    return v;
  }

  test::TempDir dir_;
  GoldenJob job_;
};

TEST(GoldenDir, NextToTheJobOrUnderTheGivenRoot) {
  EXPECT_EQ(golden_dir_of("jobs/kov.json", ""), fs::path("jobs/golden/kov"));
  EXPECT_EQ(golden_dir_of("kov.json", ""), fs::path("golden/kov"));
  EXPECT_EQ(golden_dir_of("jobs/kov.json", "ci/goldens"), fs::path("ci/goldens/kov"));
}

TEST_F(JobCheck, UpdateWritesEveryFrameAndGoldenJson) {
  const auto images = frames();
  const auto out = JobChecker(settings()).update(job_, views(images), std::nullopt);
  EXPECT_EQ(out.goldens_written, 3);
  ASSERT_EQ(out.lines.size(), 3u);
  EXPECT_EQ(out.lines[1],
            "UPDATED jobs/kov.json frame 134: " + (job_.golden_dir / "frame_0134.png").string());
  EXPECT_TRUE(out.results.empty());
  int k = 0;
  for (const char* name : {"frame_0000.png", "frame_0134.png", "frame_0269.png"}) {
    const auto png = io::read_png_rgba(job_.golden_dir / name);
    ASSERT_TRUE(png) << name;
    EXPECT_EQ(png->rgba, images[k++].rgba) << name;
  }
  // golden.json, read by an independent JSON parser.
  const auto rec = nlohmann::json::parse(test::slurp(job_.golden_dir / "golden.json"));
  EXPECT_EQ(rec["epviz_version"], "9.8.7");
  EXPECT_EQ(rec["gl_renderer"], "llvmpipe (LLVM 15)");
  EXPECT_EQ(rec["gl_version"], "4.5 Mesa 22.3.6");
  EXPECT_EQ(rec["job_file"], "kov.json");
  char hash[40];
  std::snprintf(hash, sizeof hash, "fnv1a64:%016llx",
                static_cast<unsigned long long>(io::fnv1a64("{\"a job\": 1}\n")));
  EXPECT_EQ(rec["job_hash"], hash);
  EXPECT_EQ(rec["frames"], nlohmann::json({0, 134, 269}));
  EXPECT_EQ(rec["width"], 40);
  EXPECT_EQ(rec["height"], 30);
}

TEST_F(JobCheck, UpdateKeepsEarlierFramesWhoseFilesAreThere) {
  const auto images = frames();
  JobChecker checker(settings());
  checker.update(job_, views(images), std::nullopt);
  fs::remove(job_.golden_dir / "frame_0269.png");
  job_.frames = {7};
  checker.update(job_, std::vector<ImageView>{images[0].view()}, std::nullopt);
  const auto rec = read_golden_record(job_.golden_dir / "golden.json");
  ASSERT_TRUE(rec);
  EXPECT_EQ(rec->frames, (std::vector<int>{0, 7, 134}));
}

TEST_F(JobCheck, UpdateAfterANumericalFailureWritesNothing) {
  const auto images = frames();
  const auto out = JobChecker(settings())
                       .update(job_, std::vector<ImageView>{images[0].view()},
                               std::string("dop853 failed at t = 2"));
  EXPECT_EQ(out.goldens_written, 0);
  ASSERT_EQ(out.results.size(), 1u);
  EXPECT_EQ(out.results[0].line(),
            "FAIL jobs/kov.json frame 134: numerical failure, no goldens written: dop853 failed "
            "at t = 2");
  EXPECT_FALSE(fs::exists(job_.golden_dir));
}

TEST_F(JobCheck, FramesEqualToTheirGoldensPass) {
  const auto images = frames();
  JobChecker checker(settings());
  checker.update(job_, views(images), std::nullopt);
  const auto out = checker.compare(job_, 0, views(images), std::nullopt);
  ASSERT_EQ(out.results.size(), 3u);
  for (const auto& r : out.results) EXPECT_TRUE(r.passed) << r.line();
  EXPECT_EQ(out.results[2].line(), "PASS jobs/kov.json frame 269: 0 % pixels differ (limit 0.5 %)");
  EXPECT_TRUE(out.warnings.empty());
}

TEST_F(JobCheck, AChangedFrameFailsWithGoldenActualAndDiffInTheReport) {
  auto images = frames();
  JobChecker(settings()).update(job_, views(images), std::nullopt);
  for (int x = 0; x < 40; ++x) images[1].pixel(x, 0)[0] = 200;  // one row of 30: 3.33 %
  const auto report = dir_ / "report";
  fs::create_directories(report);
  const auto out = JobChecker(settings(report)).compare(job_, 4, views(images), std::nullopt);
  EXPECT_TRUE(out.results[0].passed);
  const auto& r = out.results[1];
  EXPECT_EQ(r.line(),
            "FAIL jobs/kov.json frame 134: 3.33 % pixels differ (limit 0.5 %); rendering changed, "
            "the job did not (same GL renderer, GL version and font as the goldens)");
  EXPECT_EQ(r.golden_image, "5_kov_frame_0134.golden.png");
  EXPECT_EQ(r.actual_image, "5_kov_frame_0134.actual.png");
  EXPECT_EQ(r.diff_image, "5_kov_frame_0134.diff.png");
  const auto diff = io::read_png_rgba(report / r.diff_image);
  ASSERT_TRUE(diff);
  EXPECT_EQ(diff->rgba[0], 255);  // red: 128 + the difference (191), at most 255
  EXPECT_EQ(diff->rgba[1], 0);
  EXPECT_EQ(diff->rgba[40 * 4], 2);  // the next row: the golden's grey (9) at a quarter
  EXPECT_EQ(io::read_png_rgba(report / r.actual_image)->rgba, images[1].rgba);
  EXPECT_EQ(io::read_png_rgba(report / r.golden_image)->rgba, frames()[1].rgba);
  // Passing frames leave no images.
  EXPECT_EQ(std::distance(fs::directory_iterator(report), {}), 3);
}

TEST_F(JobCheck, MissingGoldensNameTheCommandThatCreatesThem) {
  const auto images = frames();
  job_.frames = {0, 134};
  JobChecker(settings())
      .update(job_, std::vector<ImageView>{images[0].view(), images[1].view()}, std::nullopt);
  job_.frames = {0, 134, 269};
  auto out = JobChecker(settings()).compare(job_, 0, views(images), std::nullopt);
  EXPECT_TRUE(out.results[0].passed);
  EXPECT_EQ(out.results[2].line(), "FAIL jobs/kov.json frame 269: no golden " +
                                       (job_.golden_dir / "frame_0269.png").string() +
                                       "; create it with: update jobs/kov.json 269");
}

TEST_F(JobCheck, AGoldenOfAnotherSizeFails) {
  const auto images = frames();
  JobChecker(settings()).update(job_, views(images), std::nullopt);
  const std::vector<TestImage> larger = {disc_image(40, 31), disc_image(40, 31),
                                         disc_image(40, 31)};
  const auto out = JobChecker(settings()).compare(job_, 0, views(larger), std::nullopt);
  EXPECT_FALSE(out.results[0].passed);
  EXPECT_NE(out.results[0].problem.find("is 40x30 but the frame is 40x31; re-baseline with: "
                                        "update jobs/kov.json 0,134,269"),
            std::string::npos)
      << out.results[0].problem;
}

TEST_F(JobCheck, FramesAfterANumericalFailureFail) {
  const auto images = frames();
  JobChecker(settings()).update(job_, views(images), std::nullopt);
  const auto out = JobChecker(settings())
                       .compare(job_, 0, std::vector<ImageView>{images[0].view()},
                                std::string("step size too small"));
  EXPECT_TRUE(out.results[0].passed);
  EXPECT_EQ(out.results[1].line(),
            "FAIL jobs/kov.json frame 134: numerical failure before this frame: step size too "
            "small");
  EXPECT_FALSE(out.results[2].passed);
}

TEST_F(JobCheck, WarnsOnceWhenTheGoldensCameFromAnotherRenderer) {
  const auto images = frames();
  auto other = settings();
  other.environment.gl_version = "4.5 Mesa 24.0";
  JobChecker(other).update(job_, views(images), std::nullopt);
  const auto out = JobChecker(settings()).compare(job_, 0, views(images), std::nullopt);
  ASSERT_EQ(out.warnings.size(), 1u);
  EXPECT_NE(out.warnings[0].find("goldens were made elsewhere: GL version '4.5 Mesa 24.0' in "
                                 "golden.json, '4.5 Mesa 22.3.6' now"),
            std::string::npos)
      << out.warnings[0];
  for (const auto& r : out.results) EXPECT_TRUE(r.passed);
}

TEST_F(JobCheck, SsimThresholdOnePassesFramesEqualToTheirGoldens) {
  const auto images = frames();
  JobChecker(settings()).update(job_, views(images), std::nullopt);
  auto s = settings();
  s.tolerance.metric = Metric::ssim;
  s.tolerance.min_ssim = 1.0;
  const auto out = JobChecker(s).compare(job_, 0, views(images), std::nullopt);
  for (const auto& r : out.results) EXPECT_TRUE(r.passed) << r.line();
}

}  // namespace
}  // namespace epviz::check
