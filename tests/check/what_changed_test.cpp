// Why failing frames fail, from golden.json: a changed job file gets its own
// verdict; otherwise the rendering changed, and the parts of what draws (GL
// renderer, GL version, font) that differ from what made the goldens are named.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "check/job_check.hpp"
#include "check/what_changed.hpp"
#include "io/fnv1a.hpp"
#include "support/temp_dir.hpp"
#include "test_images.hpp"

namespace epviz::check {
namespace {

namespace fs = std::filesystem;

// "fnv1a64:" and 16 hex digits of `bytes`, as golden.json spells a hash.
std::string hash_text(const std::string& bytes) {
  char text[40];
  std::snprintf(text, sizeof text, "fnv1a64:%016llx",
                static_cast<unsigned long long>(io::fnv1a64(bytes)));
  return text;
}

const RenderEnvironment kDejaVu{"llvmpipe (LLVM 15)", "4.5 Mesa 22.3.6", "/fonts/DejaVuSans.ttf",
                                "fnv1a64:1111111111111111"};

class WhatChanged : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream(dir_ / "kov.json") << "{\"a job\": 1}\n";
    job_ = {.shown = "jobs/kov.json",
            .job_file = dir_ / "kov.json",
            .golden_dir = dir_ / "golden" / "kov",
            .frame_count = 10,
            .frames = {0, 9},
            .width = 40,
            .height = 30};
  }
  CheckSettings settings(const RenderEnvironment& environment) const {
    CheckSettings s;
    s.environment = environment;
    s.update_command = [](const GoldenJob& job, const std::vector<int>&) {
      return "update " + job.shown;
    };
    return s;
  }
  // Goldens made in `made_with`; then frame 9 drawn differently in `now`.
  JobOutcome second_frame_changed(const RenderEnvironment& made_with,
                                  const RenderEnvironment& now) {
    const auto disc = disc_image(40, 30), flat = flat_image(40, 30, 9, 9, 9);
    JobChecker(settings(made_with))
        .update(job_, std::vector<ImageView>{disc.view(), disc.view()}, std::nullopt);
    return JobChecker(settings(now))
        .compare(job_, 0, std::vector<ImageView>{disc.view(), flat.view()}, std::nullopt);
  }

  test::TempDir dir_;
  GoldenJob job_;
};

TEST_F(WhatChanged, GoldenJsonRecordsTheFontAndItsHash) {
  second_frame_changed(kDejaVu, kDejaVu);
  const auto rec = nlohmann::json::parse(test::slurp(job_.golden_dir / "golden.json"));
  EXPECT_EQ(rec["font_file"], "/fonts/DejaVuSans.ttf");
  EXPECT_EQ(rec["font_hash"], "fnv1a64:1111111111111111");
}

TEST(RenderEnvironment, HashesTheFontFileButNotTheBuiltinFont) {
  test::TempDir dir;
  std::ofstream(dir / "font.ttf") << "not really a font";
  const auto e = render_environment("r", "v", (dir / "font.ttf").string());
  EXPECT_EQ(e.font_file, (dir / "font.ttf").string());
  EXPECT_EQ(e.font_hash, hash_text("not really a font"));
  EXPECT_EQ(render_environment("r", "v", "builtin").font_hash, "");
}

TEST_F(WhatChanged, AChangedJobIsToldToUpdateOrRevert) {
  const auto disc = disc_image(40, 30);
  JobChecker(settings(kDejaVu))
      .update(job_, std::vector<ImageView>{disc.view(), disc.view()}, std::nullopt);
  std::ofstream(job_.job_file) << "{\"a job\": 2}\n";
  const auto flat = flat_image(40, 30, 9, 9, 9);
  const auto out =
      JobChecker(settings(kDejaVu))
          .compare(job_, 0, std::vector<ImageView>{disc.view(), flat.view()}, std::nullopt);
  EXPECT_TRUE(out.results[0].passed);  // a passing frame is told nothing
  EXPECT_EQ(out.results[0].problem, "");
  EXPECT_NE(out.results[1].line().find(
                "; job changed since goldens: update or revert (update: update jobs/kov.json)"),
            std::string::npos)
      << out.results[1].line();
  EXPECT_EQ(out.results[1].line().find("rendering changed"), std::string::npos);
}

TEST_F(WhatChanged, AnUnchangedJobMeansTheRenderingChanged) {
  const auto out = second_frame_changed(kDejaVu, kDejaVu);
  EXPECT_EQ(out.results[1].problem,
            "rendering changed, the job did not (same GL renderer, GL version and font as the "
            "goldens)");
}

TEST_F(WhatChanged, TheRenderingVerdictNamesWhatDiffersFromTheGoldens) {
  auto now = kDejaVu;
  now.gl_renderer = "SomeGPU 9000";
  now.font_file = "builtin";
  now.font_hash = "";
  const auto out = second_frame_changed(kDejaVu, now);
  EXPECT_EQ(out.results[1].problem,
            "rendering changed, the job did not; differs from the goldens: GL renderer "
            "'llvmpipe (LLVM 15)' in golden.json, 'SomeGPU 9000' now; font "
            "'/fonts/DejaVuSans.ttf' (fnv1a64:1111111111111111) in golden.json, 'builtin' now");
  // The same once more as a warning, for frames that pass anyway.
  ASSERT_EQ(out.warnings.size(), 1u);
  EXPECT_NE(out.warnings[0].find("font '/fonts/DejaVuSans.ttf'"), std::string::npos);
}

TEST(EnvironmentDifferences, TheSameFontElsewhereIsTheSameFont) {
  GoldenRecord rec;
  rec.gl_renderer = kDejaVu.gl_renderer;
  rec.gl_version = kDejaVu.gl_version;
  rec.font_file = "/usr/share/fonts/DejaVuSans.ttf";
  rec.font_hash = kDejaVu.font_hash;
  EXPECT_TRUE(environment_differences(rec, kDejaVu).empty());
  rec.font_hash = "fnv1a64:2222222222222222";  // same name, other bytes
  ASSERT_EQ(environment_differences(rec, kDejaVu).size(), 1u);
  EXPECT_EQ(environment_differences(rec, kDejaVu)[0].rfind("font ", 0), 0u);
  // Records of older epviz hold no font: nothing to compare.
  rec.font_file = rec.font_hash = "";
  EXPECT_TRUE(environment_differences(rec, kDejaVu).empty());
}

TEST(FailureCause, WithoutARecordOrJobHashItSaysItCannotTell) {
  EXPECT_NE(failure_cause(std::nullopt, "fnv1a64:1", kDejaVu, "u").find("unknown"),
            std::string::npos);
  GoldenRecord rec;
  rec.gl_renderer = kDejaVu.gl_renderer;
  EXPECT_NE(failure_cause(rec, "fnv1a64:1", kDejaVu, "u").find("records no job_hash"),
            std::string::npos);
}

}  // namespace
}  // namespace epviz::check
