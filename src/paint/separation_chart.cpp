#include "paint/separation_chart.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "paint/dash_pattern.hpp"
#include "paint/figure_common.hpp"
#include "paint/painter_common.hpp"
#include "paint/small_chart_axes.hpp"
#include "physics/notation.hpp"
#include "render/panel_2d.hpp"

namespace epviz::paint {
namespace {

// The lowest decade the chart goes down to: below it (and at zero, runs
// that agree exactly) a separation is drawn on the bottom edge, marked.
constexpr int kLowestDecade = -16;

}  // namespace

SeparationRange separation_range(const scene::Comparison& c) {
  double smallest = INFINITY, largest = 0.0;
  for (const auto& run : c.others)
    for (const auto& p : run.separation)
      if (const double v = p.y(); std::isfinite(v) && v > 0.0) {
        smallest = std::min(smallest, v);
        largest = std::max(largest, v);
      }
  SeparationRange r;
  // Two unit vectors are at most 2 apart; a decade above the largest value
  // if a run's γ ever left the sphere that far.
  r.hi = std::max(std::log10(2.0), largest > 0.0 ? std::log10(largest) : 0.0);
  const int data_lo = std::isfinite(smallest) ? int(std::floor(std::log10(smallest))) : -3;
  // At least three decades, so that a chart of runs that agree to 10⁻¹ still
  // reads as a log scale.
  r.lo = std::max(std::min(data_lo, -3), kLowestDecade);
  return r;
}

void draw_separation_chart(render::DrawList& flat, const scene::Comparison& c,
                           const scene::Rect& area, const scene::Theme& ink, float px,
                           const std::function<glm::vec2(const std::string&)>& measure) {
  if (area.width < 40 || area.height < 30 || c.others.empty()) return;
  const SeparationRange range = separation_range(c);
  const float text_h = measure("10⁻⁸").y;
  const float gap = 2.0f * px, tick = 3.0f * px;
  // The title's line on top, the time labels underneath; with no room for
  // both and a plot, the plot takes the title's line.
  const float plot_bottom = float(area.bottom()) - tick - 1.0f * px - text_h;
  const bool title_line = plot_bottom - (float(area.y) + text_h + gap) >= 8.0f * px;
  const float plot_top = title_line ? float(area.y) + text_h + gap : float(area.y) + 0.5f * text_h;
  const float plot_h = std::max(1.0f, plot_bottom - plot_top);
  const auto y_ticks =
      decade_ticks(range.lo, int(std::floor(range.hi)), plot_h / float(range.hi - range.lo), text_h,
                   [](int e) { return decade_label(e); });
  const float left = y_label_room(y_ticks, measure, px);
  // The last time label is centred on the right edge: half of it inside.
  const float right = 0.5f * measure(render::format_tick(c.t_end, c.t_end)).x + 1.0f * px;
  const float plot_w = std::max(10.0f, float(area.width) - left - right);
  const render::Viewport plot_area{int(std::lround(float(area.x) + left)),
                                   int(std::lround(plot_top)), int(plot_w), int(plot_h)};

  // What is plotted: |Δγ| against t, and what Δγ is where there is room;
  // from the plot's left edge (the top decade's label may rise beside it),
  // else from the area's, the labels it would cover left out.
  const std::string sep(physics::symbol::separation), gamma(physics::symbol::gamma);
  const std::string shortest = sep + " against t";
  const std::string candidates[] = {
      sep + " against t,  Δ" + gamma + " = " + gamma + " − " + gamma + " of run 1,  log scale",
      shortest + ", log scale", shortest};
  std::optional<render::TextLabel> title;
  for (const float x : {float(plot_area.x), float(area.x)}) {
    for (const auto& text : candidates)
      if (title_line && measure(text).x <= float(area.right()) - x) {
        title = render::TextLabel{
            {x, float(area.y), 0.0f}, text, to_glm(ink.panel_text), render::TextAnchor::top_left};
        break;
      }
    if (title) break;
  }
  std::vector<TextBox> keep_out;
  if (title) keep_out.push_back(text_box(*title, measure(title->text)));

  const double t_end = std::max(c.t_end, 1e-9);
  const render::Panel2D plot(plot_area, {0.0, t_end, double(range.lo), range.hi}, false);
  const SmallChartStyle ticks =
      draw_small_chart_frame(flat, plot, to_glm(ink.panel_background), ink, px);
  draw_small_chart_ticks(flat, plot, time_ticks(t_end, plot_w, measure), y_ticks, ticks, measure,
                         keep_out);
  if (title) flat.add_text(*title);

  for (std::size_t i = 0; i < c.others.size(); ++i) {
    const auto& samples = c.others[i].separation;
    std::vector<glm::dvec2> points;
    points.reserve(samples.size());
    std::vector<double> below;  // times at which a stretch under the range begins
    bool was_below = false;
    for (const auto& p : samples) {
      const double v = p.y();
      const bool under = !(v > 0.0) || std::log10(v) < double(range.lo);
      if (under && !was_below) below.push_back(p.x());
      was_below = under;
      points.emplace_back(p.x(), under ? double(range.lo) : std::min(std::log10(v), range.hi));
    }
    const glm::vec4 colour = to_glm(c.colours[std::min(i + 1, c.colours.size() - 1)]);
    // In the run's line style too, as on the sphere and the plane.
    const scene::LineStyle line = i + 1 < c.lines.size() ? c.lines[i + 1] : scene::LineStyle::solid;
    std::vector<glm::vec2> pixels;
    for (const auto& p : points) pixels.push_back(plot.to_pixel(p));
    const float width = 1.4f * px;
    for (const auto& s : dash_spans(pixels, dash_pattern(line, width, false))) {
      const auto piece = span_vertices<glm::dvec2>(
          points, s, [](const glm::dvec2& a, const glm::dvec2& b, float f) {
            return a + (b - a) * double(f);
          });
      plot.draw_polyline(flat, piece, std::span(&colour, 1), width);
    }
    // Where the run is below the range (zero: the runs agree to the last
    // bit): a small arrow down on the bottom edge, in the run's colour.
    for (double t : below) {
      const glm::vec2 at = plot.to_pixel({t, double(range.lo)});
      const float a = 3.0f * px;
      const glm::vec3 arrow[] = {
          {at.x - a, at.y - a, 0.0f}, {at.x, at.y, 0.0f}, {at.x + a, at.y - a, 0.0f}};
      flat.add_polyline(arrow, colour, 1.2f * px);
    }
  }
}

}  // namespace epviz::paint
