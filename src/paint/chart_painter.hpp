#pragma once
// Figures for papers, drawn with the render toolkit: a line chart (series as
// polylines with markers, optional log10 axes with decade and minor ticks, axis
// labels, a title and a legend) and a table figure. Input is plain data; the
// painter knows nothing of what the numbers mean.
//
//   auto context = render::make_gl_context("osmesa", 16, 16);  // size unused
//   render::RgbaImage img = paint::paint_chart(*context, spec, {.width = 1280, .height = 800});
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "chart/chart_spec.hpp"
#include "render/camera.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"
#include "render/panel_2d.hpp"

namespace epviz::paint {

// The painter's input types are plain data from chart/chart_spec.hpp.
using chart::ChartPoint;
using chart::ChartSeries;
using chart::ChartSpec;
using chart::Figure;
using chart::HeatMapSpec;
using chart::TableSpec;

struct ChartOptions {
  int width = 1280;
  int height = 800;
  int msaa_samples = 4;
  // ImGui's built-in 13 px font (snapshot tests), else the overlay's TTF at a
  // size that follows the picture's height.
  bool builtin_font = false;
  float font_px = 0.0f;  // > 0: this TTF size whatever the height
};

// The colour and marker of series i (colour-blind-safe palette, cycling).
enum class MarkerShape { circle, square, triangle_up, diamond, triangle_down, hexagon, cross };
constexpr std::size_t kSeriesColours = 16;
glm::vec4 series_colour(std::size_t index);
MarkerShape series_marker(std::size_t index);
// A series' colour and marker: by its keys where it has them, else by its index.
glm::vec4 colour_of(const ChartSeries& series, std::size_t index);
MarkerShape marker_of(const ChartSeries& series, std::size_t index);

// Where the plot goes and the data range it shows. Ranges on log axes are in
// log10 units (whole decades).
struct ChartLayout {
  render::Viewport plot_area;
  render::DataRange range;
  bool log_x = false;
  bool log_y = false;
  bool legend_outside = false;  // the legend sits right of the plot
  render::Viewport legend;      // the legend's box in image pixels
  // Image pixel of a data point (given unlogged); NaN for points a log axis cannot show.
  glm::vec2 to_pixel(double x, double y) const;
};
// The layout paint_chart uses for `spec` at width x height (text widths estimated from `font_px`).
ChartLayout chart_layout(const ChartSpec& spec, int width, int height, float font_px);
// The font size paint_chart uses for a picture of this height.
float chart_font_px(const ChartOptions& options);

// The log10 decade labels: "1" for 1e0, else "1e-8" style.
std::string decade_label(int exponent);

// Where a heat map's parts go: the cells (rows top to bottom, columns left to
// right), the vertical colour bar (low values at its bottom) and its range in
// plotted units (log10 of the values on a log scale; whole decades unless the
// spec fixes the range). Labels are thinned to every k-th column or row where
// they would overlap, and cells carry their value as text only where every
// value fits its cell.
struct HeatMapLayout {
  render::Viewport grid;
  std::vector<std::vector<render::Viewport>> cells;  // [row][column]
  render::Viewport colour_bar;
  double lo = 0.0, hi = 1.0;
  bool staggered_columns = false;  // column labels on two lines (they are wider than a cell)
  std::size_t column_stride = 1;   // every k-th column labelled (labels wider than two cells)
  std::size_t row_stride = 1;      // every k-th row labelled (rows lower than a line of text)
  bool value_text = true;          // each cell shows its value (and `missing`) as text
  bool missing_key = false;        // a key under the grid says what a grey cell means
  int natural_height = 0;          // the picture's height that fits the grid with no spare room
};
HeatMapLayout heat_map_layout(const HeatMapSpec& spec, int width, int height, float font_px);
// The colour of a cell holding `value` (nullopt: NaN, drawn as missing).
std::optional<glm::vec4> heat_map_colour(const HeatMapSpec& spec, const HeatMapLayout& layout,
                                         double value);

// Renders a chart or table figure; `context` must be current (any size).
render::RgbaImage paint_chart(render::GlContext& context, const ChartSpec& spec,
                              const ChartOptions& options = {});
render::RgbaImage paint_table(render::GlContext& context, const TableSpec& spec,
                              const ChartOptions& options = {});
render::RgbaImage paint_heat_map(render::GlContext& context, const HeatMapSpec& spec,
                                 const ChartOptions& options = {});
// Any of them; a table is drawn taller than options.height when its rows need
// it, a heat map as tall as its grid needs (at most options.height).
render::RgbaImage paint_figure(render::GlContext& context, const Figure& figure,
                               const ChartOptions& options = {});

}  // namespace epviz::paint
