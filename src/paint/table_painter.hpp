#pragma once
// Table figures for papers: a title, a header between two rules, rows with
// alternate shading, columns as wide as their longest cell (where the table
// is wider than the picture, the widest narrowed alike and their cells
// wrapped onto more lines).
#include "paint/figure_common.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"

namespace epviz::paint {

// Renders a table (draw_table in figure_drawing.hpp) with GL; `context` must be
// current (any size). Rows that do not fit the picture's height are left out
// and counted under the last rule.
render::RgbaImage paint_table(render::GlContext& context, const TableSpec& spec,
                              const ChartOptions& options = {});

// The picture's height that shows every row of `spec` at options.width,
// wrapped cells included (draw_figure makes a table's file this tall).
int table_height(const TableSpec& spec, const ChartOptions& options, const ChartFont& font);

}  // namespace epviz::paint
