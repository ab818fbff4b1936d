#include "paint/chart_painter.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "paint/figure_drawing.hpp"
#include "paint/small_multiples.hpp"
#include "render/draw_list.hpp"

namespace epviz::paint {
namespace {

using render::DrawList;
using render::TextAnchor;
using render::Viewport;

const glm::vec4 kGrid{0.0f, 0.0f, 0.0f, 0.10f};
const glm::vec4 kGridMinor{0.0f, 0.0f, 0.0f, 0.045f};

// A value on an axis in plotted units (log10 on a log axis); NaN when it cannot be shown.
double axis_value(double v, bool log_axis) {
  if (!std::isfinite(v)) return kNaN;
  if (log_axis) return v > 0.0 ? std::log10(v) : kNaN;
  return v;
}

// A marker's radius, and whether it has a darker outline (dots have none:
// on a dense scatter outlines would turn the points' colours dark).
struct MarkerLook {
  float radius = 0.0f;
  bool outlined = true;
};
MarkerLook marker_look(chart::MarkerSize size, float font_px) {
  if (size == chart::MarkerSize::dot) return {std::max(1.5f, font_px * 0.15f), false};
  return {std::max(3.5f, font_px * 0.3f), true};
}

void add_shape(DrawList& list, glm::vec2 c, MarkerShape shape, MarkerLook look,
               const glm::vec4& fill) {
  const float r = look.radius;
  const glm::vec4 outline{fill.r * 0.55f, fill.g * 0.55f, fill.b * 0.55f, 1.0f};
  if (shape == MarkerShape::circle) {
    render::Marker m;
    m.position = glm::vec3(c, 0.0f);
    m.fill = fill;
    m.outline = outline;
    m.radius_px = r;
    m.outline_px = look.outlined ? 1.0f : 0.0f;
    list.add_marker(m);
    return;
  }
  std::vector<glm::vec2> poly;
  switch (shape) {
    case MarkerShape::square: {
      const float h = r * 0.85f;
      poly = {{c.x - h, c.y - h}, {c.x + h, c.y - h}, {c.x + h, c.y + h}, {c.x - h, c.y + h}};
      break;
    }
    case MarkerShape::triangle_up:
      poly = {{c.x, c.y - r * 1.15f}, {c.x + r, c.y + r * 0.75f}, {c.x - r, c.y + r * 0.75f}};
      break;
    case MarkerShape::triangle_down:
      poly = {{c.x, c.y + r * 1.15f}, {c.x - r, c.y - r * 0.75f}, {c.x + r, c.y - r * 0.75f}};
      break;
    case MarkerShape::hexagon:
      for (int k = 0; k < 6; ++k) {
        const float a = float(k) * 1.0471976f;
        poly.emplace_back(c.x + r * std::cos(a), c.y + r * std::sin(a));
      }
      break;
    case MarkerShape::cross: {
      // Two strokes, no fill: reads apart from every filled shape.
      const float h = r * 0.9f, w = look.outlined ? std::max(2.0f, r * 0.45f) : r * 0.6f;
      list.add_line({c.x - h, c.y - h, 0}, {c.x + h, c.y + h, 0}, fill, w);
      list.add_line({c.x - h, c.y + h, 0}, {c.x + h, c.y - h, 0}, fill, w);
      return;
    }
    case MarkerShape::circle:  // drawn above as a round marker
    case MarkerShape::diamond:
      poly = {{c.x, c.y - r * 1.2f}, {c.x + r, c.y}, {c.x, c.y + r * 1.2f}, {c.x - r, c.y}};
      break;
  }
  std::vector<render::ColouredVertex> tris;
  for (std::size_t i = 1; i + 1 < poly.size(); ++i)
    for (const glm::vec2& p : {poly[0], poly[i], poly[i + 1]})
      tris.push_back({glm::vec3(p, 0.0f), fill});
  list.add_triangles(tris);
  if (!look.outlined) return;
  std::vector<glm::vec3> ring;
  for (const auto& p : poly) ring.emplace_back(p, 0.0f);
  list.add_polyline(ring, outline, 1.0f, true);
}

bool draws_line(const chart::ChartSeries& s) { return s.style != chart::SeriesStyle::markers; }
bool draws_markers(const chart::ChartSeries& s) { return s.style != chart::SeriesStyle::line; }

// The legend's rows, each showing what its series draw: a row per series,
// or (keyed legends) a row per colour, then a row per marker shape.
// `colour` < 0: grey; `line`: a line sample; `marker` < 0: no marker.
struct LegendRow {
  std::string name;
  int colour = -1;
  bool line = false;
  int marker = -1;
  chart::MarkerSize marker_size = chart::MarkerSize::normal;
  bool gap_before = false;  // half a line of space above (between the two key lists)
};
// Whether any point of `s` can be drawn on the chart's axes.
bool is_drawn(const chart::ChartSeries& s, const ChartSpec& spec) {
  return std::any_of(s.points.begin(), s.points.end(), [&](const chart::ChartPoint& p) {
    return std::isfinite(axis_value(p.x, spec.log_x)) && std::isfinite(axis_value(p.y, spec.log_y));
  });
}

// The legend names only what the chart shows: a series without a point on
// the axes (e.g. a method whose cost is counted in another unit) has no row,
// nor has a colour or marker key that no drawn series uses (a marker key
// counts only where its series draw markers). A keyed legend's colour row
// shows a line where a series of that colour draws one, else a marker; a
// marker row shows its shape at the size of the first series that draws it.
std::vector<LegendRow> legend_rows(const ChartSpec& spec) {
  std::vector<LegendRow> rows;
  const bool keyed = !spec.colour_legend.empty() || !spec.marker_legend.empty();
  // What the drawn series use: colour key -> whether any draws a line;
  // marker key -> the size of the first that draws that marker.
  std::vector<std::pair<int, bool>> colours;
  std::vector<std::pair<int, chart::MarkerSize>> markers;
  for (std::size_t i = 0; i < spec.series.size(); ++i) {
    const auto& s = spec.series[i];
    if (!is_drawn(s, spec)) continue;
    const int colour = s.colour_key >= 0 ? s.colour_key : int(i);
    const int marker = s.marker_key >= 0 ? s.marker_key : int(i);
    if (!keyed) {
      rows.push_back(
          {s.name, colour, draws_line(s), draws_markers(s) ? marker : -1, s.marker_size});
      continue;
    }
    const auto c = std::find_if(colours.begin(), colours.end(),
                                [&](const auto& k) { return k.first == colour; });
    if (c == colours.end())
      colours.emplace_back(colour, draws_line(s));
    else
      c->second = c->second || draws_line(s);
    if (draws_markers(s) && std::none_of(markers.begin(), markers.end(),
                                         [&](const auto& k) { return k.first == marker; }))
      markers.emplace_back(marker, s.marker_size);
  }
  if (!keyed) return rows;
  for (const auto& k : spec.colour_legend)
    for (const auto& [key, line] : colours)
      if (key == k.key) rows.push_back({k.name, key, line, line ? -1 : 0});
  bool first = true;
  for (const auto& k : spec.marker_legend)
    for (const auto& [key, size] : markers) {
      if (key != k.key) continue;
      rows.push_back({k.name, -1, false, key, size, first && !rows.empty()});
      first = false;
    }
  return rows;
}
// A legend row's name in lines: one, or wrapped to `name_width` when that is > 0.
std::vector<std::string> name_lines(const LegendRow& row, const ChartFont& font, float name_width) {
  if (name_width > 0.0f) return wrap_text(row.name, font, name_width);
  return {row.name};
}
// The legend's height, its rows in columns of `per_column` (0: one column;
// the half line of space before a row is left out at a column's top).
float legend_height(const std::vector<LegendRow>& rows, float line, const ChartFont& font,
                    float name_width = 0.0f, std::size_t per_column = 0) {
  float tallest = 0.0f, h = 0.0f;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const bool column_top = per_column > 0 && k % per_column == 0;
    if (column_top) h = 0.0f;
    h += line * (float(std::max<std::size_t>(1, name_lines(rows[k], font, name_width).size())) +
                 (rows[k].gap_before && !column_top ? 0.5f : 0.0f));
    tallest = std::max(tallest, h);
  }
  return font.px * 0.8f + tallest;
}
// The chart's title in lines no wider than the picture, less a character each side.
std::vector<std::string> chart_title_lines(const ChartSpec& spec, int width,
                                           const ChartFont& font) {
  return wrap_text(spec.title, font, float(width) - 2.0f * font.px);
}
// The legend's width besides its names: the line sample and the padding.
float legend_frame_width(float font_px) { return font_px * 4.4f; }

// Counts drawn points of the chart (vertices and samples along segments) inside a box.
int points_inside(const ChartSpec& spec, const ChartLayout& l, const Viewport& box) {
  auto in = [&](glm::vec2 p) {
    return p.x >= float(box.x) && p.x <= float(box.x + box.width) && p.y >= float(box.y) &&
           p.y <= float(box.y + box.height);
  };
  int n = 0;
  for (const auto& s : spec.series) {
    glm::vec2 prev{NAN, NAN};
    for (const auto& pt : s.points) {
      const glm::vec2 p = l.to_pixel(pt.x, pt.y);
      if (std::isnan(p.x) || std::isnan(p.y)) {
        prev = p;
        continue;
      }
      if (in(p)) n += 4;
      if (!std::isnan(prev.x) && draws_line(s))
        for (int k = 1; k < 16; ++k)
          if (in(prev + (p - prev) * (float(k) / 16.0f))) ++n;
      prev = p;
    }
  }
  return n;
}

// Points a log y axis cannot show though their x is on its axis: finite y <= 0.
bool off_log_y(const ChartSpec& spec, const ChartPoint& p) {
  return spec.log_y && std::isfinite(p.y) && p.y <= 0.0 &&
         std::isfinite(axis_value(p.x, spec.log_x));
}
std::size_t nonpositive_points(const ChartSpec& spec) {
  std::size_t n = 0;
  for (const auto& s : spec.series)
    for (const auto& p : s.points) n += off_log_y(spec, p);
  return n;
}
std::string nonpositive_label(const ChartSpec& spec) {
  return spec.nonpositive_label.empty() ? "≤ 0" : spec.nonpositive_label;
}
// Tall enough that the row's label, centred on it, stays clear of the lowest
// y tick label, centred on the plot's bottom edge just above.
int nonpositive_row_height(float font_px) { return int(std::ceil(font_px * 2.2f)); }
// The note under the x label that counts the points off the log axis, in
// lines from the plot's left edge `left` to a character short of the
// picture's right edge (a narrow figure at a printed size wraps it).
std::vector<std::string> nonpositive_note(const ChartSpec& spec, std::size_t n, int width, int left,
                                          const ChartFont& font) {
  return wrap_text(std::to_string(n) + (n == 1 ? " point" : " points") + " not on the log axis (" +
                       nonpositive_label(spec) + "): marked in the row under the plot",
                   font, std::max(font.px * 8.0f, float(width - left) - font.px));
}

}  // namespace

glm::vec4 series_colour(std::size_t index) {
  // Okabe & Ito's colour-blind-safe set (yellow left out: it fades on white),
  // then darker and muted tones that stay apart from them on white: enough
  // for every method of a chart to have its own colour.
  static const std::array<glm::vec4, kSeriesColours> colours{{
      {0.000f, 0.447f, 0.698f, 1.0f},  // blue
      {0.835f, 0.369f, 0.000f, 1.0f},  // vermillion
      {0.000f, 0.620f, 0.451f, 1.0f},  // bluish green
      {0.800f, 0.475f, 0.655f, 1.0f},  // reddish purple
      {0.902f, 0.624f, 0.000f, 1.0f},  // orange
      {0.337f, 0.706f, 0.914f, 1.0f},  // sky blue
      {0.15f, 0.15f, 0.15f, 1.0f},     // near black
      {0.533f, 0.133f, 0.333f, 1.0f},  // wine
      {0.600f, 0.600f, 0.200f, 1.0f},  // olive
      {0.200f, 0.133f, 0.533f, 1.0f},  // indigo
      {0.550f, 0.340f, 0.160f, 1.0f},  // brown
      {0.267f, 0.667f, 0.600f, 1.0f},  // teal
      {0.600f, 0.600f, 0.600f, 1.0f},  // grey
      {0.933f, 0.400f, 0.467f, 1.0f},  // rose
      {0.067f, 0.467f, 0.200f, 1.0f},  // dark green
      {0.498f, 0.235f, 0.553f, 1.0f},  // purple
  }};
  return colours[index % colours.size()];
}

MarkerShape series_marker(std::size_t index) {
  static const std::array<MarkerShape, 7> shapes{MarkerShape::circle,        MarkerShape::square,
                                                 MarkerShape::triangle_up,   MarkerShape::diamond,
                                                 MarkerShape::triangle_down, MarkerShape::hexagon,
                                                 MarkerShape::cross};
  // Shapes cycle on a different period from colours, so pairs stay distinct.
  return shapes[index % shapes.size()];
}

glm::vec4 colour_of(const ChartSeries& s, std::size_t index) {
  return series_colour(s.colour_key >= 0 ? std::size_t(s.colour_key) : index);
}
MarkerShape marker_of(const ChartSeries& s, std::size_t index) {
  return series_marker(s.marker_key >= 0 ? std::size_t(s.marker_key) : index);
}

glm::vec2 ChartLayout::to_pixel(double x, double y) const {
  const double ax = axis_value(x, log_x), ay = axis_value(y, log_y);
  if (std::isnan(ax) || std::isnan(ay)) return {NAN, NAN};
  const double fx = (ax - range.x_min) / (range.x_max - range.x_min);
  const double fy = (ay - range.y_min) / (range.y_max - range.y_min);
  return {float(plot_area.x + fx * plot_area.width),
          float(plot_area.y + (1.0 - fy) * plot_area.height)};
}

namespace {
ChartLayout chart_layout_without_row(const ChartSpec& spec, int width, int height,
                                     const ChartFont& font) {
  const float font_px = font.px;
  ChartLayout l;
  l.log_x = spec.log_x;
  l.log_y = spec.log_y;
  Span sx, sy;
  const auto take_in = [&](const ChartPoint& p) {
    const double ax = axis_value(p.x, spec.log_x), ay = axis_value(p.y, spec.log_y);
    if (std::isnan(ax) || std::isnan(ay)) return;
    sx.add(ax);
    sy.add(ay);
  };
  for (const auto& s : spec.series)
    for (const auto& p : s.points) take_in(p);
  for (const auto& p : spec.axis_extent) take_in(p);
  finish_span(sx, spec.log_x);
  finish_span(sy, spec.log_y);
  l.range = {sx.lo, sx.hi, sy.lo, sy.hi};

  l.nonpositive_points = nonpositive_points(spec);
  // Margins: y tick labels on the left, x tick labels and the x label below,
  // title and the y label (written horizontally above the axis) on top; and
  // for points a log y axis cannot show, their row between the plot and the
  // x tick labels, and a note line under the x label.
  float widest_y = 0.0f;
  for (const auto& t : axis_ticks(sy.lo, sy.hi, spec.log_y, 8))
    widest_y = std::max(widest_y, font.width(t.label));
  const int row_h = l.nonpositive_points > 0 ? nonpositive_row_height(font_px) : 0;
  if (row_h > 0) widest_y = std::max(widest_y, font.width(nonpositive_label(spec)));
  const float line = font_px * 1.35f;
  const int left = int(std::ceil(widest_y + font_px * 1.6f));
  const auto title = chart_title_lines(spec, width, font);
  const int top =
      int(std::ceil(font_px * 0.8f + (title.empty() ? 0.0f : line * (float(title.size()) + 0.3f)) +
                    (spec.y_label.empty() ? 0.0f : line)));
  const std::size_t note_lines =
      row_h > 0 ? nonpositive_note(spec, l.nonpositive_points, width, left, font).size() : 0;
  const int bottom =
      int(std::ceil(font_px * 0.9f + line + (spec.x_label.empty() ? 0.0f : line * 1.1f) +
                    (row_h > 0 ? float(row_h) + line * (0.1f + float(note_lines)) : 0.0f)));
  // Room on the right for half the last x tick label, which is centred on the
  // plot's right edge.
  float last_x_label = 0.0f;
  for (const auto& t : axis_ticks(sx.lo, sx.hi, spec.log_x, 10))
    if (!t.label.empty()) last_x_label = font.width(t.label);
  int right = int(std::ceil(std::max(font_px * 1.5f, 0.5f * last_x_label + font_px * 0.5f)));

  // Legend: a row per series (or per key), a line sample and marker, then the name.
  const auto rows = legend_rows(spec);
  float widest_name = 0.0f;
  for (const auto& r : rows) widest_name = std::max(widest_name, font.width(r.name));
  const int legend_w = int(std::ceil(legend_frame_width(font_px) + widest_name));
  const int legend_h = int(std::ceil(legend_height(rows, line, font)));
  l.plot_area = {left, top, width - left - right, height - top - bottom};
  if (spec.series.empty()) return l;

  const int pad = int(font_px * 0.6f);
  const Viewport& a = l.plot_area;
  const std::array<Viewport, 4> corners{{
      {a.x + a.width - legend_w - pad, a.y + pad, legend_w, legend_h},   // top right
      {a.x + pad, a.y + pad, legend_w, legend_h},                        // top left
      {a.x + pad, a.y + a.height - legend_h - pad, legend_w, legend_h},  // bottom left
      {a.x + a.width - legend_w - pad, a.y + a.height - legend_h - pad, legend_w, legend_h},
  }};
  const bool fits = legend_w + 2 * pad < a.width / 2 + a.width / 4 && legend_h + 2 * pad < a.height;
  if (fits)
    for (const auto& c : corners)
      if (points_inside(spec, l, c) == 0) {
        l.legend = c;
        return l;
      }
  // No free corner: the legend goes right of the plot, which narrows; but
  // not to under half the picture (a column's width at a printed size),
  // where it goes under the x label instead, its names wrapped to the width.
  l.legend_outside = true;
  const int beside_right = std::max(right, legend_w + pad * 2);
  if (width - left - beside_right >= width / 2) {
    l.plot_area = {left, top, width - left - beside_right, height - top - bottom};
    l.legend = {l.plot_area.x + l.plot_area.width + pad, l.plot_area.y, legend_w, legend_h};
    return l;
  }
  l.legend_below = true;
  const int below_w = std::min(legend_w, width - left - right);
  l.legend_name_width = float(below_w) - legend_frame_width(font_px);
  // A long list of short names (a work-precision chart's methods) in as
  // many columns as fit across, up to three, rather than one tall column.
  int below_width = below_w;
  const int columns = std::min(3, (width - left - right) / std::max(1, legend_w));
  if (columns > 1 && rows.size() > 4) {
    l.legend_per_column = (rows.size() + std::size_t(columns) - 1) / std::size_t(columns);
    l.legend_column_width = legend_w;
    below_width = legend_w * int((rows.size() + l.legend_per_column - 1) / l.legend_per_column);
  }
  const int below_h =
      int(std::ceil(legend_height(rows, line, font, l.legend_name_width, l.legend_per_column)));
  const int gap = pad;
  l.plot_area = {left, top, width - left - right,
                 std::max(1, height - top - bottom - below_h - gap)};
  l.legend = {left, l.plot_area.y + l.plot_area.height + bottom + gap, below_width, below_h};
  return l;
}

}  // namespace

ChartLayout chart_layout(const ChartSpec& spec, int width, int height, const ChartFont& font) {
  ChartLayout l = chart_layout_without_row(spec, width, height, font);
  // The row of points off the log axis lies right under the plot, wherever the plot went.
  if (l.nonpositive_points > 0)
    l.nonpositive_row = {l.plot_area.x, l.plot_area.y + l.plot_area.height, l.plot_area.width,
                         nonpositive_row_height(font.px)};
  return l;
}

FigureDrawing draw_chart(const ChartSpec& spec, const ChartOptions& requested,
                         const ChartFont& font) {
  if (!spec.panels.empty()) return draw_small_multiples(spec, requested, font);
  // Keep the requested font size, but grow the picture downwards when a long
  // legend (many series) would not fit beside the plot: nothing is cut off.
  ChartOptions options = requested;
  const float font_px = font.px;
  ChartLayout l = chart_layout(spec, options.width, options.height, font);
  const int legend_bottom = l.legend.y + l.legend.height + int(font_px);
  if (l.legend_below) {
    // The plot keeps the height it would have had without the legend.
    options.height += l.legend.height + int(font_px * 0.6f) + int(font_px);
    l = chart_layout(spec, options.width, options.height, font);
  } else if (l.legend_outside && legend_bottom > options.height) {
    options.height = legend_bottom;
    l = chart_layout(spec, options.width, options.height, font);
  }
  FigureDrawing drawing{options.width, options.height, {}};
  const Viewport& a = l.plot_area;
  const float line = font_px * 1.35f;
  const float tick = std::max(4.0f, font_px * 0.45f);
  const float stroke = std::max(1.5f, font_px * 0.14f);
  const float thin = options.thin_line;  // grid, ticks, frames

  DrawList axes;
  const float x0 = float(a.x), x1 = float(a.x + a.width), y0 = float(a.y),
              y1 = float(a.y + a.height);
  // The x tick labels' line: under the row of points off a log y axis, if any.
  const float under = y1 + float(l.nonpositive_row.height);
  auto px_x = [&](double v) {
    return float(a.x + (v - l.range.x_min) / (l.range.x_max - l.range.x_min) * a.width);
  };
  auto px_y = [&](double v) {
    return float(a.y + (1.0 - (v - l.range.y_min) / (l.range.y_max - l.range.y_min)) * a.height);
  };
  const int max_x_labels = std::clamp(int(float(a.width) / (font_px * 6.0f)), 2, 10);
  const int max_y_labels = std::clamp(int(float(a.height) / (font_px * 2.6f)), 2, 10);
  for (const auto& t : axis_ticks(l.range.x_min, l.range.x_max, l.log_x, max_x_labels)) {
    const float x = px_x(t.at);
    if (x < x0 - 0.5f || x > x1 + 0.5f) continue;
    axes.add_line({x, y0, 0}, {x, y1, 0}, t.major ? kGrid : kGridMinor, thin);
    const float len = t.major ? tick : tick * 0.55f;
    axes.add_line({x, y1, 0}, {x, y1 - len, 0}, kFrame, thin);
    axes.add_line({x, y0, 0}, {x, y0 + len, 0}, kFrame, thin);
    if (!t.label.empty())
      axes.add_text(label({x, under + font_px * 0.45f}, t.label, TextAnchor::top));
  }
  for (const auto& t : axis_ticks(l.range.y_min, l.range.y_max, l.log_y, max_y_labels)) {
    const float y = px_y(t.at);
    if (y < y0 - 0.5f || y > y1 + 0.5f) continue;
    axes.add_line({x0, y, 0}, {x1, y, 0}, t.major ? kGrid : kGridMinor, thin);
    const float len = t.major ? tick : tick * 0.55f;
    axes.add_line({x0, y, 0}, {x0 + len, y, 0}, kFrame, thin);
    axes.add_line({x1, y, 0}, {x1 - len, y, 0}, kFrame, thin);
    if (!t.label.empty())
      axes.add_text(label({x0 - font_px * 0.45f, y}, t.label, TextAnchor::right));
  }
  const std::vector<glm::vec3> frame{{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}};
  axes.add_polyline(frame, kFrame, 1.25f * thin, true);
  const auto title = chart_title_lines(spec, options.width, font);
  for (std::size_t i = 0; i < title.size(); ++i)
    axes.add_text(label({float(options.width) * 0.5f, font_px * 0.6f + line * float(i)}, title[i],
                        TextAnchor::top));
  if (!spec.y_label.empty())
    axes.add_text(label({x0, y0 - font_px * 0.5f}, spec.y_label, TextAnchor::bottom_left));
  if (!spec.x_label.empty())
    axes.add_text(
        label({(x0 + x1) * 0.5f, under + font_px * 0.45f + line}, spec.x_label, TextAnchor::top));
  if (l.nonpositive_points > 0) {
    const Viewport& r = l.nonpositive_row;
    const float ry0 = float(r.y), ry1 = float(r.y + r.height);
    const std::vector<glm::vec3> box{{x0, ry0, 0}, {x1, ry0, 0}, {x1, ry1, 0}, {x0, ry1, 0}};
    axes.add_polyline(box, kFrame, thin, true);
    axes.add_text(label({x0 - font_px * 0.45f, (ry0 + ry1) * 0.5f}, nonpositive_label(spec),
                        TextAnchor::right));
    const float note_y = under + font_px * 0.45f + line * (spec.x_label.empty() ? 1.0f : 2.1f);
    const auto note = nonpositive_note(spec, l.nonpositive_points, options.width, a.x, font);
    for (std::size_t i = 0; i < note.size(); ++i)
      axes.add_text(label({x0, note_y + line * float(i)}, note[i], TextAnchor::top_left,
                          {0.35f, 0.35f, 0.38f, 1.0f}));
  }
  drawing.layers.push_back({std::move(axes), std::nullopt});

  // Data, clipped to the plot area: lines first, then all markers on top.
  DrawList lines, markers;
  const float marker_r = marker_look(chart::MarkerSize::normal, font_px).radius;
  for (std::size_t i = 0; i < spec.series.size(); ++i) {
    const auto& s = spec.series[i];
    const glm::vec4 colour = colour_of(s, i);
    const MarkerShape shape = marker_of(s, i);
    const MarkerLook look = marker_look(s.marker_size, font_px);
    // Lines and markers at every point (a short series, a scatter), or a
    // dozen markers, evenly spaced, along a long line (a time series).
    const bool joined = draws_line(s);
    const bool every_point =
        s.style == chart::SeriesStyle::markers ||
        (s.style == chart::SeriesStyle::lines_and_markers && s.points.size() <= 60);
    std::vector<glm::vec3> run;
    auto flush = [&] {
      if (run.size() >= 2) lines.add_polyline(run, colour, stroke);
      run.clear();
    };
    for (const auto& p : s.points) {
      const glm::vec2 q = l.to_pixel(p.x, p.y);
      if (std::isnan(q.x) || std::isnan(q.y)) {
        flush();
        continue;
      }
      if (joined) run.emplace_back(q, 0.0f);
      if (every_point) add_shape(markers, q, shape, look, colour);
    }
    flush();
    if (s.style == chart::SeriesStyle::lines_and_markers && !every_point) {
      const std::size_t every = s.points.size() / 12 + 1;
      for (std::size_t k = every / 2; k < s.points.size(); k += every) {
        const glm::vec2 q = l.to_pixel(s.points[k].x, s.points[k].y);
        if (!std::isnan(q.x) && !std::isnan(q.y)) add_shape(markers, q, shape, look, colour);
      }
    }
  }
  // Points off the log y axis: their series' marker in the row under the
  // plot, at their x (a series drawn as a line alone gets its first shape).
  if (l.nonpositive_points > 0) {
    const float cy = float(l.nonpositive_row.y) + float(l.nonpositive_row.height) * 0.5f;
    for (std::size_t i = 0; i < spec.series.size(); ++i)
      for (const auto& p : spec.series[i].points)
        if (off_log_y(spec, p)) {
          const double fx =
              (axis_value(p.x, l.log_x) - l.range.x_min) / (l.range.x_max - l.range.x_min);
          add_shape(markers, {float(a.x + fx * a.width), cy}, marker_of(spec.series[i], i),
                    marker_look(spec.series[i].marker_size, font_px), colour_of(spec.series[i], i));
        }
  }
  drawing.layers.push_back({std::move(lines), a});
  // (Reaching down over the row of points off the log axis.)
  const Viewport marker_clip = a.inset(-int(marker_r) - 2, -int(marker_r) - 2, -int(marker_r) - 2,
                                       -int(marker_r) - 2 - l.nonpositive_row.height);
  drawing.layers.push_back({std::move(markers), marker_clip});

  if (!spec.series.empty()) {
    DrawList legend;
    const Viewport& b = l.legend;
    legend.add_rect({float(b.x), float(b.y)}, {float(b.x + b.width), float(b.y + b.height)},
                    {1.0f, 1.0f, 1.0f, 0.92f});
    const std::vector<glm::vec3> box{{float(b.x), float(b.y), 0},
                                     {float(b.x + b.width), float(b.y), 0},
                                     {float(b.x + b.width), float(b.y + b.height), 0},
                                     {float(b.x), float(b.y + b.height), 0}};
    legend.add_polyline(box, {0.0f, 0.0f, 0.0f, 0.5f}, thin, true);  // 3:1 on paper, for print
    float top = float(b.y) + font_px * 0.4f;
    const glm::vec4 grey{0.45f, 0.45f, 0.47f, 1.0f};  // marker-only rows: the shape, no colour
    const auto rows = legend_rows(spec);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const auto& r = rows[k];
      // Columns side by side where the layout made them, each from the top.
      const std::size_t column = l.legend_per_column > 0 ? k / l.legend_per_column : 0;
      const bool column_top = l.legend_per_column > 0 && k % l.legend_per_column == 0;
      if (column_top) top = float(b.y) + font_px * 0.4f;
      if (r.gap_before && !column_top) top += line * 0.5f;
      const float cy = top + line * 0.5f;
      const auto names = name_lines(r, font, l.legend_name_width);
      const float lx0 = float(b.x + int(column) * l.legend_column_width) + font_px * 0.6f,
                  lx1 = lx0 + font_px * 2.4f;
      const glm::vec4 colour = r.colour >= 0 ? series_colour(std::size_t(r.colour)) : grey;
      if (r.line) legend.add_line({lx0, cy, 0}, {lx1, cy, 0}, colour, stroke);
      if (r.marker >= 0)
        add_shape(legend, {(lx0 + lx1) * 0.5f, cy}, series_marker(std::size_t(r.marker)),
                  marker_look(r.marker_size, font_px), colour);
      // A wrapped name's further lines under its first, beside nothing.
      for (const auto& name : names) {
        legend.add_text(label({lx1 + font_px * 0.6f, top + line * 0.5f}, name, TextAnchor::left));
        top += line;
      }
      if (names.empty()) top += line;
    }
    drawing.layers.push_back({std::move(legend), std::nullopt});
  }
  return drawing;
}

}  // namespace epviz::paint
