#pragma once
// Heat maps for papers: a grid of cells coloured by value (linear or log10
// scale, optionally a fixed range), row and column labels, a colour bar, and
// each cell's value as text where every value fits its cell. Cells the spec
// marks undecided are hatched and labelled, unlike the grey of a missing value;
// values beyond a fixed range carry a triangle and are counted in a key.
#include <cstddef>
#include <optional>
#include <vector>

#include <glm/vec4.hpp>

#include "paint/figure_common.hpp"
#include "paint/grid_ticks.hpp"
#include "paint/heat_map_range.hpp"
#include "render/camera.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"

namespace epviz::paint {

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
  bool undecided_key = false;      // ... and what a hatched one means (HeatMapSpec::undecided)
  // Cells beyond the spec's fixed range (paint/heat_map_range.hpp), each
  // side with a key under the grid and a triangle at that end of the colour
  // bar, which is shortened by it (the bar's own range stays lo..hi).
  OutOfRangeCount beyond;
  int natural_height = 0;  // the picture's height that fits the grid with no spare room
  // The note under the grid in lines that fit the picture's width.
  std::vector<std::string> note_lines;
  // Numeric axes (the spec's column_values, row_values) of 8 cells or more:
  // labels at round values, none overlapping the one before; empty for an
  // axis of names or of fewer cells (labelled by the cells' own values).
  std::vector<GridTick> column_ticks, row_ticks;
};
// The layout paint_heat_map uses for `spec` at width x height with the labels in `font`.
HeatMapLayout heat_map_layout(const HeatMapSpec& spec, int width, int height,
                              const ChartFont& font);
// The colour of a cell holding `value` (nullopt: NaN, drawn as missing).
std::optional<glm::vec4> heat_map_colour(const HeatMapSpec& spec, const HeatMapLayout& layout,
                                         double value);

// Renders a heat map (draw_heat_map in figure_drawing.hpp) with GL; `context`
// must be current (any size).
render::RgbaImage paint_heat_map(render::GlContext& context, const HeatMapSpec& spec,
                                 const ChartOptions& options = {});
// The same, in a picture no taller than the grid needs (HeatMapLayout::natural_height),
// at most options.height: a figure's height.
render::RgbaImage paint_heat_map_fitted(render::GlContext& context, const HeatMapSpec& spec,
                                        const ChartOptions& options = {});

}  // namespace epviz::paint
