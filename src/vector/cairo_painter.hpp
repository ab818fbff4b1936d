#pragma once
// Paints a figure's drawing (paint/figure_drawing.hpp) with cairo, in the GL
// renderer's order: paper; per layer its fills, lines and round markers,
// clipped to the layer; then all text, unclipped. Coordinates are the
// drawing's pixels, one to a unit of the cairo surface.
#include <cairo.h>

#include "paint/figure_drawing.hpp"
#include "vector/cairo_font.hpp"

namespace epviz::vector {

void paint_drawing(cairo_t* cr, const paint::FigureDrawing& drawing, const CairoFont& font);

}  // namespace epviz::vector
