// Figures side by side: each panel's drawing moved right by the panels
// before it and the gap, every kind of item (lines, markers, fills, text,
// clips) alike, the whole as wide as the panels and as tall as the tallest.
#include <gtest/gtest.h>

#include "paint/figure_panels.hpp"

namespace epviz::paint {
namespace {

FigureDrawing panel(int width, int height) {
  render::DrawList l;
  l.add_line({1, 2, 0}, {3, 4, 0}, glm::vec4(1.0f), 1.0f);
  render::Marker m;
  m.position = {5, 6, 0};
  l.add_marker(m);
  l.add_rect({7, 8}, {9, 10}, glm::vec4(1.0f));
  render::TextLabel t;
  t.position = {11, 12, 0};
  t.text = "x";
  l.add_text(t);
  FigureDrawing d{width, height, {}};
  d.layers.push_back({std::move(l), render::Viewport{1, 1, 5, 5}});
  return d;
}

TEST(FigurePanels, EachPanelMovesRightByThoseBeforeItAndTheGap) {
  const auto all = side_by_side({panel(100, 50), panel(200, 80)}, 10);
  EXPECT_EQ(all.width, 310);
  EXPECT_EQ(all.height, 80);
  ASSERT_EQ(all.layers.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const float dx = k == 0 ? 0.0f : 110.0f;
    const auto& l = all.layers[k].list;
    ASSERT_EQ(l.line_vertices().size(), 2u);
    EXPECT_EQ(l.line_vertices()[0].position.x, 1.0f + dx);
    EXPECT_EQ(l.line_vertices()[1].position.y, 4.0f);
    EXPECT_EQ(l.markers().at(0).position.x, 5.0f + dx);
    ASSERT_EQ(l.triangles().size(), 6u);
    for (const auto& v : l.triangles()) EXPECT_GE(v.position.x, 7.0f + dx);
    EXPECT_EQ(l.labels().at(0).position.x, 11.0f + dx);
    EXPECT_EQ(all.layers[k].clip->x, 1 + int(dx));
  }
}

}  // namespace
}  // namespace epviz::paint
