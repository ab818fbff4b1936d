// The progress line counts other things than frames (simulate counts samples).
#include <gtest/gtest.h>

#include <sstream>

#include "io/progress.hpp"

namespace {

using namespace epviz::io;

TEST(ProgressUnit, FramesByDefault) {
  EXPECT_EQ(format_progress("x", 1, 4, 2.0, 1.5), "x: 1/4 frames, 2.0 frames/s, ETA 0:02");
}

TEST(ProgressUnit, NamedUnitInCountAndRate) {
  EXPECT_EQ(format_progress("simulate", 10, 201, 5.0, 40.0, "samples"),
            "simulate: 10/201 samples, 5.0 samples/s, ETA 0:40");
}

TEST(ProgressUnit, LineUsesTheOptionsUnit) {
  std::ostringstream out;
  ProgressOptions options;
  options.mode = ProgressMode::on;
  options.out = &out;
  options.unit = "samples";
  {
    ProgressLine progress(3, options);
    progress.update(3);
  }
  EXPECT_NE(out.str().find("3/3 samples"), std::string::npos) << out.str();
  EXPECT_EQ(out.str().find("frames"), std::string::npos) << out.str();
}

}  // namespace
