#pragma once
// The frame painter's overlay window (title, lines, drift table and the key
// of its colours) drawn with cairo where the painter puts its ImGui window:
// the same box, the ImGui style's paddings, spacings and colours, the same
// texts, as text.
#include <cairo.h>

#include "paint/frame_painter.hpp"
#include "scene/frame.hpp"
#include "vector/cairo_font.hpp"

namespace epviz::vector {

// Draws the window of `frame` in `box` (painter.annotations().overlay_window
// after painting it); `painter` lends its overlay's style and drift key.
void draw_overlay_window(cairo_t* cr, paint::FramePainter& painter, const scene::Frame& frame,
                         const paint::Box& box, const CairoFont& font);

}  // namespace epviz::vector
