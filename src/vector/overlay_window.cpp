#include "vector/overlay_window.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "paint/painter_common.hpp"
#include "render/gui_overlay.hpp"
#include "render/imgui_context_scope.hpp"
#include "scene/layout.hpp"
#include "scene/theme.hpp"

namespace epviz::vector {
namespace {

void set_imgui_colour(cairo_t* cr, const ImVec4& c) {
  cairo_set_source_rgba(cr, c.x, c.y, c.z, c.w);
}
ImVec4 to_imgui(const scene::Rgba& c) { return {c[0], c[1], c[2], c[3]}; }

void rounded_rectangle(cairo_t* cr, double x0, double y0, double x1, double y1, double r) {
  constexpr double quarter = std::numbers::pi / 2.0;
  r = std::min({r, (x1 - x0) / 2.0, (y1 - y0) / 2.0});
  cairo_new_path(cr);
  cairo_arc(cr, x1 - r, y0 + r, r, -quarter, 0.0);
  cairo_arc(cr, x1 - r, y1 - r, r, 0.0, quarter);
  cairo_arc(cr, x0 + r, y1 - r, r, quarter, 2.0 * quarter);
  cairo_arc(cr, x0 + r, y0 + r, r, 2.0 * quarter, 3.0 * quarter);
  cairo_close_path(cr);
}

// What the window takes from the overlay's ImGui style, in the theme's
// colours (as the painter gives them to its window).
struct WindowStyle {
  ImVec2 padding, spacing;
  float rounding = 0.0f, border = 0.0f;
  ImVec4 background, border_colour, text, text_disabled, separator;
};

WindowStyle window_style(paint::FramePainter& painter, const scene::Theme& ink) {
  render::ImGuiContextScope scope(painter.gui().context());
  const ImGuiStyle& st = ImGui::GetStyle();
  return {st.WindowPadding,
          st.ItemSpacing,
          st.WindowRounding,
          st.WindowBorderSize,
          to_imgui(ink.overlay_window),
          to_imgui(ink.overlay_border),
          to_imgui(ink.overlay_text),
          to_imgui(ink.overlay_heading),
          to_imgui(ink.overlay_border)};
}

// Lines of text from the window's top left, as ImGui lays out one item a line.
class TextCursor {
 public:
  TextCursor(cairo_t* cr, const CairoFont& font, ImVec2 at, float line_step)
      : cr_(cr), font_(font), left_(at.x), y_(at.y), step_(line_step) {}
  // `text` at `x` pixels right of the left edge on the current line; returns its width.
  float put(const std::string& text, const ImVec4& colour, float x = 0.0f) {
    set_imgui_colour(cr_, colour);
    cairo_move_to(cr_, std::floor(left_ + x), std::floor(y_) + font_.baseline());
    cairo_show_text(cr_, text.c_str());
    return font_.width(text);
  }
  void next_line() { y_ = std::floor(y_ + step_); }
  // Moves down by `pixels` (a separator's room) and returns where it was.
  float skip(float pixels) {
    const float at = y_;
    y_ = std::floor(y_ + pixels);
    return at;
  }

 private:
  cairo_t* cr_;
  const CairoFont& font_;
  float left_, y_, step_;
};

}  // namespace

void draw_overlay_window(cairo_t* cr, paint::FramePainter& painter, const scene::Frame& frame,
                         const paint::Box& box, const CairoFont& font) {
  const scene::Theme& ink = paint::ink_for(frame);
  const WindowStyle st = window_style(painter, ink);
  const scene::FrameLayout layout = paint::layout_for(frame, painter.width(), painter.height());
  // ImGui puts windows on whole pixels.
  const double x0 = std::floor(box.min.x), y0 = std::floor(box.min.y);
  const double x1 = x0 + std::floor(box.width()), y1 = y0 + std::floor(box.height());

  ImVec4 background = st.background;
  background.w = layout.overlay_in_column || !layout.view_3d ? ink.overlay_alpha_in_column
                                                             : ink.overlay_alpha_floating;
  rounded_rectangle(cr, x0, y0, x1, y1, st.rounding);
  set_imgui_colour(cr, background);
  cairo_fill(cr);
  if (st.border > 0.0f) {
    rounded_rectangle(cr, x0 + 0.5, y0 + 0.5, x1 - 0.5, y1 - 0.5, st.rounding);
    set_imgui_colour(cr, st.border_colour);
    cairo_set_line_width(cr, st.border);
    cairo_stroke(cr);
  }

  font.select(cr);
  TextCursor line(cr, font, ImVec2(float(x0) + st.padding.x, float(y0) + st.padding.y),
                  font.px() + st.spacing.y);
  line.put(frame.overlay.title, to_imgui(ink.title));
  line.next_line();
  const int shown = paint::overlay_lines_shown(frame.overlay, painter.height());
  for (int i = 0; i < shown; ++i) {
    line.put(frame.overlay.lines[std::size_t(i)], st.text);
    line.next_line();
  }
  if (frame.overlay.drifts.empty()) return;
  // The separator: one pixel across the window's inner clip, taking a spacing.
  const double y = line.skip(st.spacing.y) + 0.5;
  const double inset = std::max(std::floor(st.padding.x * 0.5f), st.border);
  cairo_move_to(cr, x0 + inset, y);
  cairo_line_to(cr, x1 - inset, y);
  set_imgui_colour(cr, st.separator);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  if (scene::overlay_drifts_in_one_line(painter.height())) {
    float x = 0.0f;
    for (const auto& piece : paint::FramePainter::drift_line(frame))
      x += line.put(piece.text,
                    piece.drift ? to_imgui(ink.drift_colour(*piece.drift)) : st.text_disabled, x);
    return;
  }
  // The painter's columns: the names, then the values where it puts them,
  // each headed by what it measures.
  const float values_x = painter.drift_table_values_x(frame);
  const float column_w = painter.drift_table_column_width();
  line.put(paint::FramePainter::drift_table_heading(frame), st.text_disabled);
  const auto columns = paint::FramePainter::drift_table_columns(frame);
  for (std::size_t c = 0; c < columns.size(); ++c)
    line.put(columns[c], st.text_disabled, values_x + float(c) * column_w);
  line.next_line();
  for (std::size_t row = 0; row < frame.overlay.drifts.size(); ++row) {
    line.put(frame.overlay.drifts[row].first, st.text);
    const auto values = paint::FramePainter::drift_table_row(frame, row);
    for (std::size_t c = 0; c < values.size(); ++c) {
      const double v = c == 0 ? frame.overlay.drifts[row].second : frame.overlay.step_drifts[row];
      line.put(values[c], to_imgui(ink.drift_colour(v)), values_x + float(c) * column_w);
    }
    line.next_line();
  }
  const auto key = paint::FramePainter::drift_table_key();
  const scene::Rgba* colours[] = {&ink.drift_ok, &ink.drift_warn, &ink.drift_bad};
  float x = 0.0f;
  for (std::size_t i = 0; i < key.size(); ++i) x += line.put(key[i], to_imgui(*colours[i]), x);
}

}  // namespace epviz::vector
