// check::FrameJudge, the pass/fail rule of `epviz check` and the snapshot
// tests: counted against tolerances worked out by hand for small images.
#include <gtest/gtest.h>

#include <stdexcept>

#include "check/frame_verdict.hpp"
#include "test_images.hpp"

namespace epviz::check {
namespace {

Tolerance pixel_tolerance(int threshold, double percent) {
  Tolerance t;
  t.max_channel_difference = threshold;
  t.max_differing_percent = percent;
  return t;
}

Tolerance ssim_tolerance(double min_ssim) {
  Tolerance t;
  t.metric = Metric::ssim;
  t.min_ssim = min_ssim;
  return t;
}

TEST(FrameJudge, IdenticalImagesPassWithEveryMetric) {
  const auto a = disc_image(40, 30);
  FrameJudge pixel(pixel_tolerance(0, 0.0));
  const auto v = pixel.judge(a.view(), a.view());
  EXPECT_TRUE(v.passed);
  EXPECT_EQ(v.pixels.pixels_differing, 0u);
  EXPECT_EQ(v.measure, "0 % pixels differ (limit 0 %)");
  FrameJudge ssim(ssim_tolerance(kDefaultMinSsim));
  EXPECT_TRUE(ssim.judge(a.view(), a.view()).passed);
}

TEST(FrameJudge, SsimThresholdOnePassesIdenticalImages) {
  // The largest threshold allowed: only an image equal to its golden passes.
  FrameJudge judge(ssim_tolerance(1.0));
  for (const auto& a : {disc_image(40, 30), disc_image(160, 120)}) {
    const auto v = judge.judge(a.view(), a.view());
    EXPECT_TRUE(v.passed) << a.w << "x" << a.h << ": " << v.measure;
    EXPECT_EQ(v.measure, "SSIM 1.00000 (limit 1)");
  }
  auto b = disc_image(40, 30);
  b.pixel(3, 3)[0] ^= 1;  // one level of red in one pixel
  EXPECT_FALSE(judge.judge(b.view(), disc_image(40, 30).view()).passed);
}

TEST(FrameJudge, OnePixelOverTheLimitFails) {
  // 10x10: one pixel is 1 % of the frame.
  const auto golden = flat_image(10, 10, 100, 100, 100);
  auto actual = golden;
  actual.pixel(4, 7)[1] = 102;  // differs by 2, over a threshold of 1
  FrameJudge strict(pixel_tolerance(1, 0.5));
  const auto v = strict.judge(actual.view(), golden.view());
  EXPECT_FALSE(v.passed);
  EXPECT_EQ(v.pixels.pixels_differing, 1u);
  EXPECT_EQ(v.measure, "1.00 % pixels differ (limit 0.5 %)");
  // The share of pixels is a limit that passes when reached.
  EXPECT_TRUE(FrameJudge(pixel_tolerance(1, 1.0)).judge(actual.view(), golden.view()).passed);
  // The threshold is the largest difference that counts as equal.
  EXPECT_TRUE(FrameJudge(pixel_tolerance(2, 0.0)).judge(actual.view(), golden.view()).passed);
}

TEST(FrameJudge, TheDefaultToleranceFailsAChangeOfHalfAPercent) {
  // 20x20 = 400 pixels: 2 differing pixels are 0.5 % (passes), 3 are 0.75 %.
  const auto golden = flat_image(20, 20, 10, 20, 30);
  auto actual = golden;
  FrameJudge judge{Tolerance{}};
  for (int x = 0; x < 2; ++x) actual.pixel(x, 0)[2] = 40;
  EXPECT_TRUE(judge.judge(actual.view(), golden.view()).passed);
  actual.pixel(2, 0)[2] = 40;
  EXPECT_FALSE(judge.judge(actual.view(), golden.view()).passed);
}

TEST(FrameJudge, SsimBelowTheLimitFails) {
  const auto golden = disc_image(40, 30);
  const auto moved = disc_image(44, 30);  // the disc larger and further right
  TestImage actual = golden;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x)
      for (int c = 0; c < 4; ++c) actual.pixel(x, y)[c] = moved.pixel(x, y)[c];
  FrameJudge judge(ssim_tolerance(0.999));
  const auto v = judge.judge(actual.view(), golden.view());
  EXPECT_FALSE(v.passed) << v.measure;
  EXPECT_LT(v.ssim, 0.999);
  EXPECT_EQ(v.measure.rfind("SSIM 0.", 0), 0u) << v.measure;
  EXPECT_NE(v.measure.find("(limit 0.999)"), std::string::npos) << v.measure;
}

TEST(FrameJudge, RejectsImagesOfDifferentSizes) {
  FrameJudge judge{Tolerance{}};
  EXPECT_THROW(judge.judge(flat_image(4, 3, 0, 0, 0).view(), flat_image(3, 4, 0, 0, 0).view()),
               std::invalid_argument);
}

TEST(PercentText, KeepsSmallSharesVisible) {
  EXPECT_EQ(percent_text(0.0), "0");
  EXPECT_EQ(percent_text(0.0347), "3.47");
  EXPECT_EQ(percent_text(0.0000123), "0.0012");
}

}  // namespace
}  // namespace epviz::check
