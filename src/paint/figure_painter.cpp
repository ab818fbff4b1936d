#include "paint/figure_painter.hpp"

#include <algorithm>
#include <cmath>

#include "paint/chart_painter.hpp"
#include "paint/heat_map_painter.hpp"
#include "paint/table_painter.hpp"

namespace epviz::paint {

render::RgbaImage paint_figure(render::GlContext& context, const Figure& figure,
                               const ChartOptions& options) {
  if (const auto* chart = std::get_if<ChartSpec>(&figure.content))
    return paint_chart(context, *chart, options);
  if (const auto* heat = std::get_if<HeatMapSpec>(&figure.content))
    return paint_heat_map_fitted(context, *heat, options);
  const auto& table = std::get<TableSpec>(figure.content);
  ChartOptions o = options;
  // Tall enough for every row: paint_table shows n rows in n + 4.5 lines
  // (its margins, the title, the header, and the line it keeps for its note
  // of rows left out); the other 3.5 of these n + 8 lines are room to spare.
  o.font_px = chart_font_px(options);
  const float line = o.font_px * 1.5f;
  o.height = std::max(o.height, int(std::ceil(line * float(table.rows.size() + 8))));
  return paint_table(context, table, o);
}

}  // namespace epviz::paint
