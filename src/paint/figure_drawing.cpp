#include "paint/figure_drawing.hpp"

#include <algorithm>
#include <cmath>

namespace epviz::paint {

FigureDrawing draw_figure(const Figure& figure, const ChartOptions& options,
                          const ChartFont& font) {
  if (const auto* chart = std::get_if<ChartSpec>(&figure.content))
    return draw_chart(*chart, options, font);
  if (const auto* heat = std::get_if<HeatMapSpec>(&figure.content))
    return draw_heat_map(*heat, options, font, true);
  const auto& table = std::get<TableSpec>(figure.content);
  ChartOptions o = options;
  // Tall enough for every row: a table shows n rows in n + 4.5 lines (its
  // margins, the title, the header, and the line it keeps for its note of
  // rows left out); the other 3.5 of these n + 8 lines are room to spare.
  const float line = font.px * 1.5f;
  o.height = std::max(o.height, int(std::ceil(line * float(table.rows.size() + 8))));
  return draw_table(table, o, font);
}

}  // namespace epviz::paint
