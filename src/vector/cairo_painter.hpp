#pragma once
// Paints a figure's drawing (paint/figure_drawing.hpp) with cairo, in the GL
// renderer's order: paper; per layer its fills, lines and round markers,
// clipped to the layer; then all text, unclipped. Coordinates are the
// drawing's pixels, one to a unit of the cairo surface.
#include <cairo.h>

#include <cstddef>

#include "paint/figure_drawing.hpp"
#include "vector/cairo_font.hpp"

namespace epviz::vector {

//
// A layer of more than kMaxVectorShapes shapes (markers, triangles and
// polylines; a scatter of many thousand points) is painted as an image of
// kRasterScale pixels per unit over its clip, under the vector axes and
// text: as vectors it would make a file of hundreds of bytes a point, slow to
// open, for a picture no finer than that image (docs/figures.md).
constexpr std::size_t kMaxVectorShapes = 20000;
constexpr int kRasterScale = 2;
void paint_drawing(cairo_t* cr, const paint::FigureDrawing& drawing, const CairoFont& font);
// Whether paint_drawing paints a layer with this list as an image.
bool drawn_as_image(const render::DrawList& list);

// One list's fills, lines and markers, in that order (as the GL renderer
// draws a 2D list); and its text, which the renderer draws after all shapes.
void paint_shapes(cairo_t* cr, const render::DrawList& list);
void paint_labels(cairo_t* cr, const render::DrawList& list, const CairoFont& font);

}  // namespace epviz::vector
