// Dashes laid along a polyline by its length on screen.
#include <gtest/gtest.h>

#include <vector>

#include <glm/geometric.hpp>

#include "paint/dash_pattern.hpp"

namespace epviz {
namespace {

// Where a place on the polyline is, in pixels along it.
float along(const std::vector<glm::vec2>& line, const paint::PolylineAt& at) {
  float s = 0.0f;
  for (std::size_t i = 0; i < at.segment; ++i) s += glm::length(line[i + 1] - line[i]);
  return s + at.fraction * glm::length(line[at.segment + 1] - line[at.segment]);
}

TEST(DashPattern, DashesFollowTheLengthAcrossCorners) {
  // 10 px right, then 10 px down: 20 px; on 4, off 2 gives dashes at
  // 0-4, 6-10, 12-16, 18-20 (the third crosses no corner, the second ends on it).
  const std::vector<glm::vec2> line = {{0, 0}, {10, 0}, {10, 10}};
  const float pattern[] = {4.0f, 2.0f};
  const auto spans = paint::dash_spans(line, pattern);
  const std::vector<std::pair<float, float>> expected = {{0, 4}, {6, 10}, {12, 16}, {18, 20}};
  ASSERT_EQ(spans.size(), expected.size());
  for (std::size_t i = 0; i < spans.size(); ++i) {
    EXPECT_NEAR(along(line, spans[i].from), expected[i].first, 1e-4f) << i;
    EXPECT_NEAR(along(line, spans[i].to), expected[i].second, 1e-4f) << i;
  }
}

TEST(DashPattern, ASpanAcrossACornerKeepsTheCorner) {
  const std::vector<glm::vec2> line = {{0, 0}, {10, 0}, {10, 10}};
  const float pattern[] = {14.0f, 6.0f};  // one dash from 0 to 14: round the corner
  const auto spans = paint::dash_spans(line, pattern);
  ASSERT_EQ(spans.size(), 1u);
  const auto piece = paint::span_vertices<glm::vec2>(
      line, spans[0], [](glm::vec2 a, glm::vec2 b, float s) { return a + (b - a) * s; });
  const std::vector<glm::vec2> expected = {{0, 0}, {10, 0}, {10, 4}};
  ASSERT_EQ(piece.size(), expected.size());
  for (std::size_t i = 0; i < piece.size(); ++i)
    EXPECT_LT(glm::length(piece[i] - expected[i]), 1e-4f);
}

TEST(DashPattern, SolidIsTheWholeLineAndTheOpenPatternIsLooser) {
  const std::vector<glm::vec2> line = {{0, 0}, {3, 4}, {6, 8}};
  const auto whole = paint::dash_spans(line, {});
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_NEAR(along(line, whole[0].to), 10.0f, 1e-4f);
  // After the horizon a solid line is dashed and a dashed one has longer gaps.
  EXPECT_TRUE(paint::dash_pattern(scene::LineStyle::solid, 2.0f, false).empty());
  EXPECT_FALSE(paint::dash_pattern(scene::LineStyle::solid, 2.0f, true).empty());
  const auto dashed = paint::dash_pattern(scene::LineStyle::dashed, 2.0f, false);
  const auto open = paint::dash_pattern(scene::LineStyle::dashed, 2.0f, true);
  ASSERT_EQ(dashed.size(), open.size());
  EXPECT_EQ(dashed[0], open[0]);
  EXPECT_GT(open[1], dashed[1]);
  // Every style has its own pattern.
  const scene::LineStyle styles[] = {scene::LineStyle::dashed, scene::LineStyle::dotted,
                                     scene::LineStyle::dash_dot, scene::LineStyle::long_dash,
                                     scene::LineStyle::dash_dot_dot};
  for (std::size_t i = 0; i < std::size(styles); ++i)
    for (std::size_t j = i + 1; j < std::size(styles); ++j)
      EXPECT_NE(paint::dash_pattern(styles[i], 2.0f, false),
                paint::dash_pattern(styles[j], 2.0f, false));
}

}  // namespace
}  // namespace epviz
