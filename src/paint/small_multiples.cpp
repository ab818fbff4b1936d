#include "paint/small_multiples.hpp"

#include <algorithm>
#include <cmath>

#include "paint/figure_panels.hpp"

namespace epviz::paint {
namespace {

// Whether a point can be drawn on the chart's axes (a log axis shows only
// values above 0).
bool drawable(const ChartPoint& p, const ChartSpec& spec) {
  return std::isfinite(p.x) && std::isfinite(p.y) && (!spec.log_x || p.x > 0.0) &&
         (!spec.log_y || p.y > 0.0);
}

// The lower-left and upper-right corners of every panel's drawable points.
std::vector<ChartPoint> shared_extent(const ChartSpec& spec) {
  Span x, y;
  for (const auto& panel : spec.panels) {
    const auto add = [&](const ChartPoint& p) {
      if (!drawable(p, panel)) return;
      x.add(p.x);
      y.add(p.y);
    };
    for (const auto& s : panel.series)
      for (const auto& p : s.points) add(p);
    for (const auto& p : panel.axis_extent) add(p);
  }
  if (x.empty()) return {};
  return {{x.lo, y.lo}, {x.hi, y.hi}};
}

}  // namespace

FigureDrawing draw_small_multiples(const ChartSpec& spec, const ChartOptions& options,
                                   const ChartFont& font) {
  const int n = int(spec.panels.size());
  const int columns = std::clamp(spec.panel_columns, 1, n);
  const int rows = (n + columns - 1) / columns;
  const int title_h = spec.title.empty() ? 0 : int(std::ceil(font.px * 2.2f));
  ChartOptions cell = options;
  cell.width = options.width / columns;
  // Tall enough for a panel's legend beside a readable plot, whatever the rows.
  cell.height = std::max((options.height - title_h) / rows, int(std::ceil(font.px * 20.0f)));
  const auto extent = shared_extent(spec);

  std::vector<FigureDrawing> lines;
  FigureDrawing title{options.width, title_h, {}};
  if (!spec.title.empty()) {
    render::DrawList text;
    text.add_text(
        label({float(options.width) * 0.5f, font.px * 0.6f}, spec.title, render::TextAnchor::top));
    title.layers.push_back({std::move(text), std::nullopt});
  }
  lines.push_back(std::move(title));
  for (int r = 0; r < rows; ++r) {
    std::vector<FigureDrawing> row;
    for (int c = 0; c < columns && r * columns + c < n; ++c) {
      ChartSpec panel = spec.panels[std::size_t(r * columns + c)];
      panel.axis_extent.insert(panel.axis_extent.end(), extent.begin(), extent.end());
      row.push_back(draw_chart(panel, cell, font));
    }
    lines.push_back(side_by_side(row, 0));
  }
  FigureDrawing drawing = stacked(lines, 0);
  drawing.width = options.width;
  return drawing;
}

}  // namespace epviz::paint
