#pragma once
// Paints a figure's drawing (paint/figure_drawing.hpp) with cairo, in the GL
// renderer's order: paper; per layer its fills, square dots, lines and round markers,
// clipped to the layer; then all text, unclipped. Coordinates are the
// drawing's pixels, one to a unit of the cairo surface.
#include <cairo.h>

#include "paint/figure_drawing.hpp"
#include "vector/cairo_font.hpp"

namespace epviz::vector {

// A dense layer (a scatter of many thousand points) is painted as an image
// (vector/raster_layer.hpp).
void paint_drawing(cairo_t* cr, const paint::FigureDrawing& drawing, const CairoFont& font);

// One list's fills, dots, lines and markers, in that order (as the GL renderer
// draws a 2D list); and its text, which the renderer draws after all shapes.
void paint_shapes(cairo_t* cr, const render::DrawList& list);
// paint_shapes without the markers.
void paint_fills_and_lines(cairo_t* cr, const render::DrawList& list);
void paint_labels(cairo_t* cr, const render::DrawList& list, const CairoFont& font);

}  // namespace epviz::vector
