#pragma once
// A dense layer of a figure (a scatter of many thousand points) goes into an
// SVG or PDF as one image under the vector axes and text: as vectors it costs
// a path of some hundred bytes a point (390 MB for a million), slow to write
// and to open, for a picture no finer than an image at twice the figure's
// resolution (docs/figures.md, "Dense scatters").
//
// The image holds the layer's fills and lines drawn by cairo, then its round
// markers stamped pixel by pixel with the GL marker shader's disc
// (shaders/marker.frag: a fill, an outline ring, each edge faded over one
// pixel): cairo would take seconds to fill a million small circles.
#include <cstddef>

#include <cairo.h>

#include "render/camera.hpp"
#include "render/draw_list.hpp"

namespace epviz::vector {

// A layer of more shapes than this (markers, triangles, polylines) is an image.
constexpr std::size_t kMaxVectorShapes = 20000;
// The image's pixels per unit of the page (per pixel of the PNG).
constexpr int kRasterScale = 2;

bool drawn_as_image(const render::DrawList& list);

// Paints the list's shapes inside `box` (units of the page) as an image
// placed over the box. Throws std::runtime_error when cairo fails.
void paint_as_image(cairo_t* cr, const render::DrawList& list, const render::Viewport& box);

}  // namespace epviz::vector
