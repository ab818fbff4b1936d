#include "paint/separation_chart.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "paint/dash_pattern.hpp"
#include "paint/figure_common.hpp"
#include "paint/painter_common.hpp"
#include "physics/notation.hpp"
#include "render/panel_2d.hpp"

namespace epviz::paint {
namespace {

// Separations below this are shown at it: identical runs (zero) stay on the chart.
constexpr double kFloor = 1e-16;

}  // namespace

void draw_separation_chart(render::DrawList& flat, const scene::Comparison& c,
                           const scene::Rect& area, const scene::Theme& ink, float px,
                           const std::function<glm::vec2(const std::string&)>& measure) {
  if (area.width < 40 || area.height < 30 || c.others.empty()) return;
  // Log scale: from the smallest separation drawn (a decade below) to |Δγ| = 2.
  double lo = 0.0;
  for (const auto& run : c.others)
    for (const auto& p : run.separation)
      lo = std::min(lo, std::floor(std::log10(std::max(double(p.y()), kFloor))));
  lo = std::max(std::min(lo, -3.0), std::log10(kFloor));
  const double hi = std::log10(2.0);
  // The title above, the time axis's labels below.
  const int title_px = int(14 * px), ticks_px = int(14 * px);
  const render::Viewport plot_area{area.x, area.y + title_px, area.width,
                                   std::max(10, area.height - title_px - ticks_px)};
  const render::Panel2D plot(plot_area, {0.0, std::max(c.t_end, 1e-9), lo, hi}, false);
  render::PanelStyle style;
  style.background = to_glm(ink.panel_background);
  style.frame = to_glm(ink.panel_frame);
  style.grid = to_glm(ink.panel_grid);
  style.axis = {0, 0, 0, 0};
  style.text = to_glm(ink.panel_text);
  style.tick_length = 3.0f * px;
  style.frame_width = 1.0f * px;
  style.tick_count = 4;
  style.min_tick_spacing_px = 12.0f * px;
  draw_axes_in_print(plot, flat, style);
  for (std::size_t i = 0; i < c.others.size(); ++i) {
    const auto& sep = c.others[i].separation;
    std::vector<glm::dvec2> points;
    points.reserve(sep.size());
    for (const auto& p : sep)
      points.emplace_back(p.x(), std::log10(std::max(double(p.y()), kFloor)));
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
  }
  // |Δγ|, the distance of a run's γ from run 1's, on a log scale; what Δγ is where there is room.
  const std::string title = "log₁₀ " + std::string(physics::symbol::separation) + " over t";
  const std::string gamma(physics::symbol::gamma);
  const std::string defined = title + ",  Δ" + gamma + " = " + gamma + " − " + gamma + " of run 1";
  flat.add_text({{float(area.x), float(area.y), 0.0f},
                 measure(defined).x <= float(area.width) ? defined : title,
                 style.text,
                 render::TextAnchor::top_left});
}

}  // namespace epviz::paint
