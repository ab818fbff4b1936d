// A comparison's legend shows the key of the thin, open line only where the
// picture draws a run so (past its pixel-true time): a frame with no measured
// horizon, or before it, has no such row, and the trail's caption takes its
// place. No GL: the legend's texts as draw_run_annotations lays them out.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "paint/comparison_painter.hpp"
#include "scene/run_palette.hpp"

namespace epviz {
namespace {

constexpr int W = 1280, H = 720;
constexpr char kKey[] = "thin, open line: after the run's pixel-true time";

// Two runs at time `t`, each with the pixel-true time given (none: unknown).
scene::Frame two_runs(double t, std::optional<double> first_until,
                      std::optional<double> second_until) {
  scene::Frame f;
  f.t = t;
  f.trail_label = "gamma (body frame)";
  f.pixel_true_until = first_until;
  scene::Comparison c;
  c.labels = {"dop853", "rk4, step 0.2"};
  for (int i = 0; i < 2; ++i) {
    c.colours.push_back(scene::run_colour(i, false));
    c.lines.push_back(scene::run_line_style(i));
  }
  c.others.resize(1);
  c.others[0].pixel_true_until = second_until;
  f.comparison = c;
  return f;
}

std::vector<paint::AnnotationBox> legend_of(const scene::Frame& f) {
  render::DrawList flat;
  const auto layout = scene::frame_layout(scene::layout_request(f, W, H));
  // Every character 7 pixels wide: the texts fit the strip uncut.
  const paint::TextMeasure measure = [](const std::string& s) {
    return glm::vec2(7.0f * float(s.size()), 12.0f);
  };
  return paint::draw_run_annotations(flat, f, layout, scene::dark_theme(), 1.0f, measure,
                                     std::nullopt, glm::ivec2(W, H));
}

const paint::AnnotationBox* find(const std::vector<paint::AnnotationBox>& rows,
                                 const std::string& start) {
  for (const auto& r : rows)
    if (r.text.rfind(start, 0) == 0) return &r;
  return nullptr;
}

float middle_y(const paint::AnnotationBox& b) { return 0.5f * (b.box.min.y + b.box.max.y); }

TEST(ComparisonLegend, NoMeasuredHorizonDrawsNoKeyOfTheThinLine) {
  // The live mode's runs: no pixel-true time is ever measured.
  const auto rows = legend_of(two_runs(30.0, std::nullopt, std::nullopt));
  ASSERT_TRUE(find(rows, "trail: "));
  EXPECT_FALSE(find(rows, kKey));
}

TEST(ComparisonLegend, AHorizonNotYetReachedDrawsNoKey) {
  EXPECT_FALSE(find(legend_of(two_runs(10.0, 20.0, 25.0)), kKey));
  EXPECT_FALSE(paint::any_run_past_pixel_true(two_runs(10.0, 20.0, 25.0)));
  EXPECT_FALSE(find(legend_of(two_runs(10.0, 10.0, std::nullopt)), kKey));  // reached, not passed
}

TEST(ComparisonLegend, ARunPastItsHorizonDrawsTheKeyAboveTheCaption) {
  // Either run past its pixel-true time is enough.
  for (const auto& f : {two_runs(10.0, 4.0, std::nullopt), two_runs(10.0, std::nullopt, 4.0)}) {
    const auto rows = legend_of(f);
    const auto* key = find(rows, kKey);
    const auto* caption = find(rows, "trail: ");
    ASSERT_TRUE(key);
    ASSERT_TRUE(caption);
    EXPECT_GT(middle_y(*caption), middle_y(*key));
  }
}

TEST(ComparisonLegend, WithoutTheKeyTheCaptionMovesUpIntoItsRow) {
  const auto with_key = legend_of(two_runs(10.0, 4.0, std::nullopt));
  const auto without = legend_of(two_runs(10.0, std::nullopt, std::nullopt));
  ASSERT_TRUE(find(with_key, kKey));
  ASSERT_TRUE(find(without, "trail: "));
  EXPECT_FLOAT_EQ(middle_y(*find(without, "trail: ")), middle_y(*find(with_key, kKey)));
  // The runs' rows stay where they were.
  for (const char* run : {"1  dop853", "2  rk4, step 0.2"}) {
    ASSERT_TRUE(find(with_key, run));
    ASSERT_TRUE(find(without, run));
    EXPECT_FLOAT_EQ(middle_y(*find(without, run)), middle_y(*find(with_key, run)));
  }
}

// A run's horizon in the legend names the picture size it holds for: a
// larger picture resolves smaller errors and has an earlier one.
TEST(ComparisonLegend, AHorizonNamesThePictureSizeItHoldsFor) {
  const auto rows = legend_of(two_runs(10.0, std::nullopt, 4.0));
  const std::string note =
      "(pixel-true to t = 4 at " + std::to_string(W) + "×" + std::to_string(H) + ")";
  const auto* second = find(rows, "2  rk4, step 0.2");
  ASSERT_TRUE(second);
  EXPECT_NE(second->text.find(note), std::string::npos) << second->text;
}

}  // namespace
}  // namespace epviz
