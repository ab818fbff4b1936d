#pragma once
// Line charts and scatters for papers, drawn with the render toolkit: series
// as polylines with markers, markers alone or lines alone (their style,
// chart/chart_spec.hpp), optional log10 axes with decade and minor ticks, axis
// labels, a title and a legend. Input is plain data; the painter knows
// nothing of what the numbers mean.
//
//   auto context = render::make_gl_context("osmesa", 16, 16);  // size unused
//   render::RgbaImage img = paint::paint_chart(*context, spec, {.width = 1280, .height = 800});
#include <cstddef>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "paint/figure_common.hpp"
#include "render/camera.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"
#include "render/panel_2d.hpp"

namespace epviz::paint {

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
  bool legend_outside = false;     // the legend sits right of the plot, or under it:
  bool legend_below = false;       // a narrow picture (a printed column) puts it under the x label
  render::Viewport legend;         // the legend's box in image pixels
  float legend_name_width = 0.0f;  // > 0: the legend's names wrap to lines this wide
  // A legend under the plot with room across for more than one column of
  // rows: `legend_per_column` rows to a column, each column this wide.
  std::size_t legend_per_column = 0;  // 0: one column
  int legend_column_width = 0;
  // Points a log y axis cannot show (finite y <= 0, x on its axis): marked in
  // this row under the plot (height 0 when there are none), and counted in a
  // note under the x label (ChartSpec::nonpositive_label).
  render::Viewport nonpositive_row{0, 0, 0, 0};
  std::size_t nonpositive_points = 0;
  // Image pixel of a data point (given unlogged); NaN for points a log axis cannot show.
  glm::vec2 to_pixel(double x, double y) const;
};
// The layout paint_chart uses for `spec` at width x height with the labels in `font`.
ChartLayout chart_layout(const ChartSpec& spec, int width, int height, const ChartFont& font);

// Renders a chart (draw_chart in figure_drawing.hpp) with GL; `context` must be
// current (any size). The picture grows downwards when a legend beside the
// plot is taller than it, or by the legend's height when it goes under the plot.
render::RgbaImage paint_chart(render::GlContext& context, const ChartSpec& spec,
                              const ChartOptions& options = {});

}  // namespace epviz::paint
