// A frame's text set as print sets numbers: powers of ten in superscripts and
// a true minus sign, names with digits in them left alone.
#include <gtest/gtest.h>

#include "paint/frame_typesetting.hpp"

namespace epviz {
namespace {

using paint::print_numbers_in;

TEST(FrameTypesetting, ExponentsBecomePowersOfTen) {
  EXPECT_EQ(print_numbers_in("dop853, tol 6.7e-06 (auto)"), "dop853, tol 6.7×10⁻⁶ (auto)");
  EXPECT_EQ(print_numbers_in("tol 1e-10"), "tol 10⁻¹⁰");
  EXPECT_EQ(print_numbers_in("2E+03 and 1.5e3"), "2×10³ and 1.5×10³");
  EXPECT_EQ(print_numbers_in("tol 2.6e-07 (auto, tightened)"), "tol 2.6×10⁻⁷ (auto, tightened)");
}

TEST(FrameTypesetting, HyphensBeforeNumbersBecomeMinusSigns) {
  EXPECT_EQ(print_numbers_in("r = (0.6, -0.4, 0.7)"), "r = (0.6, −0.4, 0.7)");
  EXPECT_EQ(print_numbers_in("beyond t = 41.7"), "beyond t = 41.7");
  EXPECT_EQ(print_numbers_in("step -1e-3"), "step −10⁻³");
}

TEST(FrameTypesetting, NamesWithDigitsAreLeftAlone) {
  for (const char* name : {"dop853", "rk4, step 0.25", "Gauss-4", "exact-split4, step 0.1", "rkf78",
                           "1280x720", "t = 40.000 / 40", "e3", "x2e5y"})
    EXPECT_EQ(print_numbers_in(name), name);
}

TEST(FrameTypesetting, EveryTextOfTheFrameIsSet) {
  scene::Frame f;
  f.overlay.title = "tol 1e-08";
  f.overlay.lines = {"dop853, tol 6.7e-06 (auto)", "I = (2, 2, 1)"};
  f.comparison.emplace();
  f.comparison->labels = {"reference: dop853, tol 1e-10"};
  f.caption = "kovalevskaya: dop853, tol 2.6e-05";
  f.pixel_true_note = "beyond t = 1e+02: not pixel-accurate";
  paint::typeset_frame_text(f);
  EXPECT_EQ(f.overlay.title, "tol 10⁻⁸");
  EXPECT_EQ(f.overlay.lines[0], "dop853, tol 6.7×10⁻⁶ (auto)");
  EXPECT_EQ(f.overlay.lines[1], "I = (2, 2, 1)");
  EXPECT_EQ(f.comparison->labels[0], "reference: dop853, tol 10⁻¹⁰");
  EXPECT_EQ(f.caption, "kovalevskaya: dop853, tol 2.6×10⁻⁵");
  EXPECT_EQ(f.pixel_true_note, "beyond t = 10²: not pixel-accurate");
}

}  // namespace
}  // namespace epviz
