// The painter: every layer alone and together, both views, each classical case
// through the real pipeline (scene::FrameSource), compared with reviewed goldens
// in tests/snapshots/ (paint_*.png), plus pixel checks that can fail.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <optional>

#include "paint/frame_drawer.hpp"
#include "paint/frame_painter.hpp"
#include "paint/preset_frame.hpp"
#include "physics/cases.hpp"
#include "render/render_test_support.hpp"
#include "render/snapshot.hpp"
#include "scene/frame_source.hpp"
#include "scene/theme.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
constexpr int W = 320, H = 240;

paint::FramePainter& painter() {
  static paint::FramePainter p(et::shared_gl_context(), W, H,
                               {.msaa_samples = 4, .builtin_font = true});
  return p;
}

// A frame of a preset's short run at the goldens' size.
scene::Frame case_frame(physics::Case c, scene::View view = scene::View::body,
                        scene::Layers layers = {}) {
  scene::SceneSettings s;
  s.width = W;
  s.height = H;
  s.view = view;
  s.layers = layers;
  return et::preset_frame(c, s);
}

glm::vec4 px(const render::RgbaImage& img, glm::vec2 at) {
  return et::pixel_colour(img, int(at.x), int(at.y));
}
glm::vec4 background_of(const scene::Frame& f) {
  return {f.colours.background[0], f.colours.background[1], f.colours.background[2], 1};
}

scene::Layers only(bool body, bool sphere, bool riccati, bool overlay) {
  auto l = scene::Layers::only({});
  l.body = body;
  l.sphere = sphere;
  l.riccati = riccati;
  l.overlay = overlay;
  return l;
}

// Where the painter's camera puts a point of the 3D view of a picture of size w x h.
std::optional<glm::vec3> seen_at(const scene::Frame& f, glm::vec3 point, int w = W, int h = H) {
  const auto view = paint::to_viewport(*paint::layout_for(f, w, h).view_3d);
  return render::project_to_pixel(paint::camera_for(f, view), view, point);
}

// The Riccati panel's plot as the painter lays it out.
render::Panel2D riccati_plot(const scene::Frame& f, int w = W, int h = H) {
  const float e = f.plane_extent;
  return {paint::to_viewport(*paint::layout_for(f, w, h).plot_area), {-e, e, -e, e}, true};
}

void expect_background_at(const render::RgbaImage& img, const scene::Frame& f,
                          std::initializer_list<glm::vec2> points) {
  for (glm::vec2 at : points)
    EXPECT_LT(et::max_channel_difference(px(img, at), background_of(f)), 0.02f)
        << at.x << "," << at.y;
}

struct Named {
  std::string name;
  physics::Case c;
  scene::View view;
  scene::Layers layers;
};
void PrintTo(const Named& n, std::ostream* os) { *os << n.name; }

class PainterSnapshot : public ::testing::TestWithParam<Named> {};

TEST_P(PainterSnapshot, MatchesTheReviewedGolden) {
  const auto& n = GetParam();
  const auto& img = painter().paint(case_frame(n.c, n.view, n.layers));
  ASSERT_EQ(img.width, W);
  ASSERT_EQ(img.height, H);
  EXPECT_TRUE(et::matches_snapshot("paint_" + n.name, img.width, img.height, img.pixels));
}

INSTANTIATE_TEST_SUITE_P(
    CasesAndLayers, PainterSnapshot,
    ::testing::Values(
        Named{"euler", physics::Case::euler, scene::View::space, {}},
        Named{"lagrange", physics::Case::lagrange, scene::View::space, {}},
        Named{"kovalevskaya", physics::Case::kovalevskaya, scene::View::body, {}},
        Named{"goryachev_chaplygin", physics::Case::goryachev_chaplygin, scene::View::body, {}},
        Named{"hess", physics::Case::hess, scene::View::body, {}},
        Named{"generic", physics::Case::generic, scene::View::body, {}},
        Named{"layer_body", physics::Case::kovalevskaya, scene::View::body,
              only(true, false, false, false)},
        Named{"layer_sphere", physics::Case::kovalevskaya, scene::View::body,
              only(false, true, false, false)},
        Named{"layer_riccati", physics::Case::kovalevskaya, scene::View::body,
              only(false, false, true, false)},
        Named{"layer_overlay", physics::Case::kovalevskaya, scene::View::body,
              only(false, false, false, true)}),
    [](const auto& param_info) { return param_info.param.name; });

// The plan picks the tolerance and the trail's decimation from the same layout
// the painter draws into, and its pixel scales are those of the real camera and plot.
TEST(Painter, PlanAndPainterShareOneLayout) {
  const auto run = sim::preset_run(physics::Case::lagrange, sim::Method::dop853,
                                   sim::Formulation::direct, 12.0, 200);
  for (auto [w, h] : {std::pair{W, H}, std::pair{1280, 720}}) {
    scene::SceneSettings s;
    s.width = w;
    s.height = h;
    s.camera.distance = 4.0;
    const auto plan = scene::plan_scene(run, s);
    scene::FrameSource source(plan, s);
    const auto f = source.frame(3);
    const auto layout = paint::layout_for(f, w, h);
    EXPECT_EQ(layout.sphere_px_per_unit, plan.layout.sphere_px_per_unit);
    EXPECT_EQ(layout.plane_px_per_unit, plan.layout.plane_px_per_unit);
    EXPECT_EQ(layout.overlay_in_column, plan.layout.overlay_in_column);

    // A small step off the sphere's centre, seen by the painter's camera.
    const auto centre = seen_at(f, {0, 0, 0}, w, h);
    const auto up = seen_at(f, {0, 0, 1e-3f}, w, h);
    ASSERT_TRUE(centre && up);
    const double cos_elevation = std::cos(s.camera.elevation_deg * M_PI / 180);
    EXPECT_NEAR(glm::length(glm::vec2(*up) - glm::vec2(*centre)) / 1e-3 / cos_elevation,
                layout.sphere_px_per_unit, 0.01 * layout.sphere_px_per_unit);
    const render::Panel2D plot = riccati_plot(f, w, h);
    EXPECT_NEAR(glm::length(plot.to_pixel({1, 0}) - plot.to_pixel({0, 0})),
                layout.plane_px_per_unit, 1e-3);
  }
}

TEST(Painter, SphereLayerDrawsTheCurrentPointWithTheMarkerColour) {
  const auto f =
      case_frame(physics::Case::kovalevskaya, scene::View::body, only(false, true, false, false));
  const auto& img = painter().paint(f);
  ASSERT_TRUE(paint::layout_for(f, W, H).view_3d);
  const auto at = seen_at(f, {f.current.x(), f.current.y(), f.current.z()});
  ASSERT_TRUE(at);
  const glm::vec4 marker{f.colours.marker[0], f.colours.marker[1], f.colours.marker[2], 1};
  EXPECT_LT(et::max_channel_difference(px(img, *at), marker), 0.12f);
}

TEST(Painter, BodyLayerShowsTheBoxAtItsCentreOfMass) {
  const auto f =
      case_frame(physics::Case::lagrange, scene::View::body, only(true, false, false, false));
  const auto& img = painter().paint(f);
  const Eigen::Vector3f c = f.body.centre_of_mass;
  const auto at = seen_at(f, {c.x(), c.y(), c.z() + 0.05f});
  ASSERT_TRUE(at);
  const glm::vec4 p = px(img, *at);
  // The body's warm colour, lit: red clearly above blue, and not background.
  EXPECT_GT(p.r, p.b + 0.15f);
  EXPECT_GT(et::max_channel_difference(p, background_of(f)), 0.2f);
}

TEST(Painter, SwitchedOffLayersLeaveBackground) {
  const auto f =
      case_frame(physics::Case::kovalevskaya, scene::View::body, only(false, false, true, false));
  const auto& img = painter().paint(f);
  // Only the panel: the left and right borders and corners are background.
  expect_background_at(img, f, {glm::vec2(2, 2), glm::vec2(W - 3, H - 3), glm::vec2(2, H / 2)});
}

TEST(Painter, RiccatiPanelShowsTheUnitCircle) {
  const auto f =
      case_frame(physics::Case::kovalevskaya, scene::View::body, only(false, false, true, false));
  const auto& img = painter().paint(f);
  ASSERT_TRUE(paint::layout_for(f, W, H).plot_area);
  const render::Panel2D plot = riccati_plot(f);
  int bright = 0;
  for (int k = 0; k < 16; ++k) {
    const double a = 2 * M_PI * (k + 0.5) / 16;
    bright += et::luminance(px(img, plot.to_pixel({std::cos(a), std::sin(a)}))) > 0.35f;
  }
  EXPECT_GE(bright, 12);
}

TEST(Painter, PassThroughInfinityIsMarked) {
  auto f =
      case_frame(physics::Case::kovalevskaya, scene::View::body, only(false, false, true, false));
  f.plane_marks.push_back(
      {Eigen::Vector2f(f.plane_extent, 0.0f), scene::PlaneMark::Kind::through_infinity, 0.2f});
  const auto& img = painter().paint(f);
  const glm::vec2 at = riccati_plot(f).to_pixel({f.plane_extent, 0.0});
  int red = 0;
  for (int dx = -7; dx <= 7; ++dx)
    for (int dy = -7; dy <= 7; ++dy) {
      const glm::vec4 p = px(img, at + glm::vec2(dx, dy));
      red += p.r > 0.6f && p.g < 0.45f && p.b < 0.45f;
    }
  EXPECT_GT(red, 6);
}

// The light theme (no golden: its pictures are looked at, not pinned): a
// light page with the body, sphere, panel and overlay drawn dark on it.
TEST(Painter, LightThemeDrawsDarkOnALightPage) {
  scene::SceneSettings s;
  s.width = W;
  s.height = H;
  s.theme = scene::ThemeId::light;
  s.colours = scene::light_theme().colours;
  const auto f = et::preset_frame(physics::Case::kovalevskaya, s);
  const auto& img = painter().paint(f);
  int light = 0, dark = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const float l = et::luminance(et::pixel_colour(img, x, y));
      light += l > 0.85f;
      dark += l < 0.45f;
    }
  EXPECT_GT(light, W * H / 2);   // mostly page
  EXPECT_GT(dark, W * H / 200);  // and lines and text on it
  expect_background_at(img, f, {glm::vec2(2, 2), glm::vec2(W - 3, H - 3)});
}

TEST(Painter, OverlayAloneDrawsTextAndNothingElse) {
  const auto f =
      case_frame(physics::Case::kovalevskaya, scene::View::body, only(false, false, false, true));
  const auto& img = painter().paint(f);
  int text = 0, elsewhere = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool bright = et::luminance(et::pixel_colour(img, x, y)) > 0.5f;
      // The window at the top left: its widest line (the drift, named and
      // said to be of the drawn states) ends before the last quarter.
      (y < 3 * H / 4 && x < 3 * W / 4 ? text : elsewhere) += bright;
    }
  EXPECT_GT(text, 100);
  EXPECT_EQ(elsewhere, 0);
}

}  // namespace
}  // namespace epviz

// The drift key says what each colour stands for in one wording, whatever
// the window's width: the thresholds as powers of ten. No claim of round-off
// for the first, no "1e-8".
TEST(Painter, DriftKeyIsOneWordingInPrint) {
  const auto key = epviz::paint::FramePainter::drift_table_key();
  EXPECT_EQ(key[0], "<10⁻⁸");
  EXPECT_EQ(key[1], "  <10⁻²");
  EXPECT_EQ(key[2], "  ≥10⁻²");
}

namespace epviz {
namespace {

// The overlay's drift table says what it measures: the drawn (interpolated)
// states, and, where the run reports it, the drift at the integrator's steps
// in a column of its own, each headed.
TEST(Painter, DriftTableSaysWhatItMeasures) {
  scene::Frame f;
  f.overlay.drifts = {{"|γ|²", 2.6e-4}, {"C₁ (energy)", 1e-9}};
  EXPECT_EQ(paint::FramePainter::drift_table_columns(f), std::vector<std::string>{"drawn states"});
  EXPECT_EQ(paint::FramePainter::drift_table_row(f, 0), std::vector<std::string>{"2.6×10⁻⁴"});
  f.overlay.step_drifts = {8e-16, 3e-10};
  EXPECT_EQ(paint::FramePainter::drift_table_columns(f),
            (std::vector<std::string>{"drawn", "at steps"}));
  EXPECT_EQ(paint::FramePainter::drift_table_row(f, 0),
            (std::vector<std::string>{"2.6×10⁻⁴", "8.0×10⁻¹⁶"}));
  f.overlay.step_drifts = {8e-16};  // not one per row: not shown
  EXPECT_EQ(paint::FramePainter::drift_table_columns(f).size(), 1u);
}

TEST(Painter, StepDriftsAreDrawnInTheOverlay) {
  auto f =
      case_frame(physics::Case::kovalevskaya, scene::View::body, only(false, false, false, true));
  auto bright = [](const render::RgbaImage& img) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) n += et::luminance(et::pixel_colour(img, x, y)) > 0.35f;
    return n;
  };
  const int without = bright(painter().paint(f));
  f.overlay.step_drifts.assign(f.overlay.drifts.size(), 1e-15);
  const int with = bright(painter().paint(f));
  EXPECT_GT(with, without + 100);  // a column of values and its heading more
}

}  // namespace
}  // namespace epviz

namespace epviz {
namespace {

// A render's frames carry the run's drift at its steps beside the drawn
// states': Gauss-4 keeps |γ|² at its steps to round-off, while the states
// drawn between them (interpolated) drift far more.
TEST(Painter, RenderedFramesShowTheDriftAtTheSteps) {
  auto run = sim::preset_run(physics::Case::kovalevskaya, sim::Method::gauss4,
                             sim::Formulation::direct, 12.0, 200);
  run.step = 0.05;
  scene::SceneSettings s;
  s.width = W;
  s.height = H;
  s.fps = 10;
  s.duration = 3;
  paint::FrameDrawer drawer(scene::plan_scene(run, s), s);
  const auto f = drawer.frame(29);
  ASSERT_EQ(f.overlay.drifts.size(), 4u);  // |γ|², C₀, C₁, K
  ASSERT_EQ(f.overlay.step_drifts.size(), 4u);
  EXPECT_LT(f.overlay.step_drifts[0], 1e-12);
  EXPECT_GT(f.overlay.drifts[0].second, 1e3 * f.overlay.step_drifts[0]);
}

}  // namespace
}  // namespace epviz

namespace epviz {
namespace {

// The plane's tick labels in print, as the charts': −1, not -1.
TEST(Painter, PanelTickLabelsUseTheMinusSign) {
  const auto f =
      case_frame(physics::Case::kovalevskaya, scene::View::body, only(false, false, true, false));
  std::vector<std::string> texts;
  painter().set_flat_sink([&](const render::DrawList& list) {
    for (const auto& l : list.labels()) texts.push_back(l.text);
  });
  painter().paint(f);
  painter().set_flat_sink({});
  int negative = 0;
  for (const auto& t : texts) {
    EXPECT_FALSE(t.size() > 1 && t[0] == '-' && std::isdigit(static_cast<unsigned char>(t[1])))
        << t;
    negative += t.rfind("−", 0) == 0;
  }
  EXPECT_GE(negative, 2);  // −2 and −1 on each axis, at least
}

}  // namespace
}  // namespace epviz
