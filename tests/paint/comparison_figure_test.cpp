// Comparison figures that show their differences, checked on the picture a
// user made: three integrators on a custom body (inertia 3, 2, 1.2; centre of
// mass 0.3, 0.1, 0.5; DOP853 auto, RK4 step 0.2, exact-split4 step 0.1) and
// the chaos comparison (two starts 1e-6 apart), in both themes:
// - the runs' colours are at least 20 apart in CIELAB, and each is drawn;
// - after its pixel-true time each run is drawn in its colour, opaque, at
//   least 3:1 against the background;
// - no legend box meets the sphere's outline or another label.
// And the legend stays clear for 1 to 6 runs at 720p, 1080p and 4K.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "paint/colour_measures.hpp"
#include "paint/comparison_painter.hpp"
#include "paint/frame_painter.hpp"
#include "physics/cases.hpp"
#include "render/render_test_support.hpp"
#include "render/snapshot.hpp"
#include "scene/frame_source.hpp"
#include "scene/theme.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;

struct Figure {
  std::string name;
  std::vector<scene::RunRequest> runs;
  double trail_length;
};

scene::RunRequest fixed_step(sim::RunSpec r, sim::Method m, double step, std::string label) {
  r.method = m;
  r.step = step;
  return {r, std::move(label), false, false};
}

Figure custom_body() {
  auto base = sim::preset_run(physics::Case::generic, sim::Method::dop853, sim::Formulation::direct,
                              30.0, 1);
  base.case_id = physics::Case::custom;
  base.t_end = 60.0;  // RK4 at step 0.2 parts from the truth by about t = 31
  base.body.inertia = {3.0, 2.0, 1.2};
  base.body.com = {0.3, 0.1, 0.5};
  return {"custom_body",
          {{base, "reference", false, true},
           fixed_step(base, sim::Method::rk4, 0.2, "rk4"),
           fixed_step(base, sim::Method::exact_split4, 0.1, "split")},
          10.0};
}

// Long enough that no tolerance keeps the generic body's picture true to the end.
Figure chaos() {
  auto base = sim::preset_run(physics::Case::generic, sim::Method::dop853, sim::Formulation::direct,
                              300.0, 1);
  auto nudged = base;
  nudged.initial.omega.x() += 1e-6;
  return {
      "chaos", {{base, "omega0", false, true}, {nudged, "omega0 + 1e-6 e1", false, true}}, 15.0};
}

scene::SceneSettings settings_for(scene::ThemeId theme, int w, int h, double trail_length) {
  scene::SceneSettings s;
  s.width = w, s.height = h, s.fps = 10, s.duration = 3;
  s.trail_length = trail_length;
  s.theme = theme;
  s.colours = scene::theme(theme).colours;
  return s;
}

scene::Frame last_frame(const std::vector<scene::RunRequest>& runs, const scene::SceneSettings& s) {
  scene::FrameSource src(scene::plan_scene(runs, s), s);
  return src.frame(src.frame_count() - 1);
}

paint::FramePainter& painter_720() {
  static paint::FramePainter p(et::shared_gl_context(), 1280, 720, {.builtin_font = true});
  return p;
}

paint::Box box_of(const scene::Rect& r) {
  return {glm::vec2(r.x, r.y), glm::vec2(r.right(), r.bottom())};
}

bool meets_disc(const paint::Box& b, const paint::PaintedAnnotations::Disc& d) {
  const glm::vec2 nearest = glm::clamp(d.centre, b.min, b.max);
  return glm::length(nearest - d.centre) < d.radius;
}

// Every legend box clear of the sphere, of the labels and of each other, inside the picture.
void expect_legend_clear(const paint::PaintedAnnotations& a, int w, int h,
                         const std::string& what) {
  ASSERT_TRUE(a.sphere) << what;
  const paint::Box picture{glm::vec2(0.0f), glm::vec2(float(w), float(h))};
  for (std::size_t i = 0; i < a.legend.size(); ++i) {
    const auto& l = a.legend[i];
    EXPECT_GT(l.box.width(), 0.0f) << what << ": " << l.text;
    EXPECT_TRUE(picture.contains(l.box)) << what << ": " << l.text;
    EXPECT_FALSE(meets_disc(l.box, *a.sphere)) << what << ": " << l.text << " covers the sphere";
    for (const auto& label : a.labels)
      EXPECT_FALSE(l.box.intersects(label.box)) << what << ": " << l.text << " / " << label.text;
    for (const auto& ghost : a.ghosts)
      EXPECT_FALSE(l.box.intersects(ghost)) << what << ": " << l.text << " covers a ghost";
    for (std::size_t j = i + 1; j < a.legend.size(); ++j)
      EXPECT_FALSE(l.box.intersects(a.legend[j].box))
          << what << ": " << l.text << " / " << a.legend[j].text;
  }
}

struct Case {
  Figure figure;
  scene::ThemeId theme;
};
void PrintTo(const Case& c, std::ostream* os) {
  *os << c.figure.name << "_" << scene::name(c.theme);
}

class ComparisonFigure : public ::testing::TestWithParam<Case> {};

TEST_P(ComparisonFigure, RunsStayApartReadAfterTheirHorizonAndTheLegendIsClear) {
  const auto& [figure, theme] = GetParam();
  const auto s = settings_for(theme, 1280, 720, figure.trail_length);
  const auto f = last_frame(figure.runs, s);
  ASSERT_TRUE(f.comparison);
  const auto& c = *f.comparison;
  const std::size_t runs = figure.runs.size();
  ASSERT_EQ(c.colours.size(), runs);
  const auto& background = f.colours.background;

  // Colours apart, and line styles apart as well (for greyscale and overlaps).
  for (std::size_t i = 0; i < runs; ++i)
    for (std::size_t j = i + 1; j < runs; ++j) {
      EXPECT_GE(et::lab_distance(c.colours[i], c.colours[j]), 20.0) << i << " / " << j;
      EXPECT_NE(c.lines[i], c.lines[j]) << i << " / " << j;
    }

  // After its horizon each run keeps its colour, opaque, at 3:1 or more.
  int past_horizon = 0;
  for (std::size_t r = 0; r < runs; ++r) {
    const auto& untrue = paint::run_untrue_age(f, r);
    if (!untrue) continue;
    const auto& trail = r == 0 ? f.trail : c.others[r - 1].trail;
    for (const auto& p : trail)
      if (p.age < *untrue) {
        ++past_horizon;
        const glm::vec4 drawn = paint::run_line_colour(f, r, p.age, scene::theme(theme));
        EXPECT_EQ(drawn.a, 1.0f) << "run " << r + 1 << " fades";
        EXPECT_GE(et::contrast_ratio(drawn, background), 3.0) << "run " << r + 1;
        EXPECT_LT(et::lab_distance(drawn, c.colours[r]), 1.0) << "run " << r + 1;
      }
  }
  EXPECT_GT(past_horizon, 0) << "no run passes its pixel-true time: the check is moot";

  // In the picture: each run's colour is there, on the sphere or the plane.
  const auto& img = painter_720().paint(f);
  const auto layout = paint::layout_for(f, 1280, 720);
  for (std::size_t r = 0; r < runs; ++r) {
    int seen = 0;
    for (const auto& rect : {*layout.view_3d, *layout.plot_area})
      for (int y = rect.y; y < rect.bottom(); ++y)
        for (int x = rect.x; x < rect.right(); ++x)
          seen += et::lab_distance(et::pixel_colour(img, x, y), c.colours[r]) < 8.0;
    EXPECT_GT(seen, 100) << "run " << r + 1 << "'s colour is hardly drawn";
  }

  // The legend: a row per run, the horizon's style and the trail's caption, all clear.
  const auto& a = painter_720().annotations();
  EXPECT_EQ(a.legend.size(), runs + 2);
  expect_legend_clear(a, 1280, 720, figure.name);
}

INSTANTIATE_TEST_SUITE_P(UsersFigures, ComparisonFigure,
                         ::testing::Values(Case{custom_body(), scene::ThemeId::dark},
                                           Case{custom_body(), scene::ThemeId::light},
                                           Case{chaos(), scene::ThemeId::dark},
                                           Case{chaos(), scene::ThemeId::light}),
                         [](const auto& param_info) {
                           return param_info.param.figure.name + "_" +
                                  std::string(scene::name(param_info.param.theme));
                         });

// Where a run leaves or re-enters the (a, b) panel, the mark is in the run's
// colour (the time colours would not say whose it is).
TEST(ComparisonFigureMarks, EdgeMarksAreInTheirRunsColours) {
  const auto figure = chaos();
  const auto s = settings_for(scene::ThemeId::dark, 1280, 720, figure.trail_length);
  const auto f = last_frame(figure.runs, s);
  ASSERT_TRUE(f.comparison);
  const auto& img = painter_720().paint(f);
  const auto layout = paint::layout_for(f, 1280, 720);
  const double e = f.plane_extent;
  const render::Panel2D plot(paint::to_viewport(*layout.plot_area), {-e, e, -e, e}, true);
  const float ring = 7.0f;  // on the hollow mark's outline (radius 4, outline 1.5, times 2 at 720p)
  for (std::size_t r = 0; r < 2; ++r) {
    const auto& marks = r == 0 ? f.plane_marks : f.comparison->others[0].plane_marks;
    int checked = 0, in_colour = 0;
    for (const auto& m : marks) {
      if (m.kind != scene::PlaneMark::Kind::leaves_panel) continue;
      const glm::vec2 at = plot.to_pixel({m.ab.x(), m.ab.y()});
      int near = 0;
      for (const glm::vec2 d :
           {glm::vec2(ring, 0), glm::vec2(-ring, 0), glm::vec2(0, ring), glm::vec2(0, -ring)})
        near += et::lab_distance(et::pixel_colour(img, int(at.x + d.x), int(at.y + d.y)),
                                 f.comparison->colours[r]) < 15.0;
      ++checked;
      in_colour += near >= 2;
    }
    ASSERT_GT(checked, 0) << "run " << r + 1 << " never leaves the panel: the check is moot";
    EXPECT_GE(2 * in_colour, checked) << "run " << r + 1;
  }
}

// The custom body's figure as a reviewed golden (tests/snapshots/), in both themes.
TEST(ComparisonFigureSnapshot, CustomBodyMatchesTheReviewedGoldens) {
  static paint::FramePainter painter(et::shared_gl_context(), 640, 360, {.builtin_font = true});
  for (const auto theme : {scene::ThemeId::dark, scene::ThemeId::light}) {
    const auto figure = custom_body();
    const auto& img =
        painter.paint(last_frame(figure.runs, settings_for(theme, 640, 360, figure.trail_length)));
    EXPECT_TRUE(
        et::matches_snapshot("paint_comparison_custom_body_" + std::string(scene::name(theme)),
                             img.width, img.height, img.pixels));
  }
}

TEST(ComparisonLegend, ClearForOneToSixRunsAt720p1080pAnd4K) {
  // Six runs of the Kovalevskaya top with long labels: the legend's rows are wide.
  const auto base = sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853,
                                    sim::Formulation::direct, 6.0, 1);
  std::vector<scene::RunRequest> all = {
      {base, "reference, error-controlled", false, true},
      fixed_step(base, sim::Method::rk4, 0.25, "coarse classical Runge-Kutta"),
      fixed_step(base, sim::Method::midpoint, 0.1, "symplectic implicit midpoint"),
      fixed_step(base, sim::Method::gauss4, 0.2, "Gauss-Legendre, four stages"),
      fixed_step(base, sim::Method::exact_split4, 0.1, "splitting with the exact free flow"),
      fixed_step(base, sim::Method::rk4, 0.5, "very coarse classical Runge-Kutta")};
  for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{1920, 1080}, std::pair{3840, 2160}}) {
    paint::FramePainter painter(et::shared_gl_context(), w, h, {.builtin_font = true});
    for (std::size_t n = 1; n <= all.size(); ++n) {
      auto s = settings_for(scene::ThemeId::dark, w, h, 0.0);
      s.duration = 0.5;
      const std::vector<scene::RunRequest> runs(all.begin(), all.begin() + long(n));
      const auto f = last_frame(runs, s);
      painter.paint(f);
      const std::string what = std::to_string(n) + " runs at " + std::to_string(h) + "p";
      const auto& a = painter.annotations();
      if (n > 1) {
        EXPECT_EQ(a.legend.size(), n + 2) << what;
        const auto layout = paint::layout_for(f, w, h);
        ASSERT_TRUE(layout.legend_area) << what;
        for (const auto& l : a.legend)
          EXPECT_TRUE(box_of(*layout.legend_area).contains(l.box)) << what << ": " << l.text;
      }
      expect_legend_clear(a, w, h, what);
    }
  }
}

}  // namespace
}  // namespace epviz
