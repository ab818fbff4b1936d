#pragma once
// A figure laid out and drawn as plain data, before any backend paints it:
// the chart, heat map and table painters compute their layouts and fill draw
// lists here once, and two backends paint the result, the GL renderer into a
// PNG (figure_painter.hpp) and cairo into SVG or PDF (vector/), so that both
// files of one figure have the same axes, ticks, legend, cells and text.
// No GL here.
//
// How a backend paints a drawing (the GL renderer's order, which the others
// copy): paper, then layer after layer its fills (triangles), lines
// (polylines) and round markers, in that order, clipped to the layer's clip;
// then the text of every layer, in order, over everything and unclipped.
#include <optional>
#include <vector>

#include "paint/figure_common.hpp"
#include "render/camera.hpp"
#include "render/draw_list.hpp"

namespace epviz::paint {

struct FigureLayer {
  render::DrawList list;
  std::optional<render::Viewport> clip;  // image pixels; none: the whole picture
};

struct FigureDrawing {
  // The picture's size, which may differ from the options' (a chart grows
  // downwards for a long legend, a heat map shrinks to its grid, a table
  // grows for its rows).
  int width = 0;
  int height = 0;
  std::vector<FigureLayer> layers;
};

// Each figure with its labels measured in `font` (whose size must be
// chart_font_px(options), or 13 for the built-in font).
FigureDrawing draw_chart(const ChartSpec& spec, const ChartOptions& options, const ChartFont& font);
// `fit_grid`: the picture no taller than the grid needs.
FigureDrawing draw_heat_map(const HeatMapSpec& spec, const ChartOptions& options,
                            const ChartFont& font, bool fit_grid);
// Rows that do not fit options.height are left out and counted under the last rule.
FigureDrawing draw_table(const TableSpec& spec, const ChartOptions& options, const ChartFont& font);
// A figure of any kind as a file holds it: a heat map fitted to its grid, a
// table tall enough for all its rows.
FigureDrawing draw_figure(const Figure& figure, const ChartOptions& options, const ChartFont& font);

}  // namespace epviz::paint
