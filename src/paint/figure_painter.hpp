#pragma once
// A figure of any kind (chart, table, heat map) drawn by its painter.
#include "paint/figure_common.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"

namespace epviz::paint {

// `context` must be current (any size). A table is drawn taller than
// options.height when its rows need it, a heat map as tall as its grid needs
// (at most options.height).
render::RgbaImage paint_figure(render::GlContext& context, const Figure& figure,
                               const ChartOptions& options = {});

}  // namespace epviz::paint
