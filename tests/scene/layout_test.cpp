// The one layout of a picture: its rectangles lie inside the picture, do not
// overlap, keep their proportions, and its pixel scales follow from the
// camera's framing of the sphere and the plot's side.
#include <gtest/gtest.h>

#include "scene/layout.hpp"

namespace epviz {
namespace {

using scene::Rect;

bool inside(const Rect& r, int x0, int width, int height) {
  return r.x >= x0 && r.y >= 0 && r.right() <= width && r.bottom() <= height && r.width > 0 &&
         r.height > 0;
}
bool overlap(const Rect& a, const Rect& b) {
  return a.x < b.right() && b.x < a.right() && a.y < b.bottom() && b.y < a.bottom();
}

scene::LayoutRequest request(int w, int h, scene::Layers layers = {}, int reserved = 0) {
  scene::LayoutRequest q;
  q.width = w;
  q.height = h;
  q.layers = layers;
  q.overlay = {5, 4};
  q.reserved_left = reserved;
  return q;
}

class LayoutAtSize : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(LayoutAtSize, RectanglesInsideThePictureWithoutOverlap) {
  const auto [w, h] = GetParam();
  for (int reserved : {0, w / 4}) {
    const auto l = scene::frame_layout(request(w, h, {}, reserved));
    ASSERT_TRUE(l.view_3d && l.panel_column && l.plot_area);
    EXPECT_TRUE(inside(*l.view_3d, reserved, w, h));
    EXPECT_TRUE(inside(*l.panel_column, reserved, w, h));
    EXPECT_FALSE(overlap(*l.view_3d, *l.panel_column));
    // Side by side, filling what is not reserved.
    EXPECT_EQ(l.view_3d->x, reserved);
    EXPECT_EQ(l.view_3d->right(), l.panel_column->x);
    EXPECT_EQ(l.panel_column->right(), w);
    // The 3D view takes 60 % of the width, the plot is a square in the panel's column.
    EXPECT_NEAR(double(l.view_3d->width) / (w - reserved), 0.6, 0.01);
    const auto& p = *l.plot_area;
    EXPECT_EQ(p.width, p.height);
    EXPECT_GE(p.x, l.panel_column->x);
    EXPECT_LE(p.right(), l.panel_column->right());
    EXPECT_GE(p.y, 0);
    EXPECT_LE(p.bottom(), h);
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, LayoutAtSize,
                         ::testing::Values(std::pair{320, 240}, std::pair{640, 360},
                                           std::pair{1280, 720}, std::pair{1920, 1080},
                                           std::pair{720, 1280}));

TEST(Layout, OneLayerTakesTheWholePicture) {
  const auto sphere = scene::frame_layout(
      request(800, 600, scene::Layers::only({scene::Layer::sphere, scene::Layer::overlay})));
  ASSERT_TRUE(sphere.view_3d);
  EXPECT_FALSE(sphere.panel_column);
  EXPECT_EQ(sphere.view_3d->width, 800);
  EXPECT_EQ(sphere.plane_px_per_unit, 0.0);
  const auto plane =
      scene::frame_layout(request(800, 600, scene::Layers::only({scene::Layer::riccati})));
  ASSERT_TRUE(plane.panel_column);
  EXPECT_FALSE(plane.view_3d);
  EXPECT_EQ(plane.panel_column->width, 800);
  EXPECT_EQ(plane.sphere_px_per_unit, 0.0);
}

TEST(Layout, OverlayTakesTheColumnTopOnlyWhereThePlotStaysLarge) {
  const auto large = scene::frame_layout(request(1280, 720));
  EXPECT_TRUE(large.overlay_in_column);
  EXPECT_GE(large.plot_area->height, 720 * 35 / 100);
  const auto small = scene::frame_layout(request(320, 240));
  EXPECT_FALSE(small.overlay_in_column);
  // Without the overlay the plot grows back.
  auto q = request(1280, 720);
  q.layers.overlay = false;
  EXPECT_GT(scene::frame_layout(q).plot_area->width, large.plot_area->width);
}

// A place the job asks for decides over the room: beside the view even in a
// small picture, over a corner of the view even where the column has room.
TEST(Layout, TheOverlayPlaceAskedForDecides) {
  auto beside = request(640, 360);
  beside.page.overlay = scene::OverlayPlace::beside;
  EXPECT_FALSE(scene::frame_layout(request(640, 360)).overlay_in_column);
  const auto b = scene::frame_layout(beside);
  EXPECT_TRUE(b.overlay_in_column);
  EXPECT_LT(b.plot_area->width, scene::frame_layout(request(640, 360)).plot_area->width);
  for (const auto place : {scene::OverlayPlace::top_left, scene::OverlayPlace::top_right,
                           scene::OverlayPlace::bottom_left, scene::OverlayPlace::bottom_right}) {
    auto corner = request(1280, 720);
    corner.page.overlay = place;
    EXPECT_FALSE(scene::frame_layout(corner).overlay_in_column) << scene::name(place);
  }
  for (const auto place : {scene::OverlayPlace::automatic, scene::OverlayPlace::beside,
                           scene::OverlayPlace::bottom_right})
    EXPECT_EQ(scene::overlay_place_from_name(scene::name(place)), place);
  EXPECT_FALSE(scene::overlay_place_from_name("middle"));
}

TEST(Layout, SphereScaleFramesTheSphereWithItsLabels) {
  // At the nominal distance of 3.4 radii a sphere of radius 1.22 (the sphere
  // and its pole labels) just fits the narrower side of the 3D view.
  for (auto [w, h] : {std::pair{1280, 720}, std::pair{320, 240}, std::pair{400, 900}}) {
    const auto l = scene::frame_layout(request(w, h));
    const int narrow = std::min(l.view_3d->width, l.view_3d->height);
    EXPECT_NEAR(1.22 * l.sphere_px_per_unit, narrow / 2.0, 1e-3 * narrow) << w << "x" << h;
  }
  // Twice as far: half the size.
  auto q = request(1280, 720);
  const double near_px = scene::frame_layout(q).sphere_px_per_unit;
  q.camera_distance *= 2;
  EXPECT_NEAR(scene::frame_layout(q).sphere_px_per_unit, near_px / 2, 1e-6 * near_px);
}

TEST(Layout, PlaneScaleIsThePlotSideOverTheExtent) {
  auto q = request(1280, 720);
  q.plane_extent = 2.0f;
  const auto l = scene::frame_layout(q);
  EXPECT_DOUBLE_EQ(l.plane_px_per_unit * 4.0, double(l.plot_area->width));
}

// Gallery tiles line up: the panel's rectangles do not depend on how many
// lines and drift rows a job's overlay has, only on the picture's size.
TEST(Layout, PanelIsTheSameWhateverTheOverlayHolds) {
  for (auto [w, h] : {std::pair{1280, 720}, std::pair{480, 270}, std::pair{3840, 2160}}) {
    auto one = request(w, h), eight = request(w, h);
    one.overlay = {1, 0};
    eight.overlay = {8, 8};
    const auto a = scene::frame_layout(one), b = scene::frame_layout(eight);
    ASSERT_TRUE(a.plot_area && b.plot_area);
    for (auto [ra, rb] :
         {std::pair{*a.plot_area, *b.plot_area}, std::pair{*a.panel_column, *b.panel_column},
          std::pair{*a.view_3d, *b.view_3d}}) {
      EXPECT_EQ(ra.x, rb.x) << w << "x" << h;
      EXPECT_EQ(ra.y, rb.y) << w << "x" << h;
      EXPECT_EQ(ra.width, rb.width) << w << "x" << h;
      EXPECT_EQ(ra.height, rb.height) << w << "x" << h;
    }
    EXPECT_EQ(a.overlay_in_column, b.overlay_in_column);
  }
}

// A 4K still reads like the 720p one scaled up: text, marks and paddings grow
// with the picture's height (3x), not by a smaller factor.
TEST(Layout, TextAndMarksScaleWithThePicture) {
  const double ratio = 2160.0 / 720.0;
  EXPECT_NEAR(scene::overlay_font_px(2160) / scene::overlay_font_px(720), ratio, 0.1 * ratio);
  EXPECT_NEAR(scene::ui_scale(2160) / scene::ui_scale(720), ratio, 0.1 * ratio);
  // And the layout keeps its proportions: the plot is the same fraction of the picture.
  const auto small = scene::frame_layout(request(1280, 720));
  const auto big = scene::frame_layout(request(3840, 2160));
  EXPECT_NEAR(double(big.plot_area->width) / small.plot_area->width, ratio, 0.02 * ratio);
  EXPECT_NEAR(double(big.plot_area->y) / small.plot_area->y, ratio, 0.05 * ratio);
  EXPECT_EQ(big.overlay_in_column, small.overlay_in_column);
  // Never below a readable size in small tiles.
  EXPECT_GE(scene::overlay_font_px(120), 13.0f);
  EXPECT_EQ(scene::ui_scale(240), 1.0f);
}

// A figure at a printed size: 85 mm at 300 dpi (1004 px), its text 8 pt
// (33.3 px). Its parts stack in one column, each across the width, none over
// another, in the order the eye reads them; the page is as tall as they are.
scene::LayoutRequest printed(scene::Layers layers, int legend_rows, bool section) {
  auto q = request(1004, 0, layers);
  q.page = {scene::type_height_for_font(8.0f * 300.0f / 72.0f), true};
  q.legend_rows = legend_rows;
  q.chart_height = legend_rows > 0 ? scene::comparison_chart_height(q.page.type_height) : 0;
  q.section_panel = section;
  q.height = scene::stacked_height(q);
  return q;
}

TEST(PrintedLayout, PartsStackAcrossTheWidthInReadingOrder) {
  for (const auto& [legend, section] : {std::pair{0, false}, {5, false}, {0, true}}) {
    const auto q = printed({}, legend, section);
    const auto l = scene::frame_layout(q);
    ASSERT_TRUE(l.view_3d && l.overlay_area && l.panel_column && l.plot_area);
    std::vector<Rect> parts{*l.view_3d, *l.overlay_area, *l.plot_area};
    if (legend > 0) {
      ASSERT_TRUE(l.legend_area && l.chart_area);
      parts.push_back(*l.legend_area);
      // The legend between the view and the overlay's text.
      EXPECT_EQ(l.legend_area->y, l.view_3d->bottom());
      EXPECT_EQ(l.overlay_area->y, l.legend_area->bottom());
    } else {
      EXPECT_EQ(l.overlay_area->y, l.view_3d->bottom());
    }
    if (section) {
      ASSERT_TRUE(l.section_area);
      parts.push_back(*l.section_area);
      EXPECT_EQ(l.section_area->y, l.plot_area->y);  // side by side under the text
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
      EXPECT_TRUE(inside(parts[i], 0, q.width, q.height)) << i;
      for (std::size_t j = i + 1; j < parts.size(); ++j)
        EXPECT_FALSE(overlap(parts[i], parts[j])) << i << " " << j;
    }
    EXPECT_EQ(l.view_3d->width, q.width);
    EXPECT_EQ(l.overlay_area->width, q.width);
    EXPECT_GE(l.plot_area->y, l.overlay_area->bottom());
    // As tall as its parts: the column's bottom is the page's.
    EXPECT_EQ(l.panel_column->bottom(), q.height);
  }
}

// The type follows the font asked for, not the page's height: the same
// figure twice as tall has the same text, and the overlay's band holds its
// reserved rows at that font.
TEST(PrintedLayout, TypeFollowsTheFontAskedNotThePageHeight) {
  const auto q = printed({}, 0, false);
  const float font = scene::overlay_font_px(q.page.type_height);
  EXPECT_NEAR(font, 8.0f * 300.0f / 72.0f, 0.05f);
  const int rows = 1 + scene::kOverlayReserved.lines + 2 + scene::kOverlayReserved.drifts;
  const auto l = scene::frame_layout(q);
  EXPECT_GE(l.overlay_area->height, int(font * 1.3f * float(rows)));
  auto taller = q;
  taller.height = 2 * q.height;
  const auto lt = scene::frame_layout(taller);
  EXPECT_EQ(lt.overlay_area->height, l.overlay_area->height);
  EXPECT_EQ(lt.plot_area->width, l.plot_area->width);
  // Twice the font: the text's parts grow, the view (the width's) does not.
  auto bigger = q;
  bigger.page.type_height *= 2;
  const auto lb = scene::frame_layout(bigger);
  EXPECT_EQ(lb.view_3d->height, l.view_3d->height);
  EXPECT_GT(lb.overlay_area->height, l.overlay_area->height * 3 / 2);
}

// Without a 3D view the panels come first; without panels the page ends
// with the overlay's text.
TEST(PrintedLayout, MissingPartsLeaveNoGap) {
  const auto plane_only = scene::frame_layout(
      printed(scene::Layers::only({scene::Layer::riccati, scene::Layer::overlay}), 0, false));
  ASSERT_TRUE(plane_only.overlay_area && plane_only.plot_area);
  EXPECT_FALSE(plane_only.view_3d);
  EXPECT_EQ(plane_only.overlay_area->y, 0);
  const auto q =
      printed(scene::Layers::only({scene::Layer::sphere, scene::Layer::overlay}), 0, false);
  const auto sphere_only = scene::frame_layout(q);
  EXPECT_FALSE(sphere_only.panel_column);
  ASSERT_TRUE(sphere_only.overlay_area);
  EXPECT_EQ(sphere_only.overlay_area->bottom(), q.height);
}

}  // namespace
}  // namespace epviz
