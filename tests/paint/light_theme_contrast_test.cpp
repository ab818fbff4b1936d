// A --theme light figure is made for print: every line and text at least 3:1
// against what lies behind it (WCAG's contrast ratio, colour_measures.hpp).
// Measured on the colours the painter uses, each laid over its backdrop as
// the picture composes it (source over, as GL blends):
// - the page: the theme's background;
// - the sphere's glass over the page, where it is most opaque (its outline);
// - the (a, b) plane's panel, which the separation chart shares;
// - the overlay window over the page, at both of its opacities.
// A mark (marker, fixed point, centre of mass) passes by its fill or by its
// outline. The panels' grids are faint guides behind the data, as on paper
// charts, and are not held to 3:1. Bench charts, drawn on paper in every
// theme, are checked line by line and text by text on their drawing.
#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <string>

#include "paint/colour_measures.hpp"
#include "paint/comparison_painter.hpp"
#include "paint/figure_drawing.hpp"
#include "paint/figure_fixtures.hpp"
#include "paint/preset_frame.hpp"
#include "physics/cases.hpp"
#include "scene/theme.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;

constexpr double kPrint = 3.0;

glm::vec4 rgba(const scene::Rgba& c) { return {c[0], c[1], c[2], c[3]}; }

// `fg` with opacity `alpha` (times its own) over the opaque `bg`.
glm::vec4 over(const glm::vec4& fg, const glm::vec4& bg, float alpha = 1.0f) {
  const float a = fg.a * alpha;
  return {fg.r * a + bg.r * (1 - a), fg.g * a + bg.g * (1 - a), fg.b * a + bg.b * (1 - a), 1.0f};
}

struct Backdrop {
  std::string name;
  glm::vec4 colour;
};

// The glass's opacity grows towards the outline by (1 + rim) (shaders/mesh.frag,
// the rim term FramePainter::draw_sphere gives the glass).
constexpr float kGlassRim = 1.4f;

struct LightPicture {
  const scene::Theme& ink = scene::light_theme();
  glm::vec4 page = rgba(ink.colours.background);
  glm::vec4 glass = over(rgba(ink.colours.sphere), page, 1.0f + kGlassRim);
  glm::vec4 panel = rgba(ink.panel_background);
  Backdrop page_ = {"page", page}, glass_ = {"glass", glass}, panel_ = {"panel", panel};
  std::vector<Backdrop> window = {
      {"window in the column", over(rgba(ink.overlay_window), page, ink.overlay_alpha_in_column)},
      {"floating window", over(rgba(ink.overlay_window), page, ink.overlay_alpha_floating)}};
};

void expect_print_contrast(const std::string& what, const glm::vec4& colour,
                           const std::vector<Backdrop>& backdrops, float alpha = 1.0f) {
  for (const auto& b : backdrops)
    EXPECT_GE(et::contrast_ratio(over(colour, b.colour, alpha), b.colour), kPrint)
        << what << " on the " << b.name;
}

void expect_print_mark(const std::string& what, const glm::vec4& fill, const glm::vec4& outline,
                       const std::vector<Backdrop>& backdrops) {
  for (const auto& b : backdrops)
    EXPECT_GE(std::max(et::contrast_ratio(over(fill, b.colour), b.colour),
                       et::contrast_ratio(over(outline, b.colour), b.colour)),
              kPrint)
        << what << " on the " << b.name;
}

TEST(LightThemeContrast, OverlayTextAndKeys) {
  const LightPicture p;
  const auto& ink = p.ink;
  for (const auto& [what, c] : {std::pair{"title", ink.title},
                                {"overlay text", ink.overlay_text},
                                {"drift heading", ink.overlay_heading},
                                {"drift ok", ink.drift_ok},
                                {"drift warn", ink.drift_warn},
                                {"drift bad", ink.drift_bad},
                                {"window border and separator", ink.overlay_border}})
    expect_print_contrast(what, rgba(c), p.window);
  // The keys and captions over the 3D view (marks key, colour bar, trail
  // caption, legend rows) and the horizon note on its box.
  expect_print_contrast("marks key and axis labels", rgba(ink.axis_label), {p.page_, p.glass_});
  expect_print_contrast("trail caption", rgba(ink.trail_caption), {p.page_, p.glass_});
  expect_print_contrast("legend rows", rgba(ink.title), {p.page_});
  expect_print_contrast("horizon note", rgba(ink.drift_warn),
                        {{"note's box", over(p.panel, p.page, 0.8f)}});
}

TEST(LightThemeContrast, SphereWireframeLabelsAndBody) {
  const LightPicture p;
  const auto& ink = p.ink;
  expect_print_contrast("sphere wireframe", rgba(ink.sphere_grid), {p.page_, p.glass_});
  expect_print_contrast("pole labels", rgba(ink.pole_label), {p.page_, p.glass_});
  for (int i = 0; i < 3; ++i)
    expect_print_contrast("axis e" + std::to_string(i + 1), rgba(ink.axes[i]), {p.page_, p.glass_});
  expect_print_mark("current point", rgba(ink.colours.marker), rgba(ink.marker_edge),
                    {p.page_, p.glass_, p.panel_});
  expect_print_mark("fixed point", rgba(ink.fixed_point_fill), rgba(ink.fixed_point_edge),
                    {p.page_, p.glass_});
  expect_print_mark("centre of mass", rgba(ink.centre_of_mass_fill), rgba(ink.centre_of_mass_edge),
                    {p.page_, p.glass_});
}

TEST(LightThemeContrast, PlanePanelAndSeparationChart) {
  const LightPicture p;
  const auto& ink = p.ink;
  expect_print_contrast("panel frame", rgba(ink.panel_frame), {p.panel_});
  expect_print_contrast("axes", rgba(ink.panel_axis), {p.panel_});
  // The unit circle: the panel's text colour at 0.85 (FramePainter::draw_plane).
  expect_print_contrast("unit circle", rgba(ink.panel_text), {p.panel_}, 0.85f);
  expect_print_contrast("titles, ticks and caption", rgba(ink.panel_text), {p.panel_, p.page_});
  expect_print_contrast("pass through infinity", rgba(ink.infinity_mark), {p.panel_});
  expect_print_contrast("its label", rgba(ink.infinity_label), {p.panel_});
}

// A single run's trail, along the time colours from its oldest point kept to
// now, on the sphere (page and glass) and on the plane.
TEST(LightThemeContrast, TrailFromOldestToNow) {
  const LightPicture p;
  scene::SceneSettings s;
  s.theme = scene::ThemeId::light;
  s.colours = p.ink.colours;
  const auto f = et::preset_frame(physics::Case::kovalevskaya, s);
  ASSERT_FALSE(f.comparison);
  for (int i = 0; i <= 20; ++i) {
    const float age = float(i) / 20.0f;
    expect_print_contrast("trail at age " + std::to_string(age),
                          paint::run_line_colour(f, 0, age, p.ink), {p.page_, p.glass_, p.panel_});
  }
}

// A bench chart's every line and text, from its drawing: on paper, as in
// every theme. Lines drawn at most a quarter opaque are its grid.
TEST(LightThemeContrast, ChartAxesTicksSeriesAndLegend) {
  const auto drawing =
      paint::draw_chart(et::two_series(), et::builtin_font_options(), et::builtin_chart_font());
  const Backdrop paper{"paper", paint::kPaper};
  int lines = 0, texts = 0;
  for (const auto& layer : drawing.layers) {
    const auto& l = layer.list;
    for (const auto& range : l.polylines())
      for (std::size_t v = range.first; v < range.first + range.count; ++v) {
        const glm::vec4 c = l.line_vertices()[v].colour;
        if (c.a <= 0.25f) continue;
        ++lines;
        expect_print_contrast("chart line of colour " + std::to_string(c.r) + " " +
                                  std::to_string(c.g) + " " + std::to_string(c.b) + " " +
                                  std::to_string(c.a),
                              c, {paper});
      }
    for (const auto& m : l.markers()) expect_print_mark("chart marker", m.fill, m.outline, {paper});
    for (const auto& t : l.labels()) {
      ++texts;
      expect_print_contrast("chart text '" + t.text + "'", t.colour, {paper});
    }
  }
  EXPECT_GT(lines, 0);
  EXPECT_GT(texts, 0);
}

}  // namespace
}  // namespace epviz
