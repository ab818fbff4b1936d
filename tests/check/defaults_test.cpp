// The default tolerances: one set of numbers (check/tolerance.hpp), which
// docs/ci.md states and the reports describe; and the frames checked by default.
#include <gtest/gtest.h>

#include "check/frame_choice.hpp"
#include "check/tolerance.hpp"
#include "support/cli.hpp"

namespace epviz::check {
namespace {

TEST(Defaults, DocsStateTheNumbersTheCodeUses) {
  const auto doc = test::slurp(std::filesystem::path(EPVIZ_SOURCE_DIR) / "docs" / "ci.md");
  ASSERT_FALSE(doc.empty());
  for (const auto& stated :
       {"(0..255, default **" + std::to_string(kDefaultChannelThreshold) + "**)",
        "(default **" + number_text(kDefaultMaxDifferingPercent) + "**)",
        "`--threshold` (default **" + number_text(kDefaultMinSsim) + "**)"})
    EXPECT_NE(doc.find(stated), std::string::npos) << "docs/ci.md does not say: " << stated;
}

TEST(Defaults, DescribeNamesTheLimits) {
  EXPECT_EQ(Tolerance{}.describe(),
            "a pixel differs when a channel differs by more than 1/255; a frame fails when more "
            "than 0.5 % of its pixels differ");
  Tolerance ssim;
  ssim.metric = Metric::ssim;
  EXPECT_EQ(ssim.describe(),
            "a frame fails when its SSIM (grey level, 8x8 windows) is below 0.999");
}

TEST(FramesToCheck, FirstMiddleAndLastByDefault) {
  EXPECT_EQ(frames_to_check({}, 270), (std::vector<int>{0, 134, 269}));
  EXPECT_EQ(frames_to_check({}, 2), (std::vector<int>{0, 1}));
  EXPECT_EQ(frames_to_check({}, 1), (std::vector<int>{0}));
}

TEST(FramesToCheck, RangesJoinedOnceInOrder) {
  const std::vector<io::FrameRangeSpec> ranges = {
      io::parse_frame_range("8"), io::parse_frame_range("3:5"), io::parse_frame_range("4:"),
      io::parse_frame_range(":1")};
  EXPECT_EQ(frames_to_check(ranges, 10), (std::vector<int>{0, 1, 3, 4, 5, 6, 7, 8, 9}));
  const std::vector<io::FrameRangeSpec> outside = {io::parse_frame_range("5:12")};
  EXPECT_THROW(frames_to_check(outside, 10), io::FrameRangeError);
}

}  // namespace
}  // namespace epviz::check
