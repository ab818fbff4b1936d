#include "vector/cairo_painter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/gui_overlay.hpp"
#include "vector/raster_layer.hpp"

namespace epviz::vector {
namespace {

void set_colour(cairo_t* cr, const glm::vec4& c) {
  cairo_set_source_rgba(cr, double(c.r), double(c.g), double(c.b), double(c.a));
}

// Consecutive triangles of one colour are filled as one path: the two halves
// of a rectangle (or a translucent band) then show no seam and no overlap.
void fill_triangles(cairo_t* cr, const render::DrawList& list) {
  const auto& v = list.triangles();
  std::size_t i = 0;
  while (i + 2 < v.size()) {
    const glm::vec4 colour = v[i].colour;
    cairo_new_path(cr);
    for (; i + 2 < v.size() && v[i].colour == colour; i += 3) {
      cairo_move_to(cr, v[i].position.x, v[i].position.y);
      cairo_line_to(cr, v[i + 1].position.x, v[i + 1].position.y);
      cairo_line_to(cr, v[i + 2].position.x, v[i + 2].position.y);
      cairo_close_path(cr);
    }
    set_colour(cr, colour);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    if (colour.a < 1.0f) {
      cairo_fill(cr);
      continue;
    }
    // Opaque fills that touch (the cells of a large heat map) show hairline
    // seams where a rasteriser antialiases both edges, at some zooms; a
    // quarter pixel of their own colour around each mostly closes them.
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 0.5);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
    cairo_stroke(cr);
  }
}

// Square dots (the renderer's GL points), consecutive ones of one colour as
// one path, after the triangles as the renderer draws them.
void fill_dots(cairo_t* cr, const render::DrawList& list) {
  const auto& v = list.dot_vertices();
  for (const auto& range : list.dots()) {
    const double half = 0.5 * double(range.size_px);
    for (std::size_t i = range.first, end = range.first + range.count; i < end;) {
      const glm::vec4 colour = v[i].colour;
      cairo_new_path(cr);
      for (; i < end && v[i].colour == colour; ++i)
        cairo_rectangle(cr, v[i].position.x - half, v[i].position.y - half, range.size_px,
                        range.size_px);
      set_colour(cr, colour);
      cairo_fill(cr);
    }
  }
}

// A segment whose ends differ in colour, as the GL line shader blends them:
// a linear gradient from one end's colour to the other's.
void stroke_blended_segment(cairo_t* cr, const render::LineVertex& a, const render::LineVertex& b) {
  cairo_pattern_t* gradient =
      cairo_pattern_create_linear(a.position.x, a.position.y, b.position.x, b.position.y);
  cairo_pattern_add_color_stop_rgba(gradient, 0.0, a.colour.r, a.colour.g, a.colour.b, a.colour.a);
  cairo_pattern_add_color_stop_rgba(gradient, 1.0, b.colour.r, b.colour.g, b.colour.b, b.colour.a);
  cairo_new_path(cr);
  cairo_move_to(cr, a.position.x, a.position.y);
  cairo_line_to(cr, b.position.x, b.position.y);
  cairo_set_source(cr, gradient);
  cairo_stroke(cr);
  cairo_pattern_destroy(gradient);
}

void stroke_polylines(cairo_t* cr, const render::DrawList& list) {
  const auto& v = list.line_vertices();
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  for (const auto& p : list.polylines()) {
    const bool one_colour =
        std::all_of(v.begin() + long(p.first), v.begin() + long(p.first + p.count),
                    [&](const render::LineVertex& x) { return x.colour == v[p.first].colour; });
    if (!one_colour) {
      // A path coloured along its length (a trail by time): segment by segment.
      cairo_set_line_width(cr, p.width_px);
      for (std::size_t k = 0; k + 1 < p.count; ++k)
        stroke_blended_segment(cr, v[p.first + k], v[p.first + k + 1]);
      if (p.closed && p.count > 2) stroke_blended_segment(cr, v[p.first + p.count - 1], v[p.first]);
      continue;
    }
    cairo_new_path(cr);
    for (std::size_t k = 0; k < p.count; ++k) {
      const glm::vec3& at = v[p.first + k].position;
      if (k == 0)
        cairo_move_to(cr, at.x, at.y);
      else
        cairo_line_to(cr, at.x, at.y);
    }
    if (p.closed) cairo_close_path(cr);
    set_colour(cr, v[p.first].colour);
    cairo_set_line_width(cr, p.width_px);
    cairo_stroke(cr);
  }
}

// Opaque markers without outline (a scatter's dots) of one fill and size are
// filled as one path, consecutive ones together: the same picture as one by
// one, since a later dot covers an earlier one of its colour just the same,
// in a fraction of the file.
bool joins(const render::Marker& a, const render::Marker& b) {
  return a.outline_px <= 0.0f && a.fill.a >= 1.0f && b.outline_px <= 0.0f && a.fill == b.fill &&
         a.radius_px == b.radius_px;
}

void draw_markers(cairo_t* cr, const render::DrawList& list) {
  const auto& markers = list.markers();
  for (std::size_t i = 0; i < markers.size();) {
    const auto& m = markers[i];
    if (i + 1 < markers.size() && joins(m, markers[i + 1])) {
      cairo_new_path(cr);
      for (; i < markers.size() && joins(m, markers[i]); ++i) {
        const auto& at = markers[i].position;
        cairo_new_sub_path(cr);
        cairo_arc(cr, at.x, at.y, m.radius_px, 0.0, 2.0 * std::numbers::pi);
      }
      set_colour(cr, m.fill);
      cairo_fill(cr);
      continue;
    }
    ++i;
    // radius_px is the outer radius, outline included.
    const double r = m.radius_px, w = m.outline_px;
    cairo_new_path(cr);
    cairo_arc(cr, m.position.x, m.position.y, r - w * 0.5, 0.0, 2.0 * std::numbers::pi);
    set_colour(cr, m.fill);
    if (w > 0.0) {
      cairo_fill_preserve(cr);
      set_colour(cr, m.outline);
      cairo_set_line_width(cr, w);
      cairo_stroke(cr);
    } else {
      cairo_fill(cr);
    }
  }
}

void draw_text(cairo_t* cr, const render::TextLabel& label, const CairoFont& font) {
  if (label.text.empty()) return;
  const glm::vec2 size{font.width(label.text), font.px()};
  const glm::vec2 corner =
      render::anchored_top_left(glm::vec2(label.position) + label.offset_px, size, label.anchor);
  // Whole pixels, as the overlay places labels.
  const glm::vec2 at{std::round(corner.x), std::round(corner.y)};
  if (label.background.a > 0.0f) {
    const float pad = 3.0f;
    cairo_rectangle(cr, at.x - pad, at.y - pad + 1.0f, size.x + 2.0f * pad,
                    size.y + 2.0f * pad - 2.0f);
    set_colour(cr, label.background);
    cairo_fill(cr);
  }
  set_colour(cr, label.colour);
  cairo_move_to(cr, at.x, at.y + font.baseline());
  cairo_show_text(cr, label.text.c_str());
}

}  // namespace

void paint_drawing(cairo_t* cr, const paint::FigureDrawing& drawing, const CairoFont& font) {
  set_colour(cr, paint::kPaper);
  cairo_paint(cr);
  for (const auto& layer : drawing.layers) {
    cairo_save(cr);
    if (layer.clip) {
      const auto& c = *layer.clip;
      cairo_rectangle(cr, c.x, c.y, c.width, c.height);
      cairo_clip(cr);
    }
    if (drawn_as_image(layer.list))
      paint_as_image(cr, layer.list,
                     layer.clip.value_or(render::Viewport{0, 0, drawing.width, drawing.height}));
    else
      paint_shapes(cr, layer.list);
    cairo_restore(cr);
  }
  for (const auto& layer : drawing.layers) paint_labels(cr, layer.list, font);
}

void paint_shapes(cairo_t* cr, const render::DrawList& list) {
  paint_fills_and_lines(cr, list);
  draw_markers(cr, list);
}

void paint_fills_and_lines(cairo_t* cr, const render::DrawList& list) {
  fill_triangles(cr, list);
  fill_dots(cr, list);
  stroke_polylines(cr, list);
}

void paint_labels(cairo_t* cr, const render::DrawList& list, const CairoFont& font) {
  font.select(cr);
  for (const auto& label : list.labels()) draw_text(cr, label, font);
}

}  // namespace epviz::vector
