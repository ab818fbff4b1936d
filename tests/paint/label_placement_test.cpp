// Label placement: each label takes its first free candidate, inside its
// bounds and clear of the marks and of the labels placed before it.
#include <gtest/gtest.h>

#include "paint/label_placement.hpp"

namespace epviz {
namespace {

using paint::Box;

TEST(LabelPlacement, FirstFreeCandidateWins) {
  const Box bounds{{0, 0}, {200, 100}};
  const Box mark{{40, 40}, {60, 60}};
  paint::LabelRequest r{"e3", {20, 10}, {{45, 45}, {100, 45}, {10, 10}}};
  const auto boxes = paint::place_labels({r}, {mark}, bounds);
  ASSERT_EQ(boxes.size(), 1u);
  EXPECT_EQ(boxes[0].min, glm::vec2(100, 45));  // the first one covers the mark
  EXPECT_FALSE(boxes[0].intersects(mark));
}

TEST(LabelPlacement, LaterLabelsAvoidEarlierOnesAndStayInside) {
  const Box bounds{{0, 0}, {100, 100}};
  // Both prefer the same spot; the second's next choice leaves the bounds
  // (cut off at the top, as "N" was), its third is free.
  paint::LabelRequest a{"N", {10, 12}, {{45, 20}}};
  paint::LabelRequest b{"S", {10, 12}, {{45, 20}, {45, -5}, {45, 40}}};
  const auto boxes = paint::place_labels({a, b}, {}, bounds);
  EXPECT_EQ(boxes[0].min, glm::vec2(45, 20));
  EXPECT_EQ(boxes[1].min, glm::vec2(45, 40));
  EXPECT_FALSE(boxes[0].intersects(boxes[1]));
  for (const auto& box : boxes) EXPECT_TRUE(bounds.contains(box));
}

TEST(LabelPlacement, NoFreeCandidateTakesTheLeastCoveredMovedInside) {
  const Box bounds{{0, 0}, {50, 50}};
  const Box mark{{0, 0}, {50, 30}};
  // Both candidates meet the mark; the second less, and it sticks out at the
  // bottom, so it is moved up into the bounds.
  paint::LabelRequest r{"x", {10, 10}, {{5, 5}, {20, 45}}};
  const auto boxes = paint::place_labels({r}, {mark}, bounds);
  EXPECT_TRUE(bounds.contains(boxes[0]));
  EXPECT_EQ(boxes[0].min, glm::vec2(20, 40));
  EXPECT_EQ(boxes[0].overlap_area(mark), 0.0f);
}

TEST(LabelPlacement, CandidatesClearTheAnchorFirstOutwards) {
  const glm::vec2 anchor(100, 100), size(30, 12);
  const auto c = paint::candidates_around(anchor, size, {0, -5}, 3.0f);
  ASSERT_GE(c.size(), 8u);
  // The first: straight up (outwards), centred, its bottom 3 px above the anchor.
  EXPECT_NEAR(c[0].x + size.x / 2, anchor.x, 1e-3);
  EXPECT_NEAR(c[0].y + size.y, anchor.y - 3.0f, 1e-3);
  // None covers the anchor (with its gap).
  const Box around = paint::box_around(anchor, {5.9f, 5.9f});
  for (const auto& tl : c)
    EXPECT_FALSE((Box{tl, tl + size}).intersects(around)) << tl.x << "," << tl.y;
}

}  // namespace
}  // namespace epviz
