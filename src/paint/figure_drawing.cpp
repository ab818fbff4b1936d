#include "paint/figure_drawing.hpp"

#include <algorithm>
#include <cmath>

#include "paint/heat_map_painter.hpp"
#include "paint/table_painter.hpp"

namespace epviz::paint {

FigureDrawing draw_figure(const Figure& figure, const ChartOptions& options,
                          const ChartFont& font) {
  if (const auto* chart = std::get_if<ChartSpec>(&figure.content))
    return draw_chart(*chart, options, font);
  if (const auto* heat = std::get_if<HeatMapSpec>(&figure.content)) {
    ChartOptions o = options;
    if (o.grid_rows_of_text)
      o.height = std::max(o.height, heat_map_layout(*heat, o.width, o.height, font).natural_height);
    return draw_heat_map(*heat, o, font, true);
  }
  const auto& table = std::get<TableSpec>(figure.content);
  ChartOptions o = options;
  // Tall enough for every row, wrapped ones included (table_height).
  o.height = std::max(o.height, table_height(table, o, font));
  return draw_table(table, o, font);
}

}  // namespace epviz::paint
