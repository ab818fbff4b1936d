// Renders the synthetic scene at 320x240 and checks what a reader of the
// picture would check: background, the lit sphere, the trail, the panel circle,
// the ImGui text, anti-aliasing and that the image is not upside down.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "io/png_writer.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include "render/render_test_support.hpp"

#include "render/gpu_mesh.hpp"
#include "render/mesh_data.hpp"
#include "render/renderer.hpp"
#include "render/snapshot.hpp"
#include "render/synthetic_scene.hpp"

namespace {

namespace render = epviz::render;
namespace et = epviz::testing;
namespace io = epviz::io;
using epviz::testing::SyntheticScene;

constexpr int width = 320;
constexpr int height = 240;

render::RendererOptions options(int samples = 4) {
  render::RendererOptions o;
  o.width = width;
  o.height = height;
  o.msaa_samples = samples;
  o.overlay_options.builtin_font = true;  // same pixels on every machine
  return o;
}

// 64 x 48 without the overlay, for what one pixel row or column shows.
render::RendererOptions small_options() {
  render::RendererOptions o = options();
  o.width = 64;
  o.height = 48;
  o.overlay = false;
  return o;
}

// One renderer and one frame for all tests in this file.
class SceneRender : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    et::shared_gl_context();
    renderer_ = new render::Renderer(et::shared_gl_context(), options());
    scene_ = new SyntheticScene();
    scene_->draw(*renderer_);
    image_ = new render::RgbaImage(renderer_->finish_frame());
  }
  static void TearDownTestSuite() {
    delete image_;
    delete scene_;
    delete renderer_;
  }
  static render::Renderer* renderer_;
  static SyntheticScene* scene_;
  static render::RgbaImage* image_;

  static glm::vec2 project(const glm::vec3& p) {
    auto pixel = render::project_to_pixel(SyntheticScene::camera(width, height),
                                          SyntheticScene::view_3d(width, height), p);
    EXPECT_TRUE(pixel.has_value());
    return pixel ? glm::vec2(*pixel) : glm::vec2(0.0f);
  }
  static glm::vec4 at(glm::vec2 p) {
    return et::pixel_colour(*image_, static_cast<int>(p.x), static_cast<int>(p.y));
  }
};
render::Renderer* SceneRender::renderer_ = nullptr;
SyntheticScene* SceneRender::scene_ = nullptr;
render::RgbaImage* SceneRender::image_ = nullptr;

TEST_F(SceneRender, ImageHasTheRequestedSizeAndIsOpaque) {
  ASSERT_EQ(image_->width, width);
  ASSERT_EQ(image_->height, height);
  ASSERT_EQ(image_->pixels.size(), std::size_t{width * height * 4});
  for (int y = 0; y < height; y += 7)
    for (int x = 0; x < width; x += 7) ASSERT_EQ(image_->at(x, y).a, 255) << x << "," << y;
}

TEST_F(SceneRender, BackgroundWhereNothingIsDrawn) {
  // Bottom-left corner of the 3D view: outside the sphere, below the window.
  const glm::vec4 corner = et::pixel_colour(*image_, 2, height - 3);
  EXPECT_LT(et::max_channel_difference(corner, SyntheticScene::background), 1.5f / 255.0f);
}

TEST_F(SceneRender, SphereCentreShowsTheBodyColour) {
  const glm::vec4 centre = at(project(glm::vec3(0.0f)));
  // Orange under a faint glass tint: red clearly above green above blue.
  EXPECT_GT(centre.r, 0.6f);
  EXPECT_GT(centre.r, centre.g + 0.15f);
  EXPECT_GT(centre.g, centre.b + 0.1f);
}

TEST_F(SceneRender, LitSideIsBrighterThanShadedSide) {
  // The key light comes from the upper left of the view; compare two points
  // on the sphere symmetric about its centre along that diagonal.
  const glm::vec2 centre = project(glm::vec3(0.0f));
  const glm::vec2 edge = project(glm::vec3(0.0f, 0.0f, SyntheticScene::body_radius));
  const float r = 0.55f * glm::length(edge - centre);
  const glm::vec2 diagonal = glm::normalize(glm::vec2(-1.0f, -1.0f));
  const float lit = et::luminance(at(centre + r * diagonal));
  const float shaded = et::luminance(at(centre - r * diagonal));
  EXPECT_GT(lit, shaded + 0.15f) << "lit " << lit << " shaded " << shaded;
}

TEST_F(SceneRender, TrailHasItsColourAlongItsPath) {
  // Points on the trail that face the camera (not behind the glass). Where
  // the trail crosses itself the later part is on top, so the pixel may have
  // the colour of any trail point that projects within two pixels of it.
  const glm::vec3 eye = SyntheticScene::camera(width, height).eye_position();
  int checked = 0;
  for (float t = 0.70f; t <= 1.0f; t += 0.01f) {
    const glm::vec3 p = SyntheticScene::trail_point(t);
    if (glm::dot(p, glm::normalize(eye)) < 0.35f) continue;
    const glm::vec2 pixel = project(p);
    const glm::vec4 actual = at(pixel);
    float best = 1.0f;
    for (int k = 0; k <= 2000; ++k) {
      const float s = k / 2000.0f;
      if (glm::length(project(SyntheticScene::trail_point(s)) - pixel) > 2.0f) continue;
      const glm::vec4 expected = SyntheticScene::trail_colour(s);
      // Alpha-blended over the background.
      const glm::vec4 blended = glm::mix(SyntheticScene::background, expected, expected.a);
      best = std::min(best, et::max_channel_difference(actual, blended));
    }
    EXPECT_LT(best, 0.12f) << "t = " << t << " actual " << actual.r << "," << actual.g << ","
                           << actual.b;
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

TEST_F(SceneRender, PanelShowsTheUnitCircle) {
  const auto panel = SyntheticScene::panel(width, height);
  int on_circle = 0;
  for (int k = 0; k < 16; ++k) {
    const double angle = 2.0 * 3.14159265358979 * (k + 0.5) / 16.0;
    const glm::vec4 c = at(panel.to_pixel({std::cos(angle), std::sin(angle)}) + glm::vec2(0.0f));
    if (et::max_channel_difference(c, SyntheticScene::circle_colour) < 0.25f) ++on_circle;
  }
  EXPECT_GE(on_circle, 12);
  // Halfway between circle and origin, off the axes: panel background.
  const glm::vec4 inside = at(panel.to_pixel({0.12, 0.3}));
  EXPECT_LT(et::luminance(inside), 0.2f);
}

TEST_F(SceneRender, ImGuiWindowShowsText) {
  // The same frame without the ImGui window: the difference in bright pixels
  // in the window's corner is the text (and nothing else draws there).
  scene_->draw(*renderer_, false);
  const auto without = renderer_->finish_frame();
  auto bright = [](const render::RgbaImage& image) {
    int count = 0;
    for (int y = 6; y < 70; ++y)
      for (int x = width - 130; x < width - 6; ++x)
        if (et::luminance(et::pixel_colour(image, x, y)) > 0.75f) ++count;
    return count;
  };
  EXPECT_GT(bright(*image_) - bright(without), 80);
}

// The fraction of pixels near the panel circle whose colour lies strictly
// between the panel background and the circle's colour.
double intermediate_fraction(const render::RgbaImage& image) {
  const auto panel = SyntheticScene::panel(width, height);
  const glm::vec4 background = render::PanelStyle{}.background;
  int between = 0, total = 0;
  for (int k = 0; k < 8; ++k) {
    const double angle = 2.0 * 3.14159265358979 * (k + 0.25) / 8.0;  // off the axes
    const glm::vec2 centre = panel.to_pixel({std::cos(angle), std::sin(angle)});
    for (int dy = -3; dy <= 3; ++dy)
      for (int dx = -3; dx <= 3; ++dx) {
        const glm::vec4 c = et::pixel_colour(image, int(centre.x) + dx, int(centre.y) + dy);
        const float s = (et::luminance(c) - et::luminance(background)) /
                        (et::luminance(SyntheticScene::circle_colour) - et::luminance(background));
        if (s > 0.2f && s < 0.8f) ++between;
        ++total;
      }
  }
  return static_cast<double>(between) / total;
}

TEST_F(SceneRender, LineEdgesAreAntiAliased) { EXPECT_GT(intermediate_fraction(*image_), 0.05); }

// A white box turned 20 degrees on black, filling the view; returns how many
// pixels are neither black nor white (the partly covered edge pixels).
int mesh_edge_grey_pixels(int samples) {
  render::RendererOptions o = options(samples);
  o.width = 64;
  o.height = 64;
  o.overlay = false;
  render::Renderer renderer(et::shared_gl_context(), o);
  render::GpuMesh box(render::make_box({0.5f, 0.5f, 0.5f}));
  render::DrawList list;
  // Unlit-looking: full ambient, no specular, so the face is flat white.
  list.add_mesh(box, glm::rotate(glm::mat4(1.0f), glm::radians(20.0f), glm::vec3(0, 0, 1)),
                {{1, 1, 1, 1}, 0.0f, 1.0f, 0.0f});
  render::Lighting flat;
  flat.key_colour = flat.fill_colour = glm::vec3(0.0f);
  flat.sky_colour = flat.ground_colour = glm::vec3(1.0f);
  renderer.begin_frame({0, 0, 0, 1});
  renderer.draw_3d(list, render::Camera{}, {0, 0, 64, 64}, flat);
  const auto image = renderer.finish_frame();
  int grey = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const float l = et::luminance(et::pixel_colour(image, x, y));
      if (l > 0.1f && l < 0.9f) ++grey;
    }
  return grey;
}

TEST(AntiAliasing, MeshEdgesNeedMultisampling) {
  // Four slanted edges of ~40 pixels each: with MSAA most edge pixels are
  // partly covered; without it every pixel is all in or all out.
  EXPECT_GT(mesh_edge_grey_pixels(4), 60);
  EXPECT_EQ(mesh_edge_grey_pixels(0), 0);
}

TEST_F(SceneRender, MatchesTheGoldenSnapshot) {
  EXPECT_TRUE(et::matches_snapshot("synthetic_scene_320x240", image_->width, image_->height,
                                   image_->pixels,
                                   {.max_channel_difference = 4, .max_fraction_over = 0.01}));
}

TEST(Readback, TopOfTheSceneIsTheFirstRow) {
  // GL's +y is up; the image's first row must show what is drawn at the top.
  render::Renderer renderer(et::shared_gl_context(), small_options());
  renderer.begin_frame({0, 0, 0, 1});
  render::DrawList list;
  list.add_marker({{0.0f, 0.75f, 0.0f}, {1, 0, 0, 1}, {1, 0, 0, 1}, 5.0f, 0.0f});  // near the top
  list.add_marker(
      {{0.0f, -0.75f, 0.0f}, {0, 0, 1, 1}, {0, 0, 1, 1}, 5.0f, 0.0f});  // near the bottom
  render::Camera identity;                                              // clip space = world space
  renderer.draw_3d(list, identity, {0, 0, 64, 48});
  const auto image = renderer.finish_frame();
  const auto top = image.at(32, 48 / 8);
  const auto bottom = image.at(32, 48 - 1 - 48 / 8);
  EXPECT_GT(top.r, 200);
  EXPECT_LT(top.b, 50);
  EXPECT_GT(bottom.b, 200);
  EXPECT_LT(bottom.r, 50);
}

TEST(Readback, TwoDPixelCoordinatesCountRowsFromTheTop) {
  render::Renderer renderer(et::shared_gl_context(), small_options());
  renderer.begin_frame({0, 0, 0, 1});
  render::DrawList list;
  list.add_rect({0, 0}, {64, 8}, {0, 1, 0, 1});
  renderer.draw_2d(list);
  const auto image = renderer.finish_frame();
  EXPECT_EQ(image.at(10, 2).g, 255);
  EXPECT_EQ(image.at(10, 45).g, 0);
}

// Dots are squares of their size in pixels, each where its centre says, in
// its colour; and, in a 3D view, hidden behind what is nearer.
TEST(Dots, EachIsASquareOfItsSizeAtItsCentre) {
  render::Renderer renderer(et::shared_gl_context(), small_options());
  renderer.begin_frame({0, 0, 0, 1});
  render::DrawList list;
  const render::ColouredVertex dots[] = {{{10.0f, 10.0f, 0.0f}, {1, 0, 0, 1}},
                                         {{40.0f, 30.0f, 0.0f}, {0, 0, 1, 1}}};
  list.add_dots(dots, 4.0f);
  renderer.draw_2d(list);
  const auto image = renderer.finish_frame();
  const auto lit = [&](int x0, int y0, int size, char channel) {
    int n = 0;
    for (int y = y0 - size; y < y0 + size; ++y)
      for (int x = x0 - size; x < x0 + size; ++x) {
        const auto p = image.at(x, y);
        n += (channel == 'r' ? p.r : p.b) > 200;
      }
    return n;
  };
  EXPECT_EQ(lit(10, 10, 4, 'r'), 16) << "a 4 x 4 square about (10, 10)";
  EXPECT_EQ(lit(40, 30, 4, 'b'), 16) << "a 4 x 4 square about (40, 30)";
  EXPECT_EQ(lit(40, 30, 4, 'r'), 0);
}

TEST(Dots, InAThreeDViewANearerTriangleHidesThem) {
  render::Renderer renderer(et::shared_gl_context(), small_options());
  renderer.begin_frame({0, 0, 0, 1});
  render::DrawList list;
  // A green square at depth 0 over the left half; red dots behind it (z = 0.5,
  // farther in clip space) on both halves.
  list.add_rect({-1.0f, -1.0f}, {0.0f, 1.0f}, {0, 1, 0, 1});
  const render::ColouredVertex dots[] = {{{-0.5f, 0.0f, 0.5f}, {1, 0, 0, 1}},
                                         {{0.5f, 0.0f, 0.5f}, {1, 0, 0, 1}}};
  list.add_dots(dots, 3.0f);
  render::Camera identity;  // clip space = world space
  renderer.draw_3d(list, identity, {0, 0, 64, 48});
  const auto image = renderer.finish_frame();
  EXPECT_GT(image.at(16, 24).g, 200) << "the dot behind the square is hidden";
  EXPECT_LT(image.at(16, 24).r, 50);
  EXPECT_GT(image.at(48, 24).r, 200) << "the other dot is drawn";
}

}  // namespace
