#pragma once
// A figure of any kind (chart, table, heat map) painted with the GL renderer
// into pixels: its drawing (figure_drawing.hpp) with the labels measured on
// the overlay's font.
#include <functional>

#include "paint/figure_common.hpp"
#include "paint/figure_drawing.hpp"
#include "render/gl_context.hpp"
#include "render/gui_overlay.hpp"
#include "render/image.hpp"
#include "render/renderer.hpp"

namespace epviz::paint {

// `context` must be current (any size). A table is drawn taller than
// options.height when its rows need it, a heat map as tall as its grid needs
// (at most options.height).
render::RgbaImage paint_figure(render::GlContext& context, const Figure& figure,
                               const ChartOptions& options = {});

// The font `overlay` draws labels with; the overlay must outlive the result.
ChartFont chart_font(const render::ImGuiOverlay& overlay);

// A renderer for a figure: light style, the options' font and size.
render::RendererOptions renderer_options(const ChartOptions& options);

// Paints what `draw` makes with the font of a renderer for `options`, at the
// drawing's size; what every figure painter of this module does.
render::RgbaImage paint_drawing(render::GlContext& context, const ChartOptions& options,
                                const std::function<FigureDrawing(const ChartFont&)>& draw);

}  // namespace epviz::paint
