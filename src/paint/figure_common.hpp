#pragma once
// What the figure painters (chart, table, heat map) share: the options, the
// labels' font as their layouts measure it, the page's colours, axis ranges
// and ticks. No GL here: the GL painter (figure_painter.hpp) and the vector
// painter (vector/) draw the same layouts.
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "chart/chart_spec.hpp"
#include "render/draw_list.hpp"
#include "render/panel_2d.hpp"

namespace epviz::paint {

// The painters' input types are plain data from chart/chart_spec.hpp.
using chart::ChartPoint;
using chart::ChartSeries;
using chart::ChartSpec;
using chart::Figure;
using chart::HeatMapSpec;
using chart::TableSpec;

struct ChartOptions {
  int width = 1280;
  int height = 800;
  int msaa_samples = 4;
  // ImGui's built-in 13 px font (snapshot tests), else the overlay's TTF at a
  // size that follows the picture's height.
  bool builtin_font = false;
  float font_px = 0.0f;  // > 0: this TTF size whatever the height
  // Points of an SVG or PDF page per unit of the layout: 1 draws a unit per
  // point (the page as many points as the PNG has pixels); a figure of a
  // printed size (io/print_size.hpp) lays out in 1/dpi inch and sets 72/dpi,
  // so that the page is as wide as asked and its text the size asked.
  double page_pt_per_unit = 1.0;
  // The width of the thinnest lines (grid, ticks, frames, rules) in units:
  // a pixel on screen; at a printed size half a point, so that they show in print.
  float thin_line = 1.0f;
  // A heat map as tall as its grid needs for a line of text per row (every
  // row named, each cell's value legible) rather than the height above: a
  // figure at a printed size, whose height follows its width.
  bool grid_rows_of_text = false;
};

// The font size the painters use for a picture of this height.
float chart_font_px(const ChartOptions& options);

// The labels' font as a layout needs it: the height of a line of text, and
// how wide a text is drawn, measured on the font the labels are drawn with
// (the GL painter's overlay, or cairo for vector files).
struct ChartFont {
  float px = 13.0f;
  std::function<float(const std::string&)> width;
};

// Numbers as print sets them, the one formatter of the figures' tick labels
// and chart text (GL and vector painters alike): a minus sign (U+2212, not
// the hyphen) and powers of ten in superscripts ("10⁻⁸", not "1e-8").
// `exponent` as a power of ten: "10⁻⁸", "10⁰", "10³".
std::string power_of_ten(int exponent);
// The log10 decade labels: power_of_ten, every decade alike.
std::string decade_label(int exponent);
// `text` with each hyphen that stands for a minus (before a digit or a
// decimal point) made a minus sign; other hyphens ("Gauss-4") kept.
std::string print_minus(std::string text);
// `value` to `significant` digits ("%g"-style), in print: "−0.25", and
// "2.6×10⁻⁴" where "%g" would write an exponent.
std::string print_number(double value, int significant = 3);
// `value` always in scientific form with `decimals` decimals, in print:
// "2.6×10⁻⁴" (a table's column of drifts); "nan" for NaN.
std::string print_scientific(double value, int decimals = 1);

// --- For the painters' own files -------------------------------------------------

inline const glm::vec4 kPaper{1.0f, 1.0f, 1.0f, 1.0f};
inline const glm::vec4 kInk{0.10f, 0.10f, 0.12f, 1.0f};
inline const glm::vec4 kFrame{0.20f, 0.20f, 0.22f, 1.0f};
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The range of the finite values added.
struct Span {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v);
  bool empty() const { return !(lo <= hi); }
};
// Whole decades on a log axis, a padded range with nice ends on a linear one.
void finish_span(Span& s, bool log_axis);

struct Tick {
  double at;          // plotted units
  std::string label;  // empty for minor ticks
  bool major;
};
// Ticks over [lo, hi] in plotted units (log10 on a log axis), at most
// `max_labels` of them labelled.
std::vector<Tick> axis_ticks(double lo, double hi, bool log_axis, int max_labels);

// plot.draw_axes into `list`, its tick labels in print (print_minus): the
// panels of frames (the plane, the separation chart, sections) read as the
// charts do.
void draw_axes_in_print(const render::Panel2D& plot, render::DrawList& list,
                        const render::PanelStyle& style);

render::TextLabel label(glm::vec2 at, std::string text, render::TextAnchor anchor,
                        glm::vec4 colour = kInk);

// Characters a long word may be broken after: "_", "-", "+", ",", "/".
bool is_soft_break(char c);
// `text` in lines no wider than `max_width` as `font` measures them, broken
// at spaces, and a word wider than a line after one of its soft breaks
// (is_soft_break), else between its characters (a narrow figure at a
// printed size: a table's cell, a note, a legend's name).
// One line, `text` itself, when it fits; none for "".
std::vector<std::string> wrap_text(const std::string& text, const ChartFont& font, float max_width);

}  // namespace epviz::paint
