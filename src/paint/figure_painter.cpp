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
  if (const auto* heat = std::get_if<HeatMapSpec>(&figure.content)) {
    ChartOptions o = options;
    o.font_px = chart_font_px(options);
    o.height =
        std::min(o.height, heat_map_layout(*heat, o.width, o.height, o.font_px).natural_height);
    return paint_heat_map(context, *heat, o);
  }
  const auto& table = std::get<TableSpec>(figure.content);
  ChartOptions o = options;
  // Tall enough for every row: the title, the header, the rules and the
  // margins take five and a half lines (paint_table's layout); one more spare.
  o.font_px = chart_font_px(options);
  const float line = o.font_px * 1.5f;
  o.height = std::max(o.height, int(std::ceil(line * float(table.rows.size() + 8))));
  return paint_table(context, table, o);
}

}  // namespace epviz::paint
