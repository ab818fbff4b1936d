#include "paint/chart_painter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "render/colour_map.hpp"
#include "render/draw_list.hpp"
#include "render/renderer.hpp"

namespace epviz::paint {
namespace {

using render::DrawList;
using render::TextAnchor;
using render::TextLabel;
using render::Viewport;

const glm::vec4 kPaper{1.0f, 1.0f, 1.0f, 1.0f};
const glm::vec4 kInk{0.10f, 0.10f, 0.12f, 1.0f};
const glm::vec4 kFrame{0.20f, 0.20f, 0.22f, 1.0f};
const glm::vec4 kGrid{0.0f, 0.0f, 0.0f, 0.10f};
const glm::vec4 kGridMinor{0.0f, 0.0f, 0.0f, 0.045f};
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

float estimate_width(const std::string& s, float font_px) {
  return float(s.size()) * font_px * 0.58f;
}

// A value on an axis in plotted units (log10 on a log axis); NaN when it cannot be shown.
double axis_value(double v, bool log_axis) {
  if (!std::isfinite(v)) return kNaN;
  if (log_axis) return v > 0.0 ? std::log10(v) : kNaN;
  return v;
}

struct Span {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (std::isfinite(v)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  bool empty() const { return !(lo <= hi); }
};

// Whole decades on a log axis, a padded range with nice ends on a linear one.
void finish_span(Span& s, bool log_axis) {
  if (s.empty()) {
    s.lo = log_axis ? -1.0 : 0.0;
    s.hi = log_axis ? 1.0 : 1.0;
    return;
  }
  if (log_axis) {
    s.lo = std::floor(s.lo + 1e-9);
    s.hi = std::ceil(s.hi - 1e-9);
    if (s.hi <= s.lo) s.hi = s.lo + 1.0;
    return;
  }
  if (s.hi - s.lo < 1e-300) {
    const double pad = std::max(std::abs(s.lo) * 0.1, 1.0);
    s.lo -= pad;
    s.hi += pad;
  }
  const double pad = 0.04 * (s.hi - s.lo);
  s.lo -= pad;
  s.hi += pad;
}

struct Tick {
  double at;          // plotted units
  std::string label;  // empty for minor ticks
  bool major;
};

std::vector<Tick> axis_ticks(double lo, double hi, bool log_axis, int max_labels) {
  std::vector<Tick> ticks;
  if (log_axis) {
    const int first = int(std::ceil(lo - 1e-9)), last = int(std::floor(hi + 1e-9));
    const int decades = last - first;
    const int step =
        std::max(1, int(std::ceil(double(decades) / double(std::max(1, max_labels - 1)))));
    for (int e = first; e <= last; ++e) {
      const bool labelled = (e - first) % step == 0;
      ticks.push_back({double(e), labelled ? decade_label(e) : std::string(), true});
      if (step == 1 && decades <= 8 && e < last)
        for (int m = 2; m <= 9; ++m)
          ticks.push_back({double(e) + std::log10(double(m)), {}, false});
    }
    return ticks;
  }
  const auto values = render::nice_ticks(lo, hi, max_labels);
  const double spacing = values.size() > 1 ? values[1] - values[0] : (hi - lo);
  for (double v : values) ticks.push_back({v, render::format_tick(v, spacing), true});
  return ticks;
}

TextLabel label(glm::vec2 at, std::string text, TextAnchor anchor, glm::vec4 colour = kInk) {
  TextLabel l;
  l.position = glm::vec3(at, 0.0f);
  l.text = std::move(text);
  l.colour = colour;
  l.anchor = anchor;
  return l;
}

void add_shape(DrawList& list, glm::vec2 c, MarkerShape shape, float r, const glm::vec4& fill) {
  const glm::vec4 outline{fill.r * 0.55f, fill.g * 0.55f, fill.b * 0.55f, 1.0f};
  if (shape == MarkerShape::circle) {
    render::Marker m;
    m.position = glm::vec3(c, 0.0f);
    m.fill = fill;
    m.outline = outline;
    m.radius_px = r;
    m.outline_px = 1.0f;
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
      const float h = r * 0.9f;
      list.add_line({c.x - h, c.y - h, 0}, {c.x + h, c.y + h, 0}, fill, std::max(2.0f, r * 0.45f));
      list.add_line({c.x - h, c.y + h, 0}, {c.x + h, c.y - h, 0}, fill, std::max(2.0f, r * 0.45f));
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
  std::vector<glm::vec3> ring;
  for (const auto& p : poly) ring.emplace_back(p, 0.0f);
  list.add_polyline(ring, outline, 1.0f, true);
}

// The legend's rows: a row per series, or (keyed legends) a row per colour,
// then a row per marker shape. `colour` < 0: no line sample; `marker` < 0: none.
struct LegendRow {
  std::string name;
  int colour = -1;
  int marker = -1;
  bool gap_before = false;  // half a line of space above (between the two key lists)
};
std::vector<LegendRow> legend_rows(const ChartSpec& spec) {
  std::vector<LegendRow> rows;
  if (spec.colour_legend.empty() && spec.marker_legend.empty()) {
    for (std::size_t i = 0; i < spec.series.size(); ++i) {
      const auto& s = spec.series[i];
      rows.push_back({s.name, s.colour_key >= 0 ? s.colour_key : int(i),
                      s.marker_key >= 0 ? s.marker_key : int(i)});
    }
    return rows;
  }
  for (const auto& k : spec.colour_legend) rows.push_back({k.name, k.key, -1});
  bool first = true;
  for (const auto& k : spec.marker_legend) {
    rows.push_back({k.name, -1, k.key, first && !rows.empty()});
    first = false;
  }
  return rows;
}
float legend_height(const std::vector<LegendRow>& rows, float line, float font_px) {
  float h = font_px * 0.8f;
  for (const auto& r : rows) h += line * (r.gap_before ? 1.5f : 1.0f);
  return h;
}

render::RendererOptions renderer_options(const ChartOptions& options) {
  render::RendererOptions ro;
  ro.width = options.width;
  ro.height = options.height;
  ro.msaa_samples = options.msaa_samples;
  ro.overlay = true;
  ro.overlay_options.builtin_font = options.builtin_font;
  ro.overlay_options.font_size_px = chart_font_px(options);
  ro.overlay_options.light_style = true;
  return ro;
}

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
      if (!std::isnan(prev.x))
        for (int k = 1; k < 16; ++k)
          if (in(prev + (p - prev) * (float(k) / 16.0f))) ++n;
      prev = p;
    }
  }
  return n;
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

std::string decade_label(int exponent) {
  if (exponent == 0) return "1";
  return "1e" + std::to_string(exponent);
}

float chart_font_px(const ChartOptions& options) {
  if (options.builtin_font) return 13.0f;
  if (options.font_px > 0.0f) return options.font_px;
  return std::clamp(float(options.height) / 40.0f, 13.0f, 30.0f);
}

glm::vec2 ChartLayout::to_pixel(double x, double y) const {
  const double ax = axis_value(x, log_x), ay = axis_value(y, log_y);
  if (std::isnan(ax) || std::isnan(ay)) return {NAN, NAN};
  const double fx = (ax - range.x_min) / (range.x_max - range.x_min);
  const double fy = (ay - range.y_min) / (range.y_max - range.y_min);
  return {float(plot_area.x + fx * plot_area.width),
          float(plot_area.y + (1.0 - fy) * plot_area.height)};
}

ChartLayout chart_layout(const ChartSpec& spec, int width, int height, float font_px) {
  ChartLayout l;
  l.log_x = spec.log_x;
  l.log_y = spec.log_y;
  Span sx, sy;
  for (const auto& s : spec.series)
    for (const auto& p : s.points) {
      const double ax = axis_value(p.x, spec.log_x), ay = axis_value(p.y, spec.log_y);
      if (std::isnan(ax) || std::isnan(ay)) continue;
      sx.add(ax);
      sy.add(ay);
    }
  finish_span(sx, spec.log_x);
  finish_span(sy, spec.log_y);
  l.range = {sx.lo, sx.hi, sy.lo, sy.hi};

  // Margins: y tick labels on the left, x tick labels and the x label below,
  // title and the y label (written horizontally above the axis) on top.
  float widest_y = 0.0f;
  for (const auto& t : axis_ticks(sy.lo, sy.hi, spec.log_y, 8))
    widest_y = std::max(widest_y, estimate_width(t.label, font_px));
  const float line = font_px * 1.35f;
  const int left = int(std::ceil(widest_y + font_px * 1.6f));
  const int top = int(std::ceil(font_px * 0.8f + (spec.title.empty() ? 0.0f : line * 1.3f) +
                                (spec.y_label.empty() ? 0.0f : line)));
  const int bottom =
      int(std::ceil(font_px * 0.9f + line + (spec.x_label.empty() ? 0.0f : line * 1.1f)));
  // Room on the right for half the last x tick label, which is centred on the
  // plot's right edge.
  float last_x_label = 0.0f;
  for (const auto& t : axis_ticks(sx.lo, sx.hi, spec.log_x, 10))
    if (!t.label.empty()) last_x_label = estimate_width(t.label, font_px);
  int right = int(std::ceil(std::max(font_px * 1.5f, 0.5f * last_x_label + font_px * 0.5f)));

  // Legend: a row per series (or per key), a line sample and marker, then the name.
  const auto rows = legend_rows(spec);
  float widest_name = 0.0f;
  for (const auto& r : rows) widest_name = std::max(widest_name, estimate_width(r.name, font_px));
  const int legend_w = int(std::ceil(font_px * 3.6f + widest_name + font_px * 0.8f));
  const int legend_h = int(std::ceil(legend_height(rows, line, font_px)));
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
  // No free corner: the legend goes right of the plot, which narrows.
  right = std::max(right, legend_w + pad * 2);
  l.plot_area = {left, top, width - left - right, height - top - bottom};
  l.legend = {l.plot_area.x + l.plot_area.width + pad, l.plot_area.y, legend_w, legend_h};
  l.legend_outside = true;
  return l;
}

render::RgbaImage paint_chart(render::GlContext& context, const ChartSpec& spec,
                              const ChartOptions& requested) {
  context.make_current();
  // Keep the requested font size, but grow the picture downwards when a long
  // legend (many series) would not fit beside the plot: nothing is cut off.
  ChartOptions options = requested;
  const float font_px = chart_font_px(requested);
  options.font_px = font_px;
  ChartLayout l = chart_layout(spec, options.width, options.height, font_px);
  const int legend_bottom = l.legend.y + l.legend.height + int(font_px);
  if (l.legend_outside && legend_bottom > options.height) {
    options.height = legend_bottom;
    l = chart_layout(spec, options.width, options.height, font_px);
  }
  render::Renderer renderer(context, renderer_options(options));
  const Viewport& a = l.plot_area;
  const float line = font_px * 1.35f;
  const float tick = std::max(4.0f, font_px * 0.45f);
  const float stroke = std::max(1.5f, font_px * 0.14f);

  renderer.begin_frame(kPaper);
  DrawList axes;
  const float x0 = float(a.x), x1 = float(a.x + a.width), y0 = float(a.y),
              y1 = float(a.y + a.height);
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
    axes.add_line({x, y0, 0}, {x, y1, 0}, t.major ? kGrid : kGridMinor, 1.0f);
    const float len = t.major ? tick : tick * 0.55f;
    axes.add_line({x, y1, 0}, {x, y1 - len, 0}, kFrame, 1.0f);
    axes.add_line({x, y0, 0}, {x, y0 + len, 0}, kFrame, 1.0f);
    if (!t.label.empty()) axes.add_text(label({x, y1 + font_px * 0.45f}, t.label, TextAnchor::top));
  }
  for (const auto& t : axis_ticks(l.range.y_min, l.range.y_max, l.log_y, max_y_labels)) {
    const float y = px_y(t.at);
    if (y < y0 - 0.5f || y > y1 + 0.5f) continue;
    axes.add_line({x0, y, 0}, {x1, y, 0}, t.major ? kGrid : kGridMinor, 1.0f);
    const float len = t.major ? tick : tick * 0.55f;
    axes.add_line({x0, y, 0}, {x0 + len, y, 0}, kFrame, 1.0f);
    axes.add_line({x1, y, 0}, {x1 - len, y, 0}, kFrame, 1.0f);
    if (!t.label.empty())
      axes.add_text(label({x0 - font_px * 0.45f, y}, t.label, TextAnchor::right));
  }
  const std::vector<glm::vec3> frame{{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}};
  axes.add_polyline(frame, kFrame, 1.25f, true);
  if (!spec.title.empty())
    axes.add_text(
        label({float(options.width) * 0.5f, font_px * 0.6f}, spec.title, TextAnchor::top));
  if (!spec.y_label.empty())
    axes.add_text(label({x0, y0 - font_px * 0.5f}, spec.y_label, TextAnchor::bottom_left));
  if (!spec.x_label.empty())
    axes.add_text(
        label({(x0 + x1) * 0.5f, y1 + font_px * 0.45f + line}, spec.x_label, TextAnchor::top));
  renderer.draw_2d(axes);

  // Data, clipped to the plot area: lines first, then all markers on top.
  DrawList lines, markers;
  const float marker_r = std::max(3.5f, font_px * 0.3f);
  for (std::size_t i = 0; i < spec.series.size(); ++i) {
    const auto& s = spec.series[i];
    const glm::vec4 colour = colour_of(s, i);
    const MarkerShape shape = marker_of(s, i);
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
      run.emplace_back(q, 0.0f);
      if (s.points.size() <= 60) add_shape(markers, q, shape, marker_r, colour);
    }
    flush();
    // Long series (time series) get a few markers only, evenly spaced.
    if (s.points.size() > 60) {
      const std::size_t every = s.points.size() / 12 + 1;
      for (std::size_t k = every / 2; k < s.points.size(); k += every) {
        const glm::vec2 q = l.to_pixel(s.points[k].x, s.points[k].y);
        if (!std::isnan(q.x) && !std::isnan(q.y)) add_shape(markers, q, shape, marker_r, colour);
      }
    }
  }
  renderer.draw_2d(lines, &a);
  const Viewport marker_clip =
      a.inset(-int(marker_r) - 2, -int(marker_r) - 2, -int(marker_r) - 2, -int(marker_r) - 2);
  renderer.draw_2d(markers, &marker_clip);

  if (!spec.series.empty()) {
    DrawList legend;
    const Viewport& b = l.legend;
    legend.add_rect({float(b.x), float(b.y)}, {float(b.x + b.width), float(b.y + b.height)},
                    {1.0f, 1.0f, 1.0f, 0.92f});
    const std::vector<glm::vec3> box{{float(b.x), float(b.y), 0},
                                     {float(b.x + b.width), float(b.y), 0},
                                     {float(b.x + b.width), float(b.y + b.height), 0},
                                     {float(b.x), float(b.y + b.height), 0}};
    legend.add_polyline(box, {0.0f, 0.0f, 0.0f, 0.35f}, 1.0f, true);
    float top = float(b.y) + font_px * 0.4f;
    const glm::vec4 grey{0.45f, 0.45f, 0.47f, 1.0f};  // marker-only rows: the shape, no colour
    for (const auto& r : legend_rows(spec)) {
      if (r.gap_before) top += line * 0.5f;
      const float cy = top + line * 0.5f;
      top += line;
      const float lx0 = float(b.x) + font_px * 0.6f, lx1 = lx0 + font_px * 2.4f;
      const glm::vec4 colour = r.colour >= 0 ? series_colour(std::size_t(r.colour)) : grey;
      if (r.colour >= 0) legend.add_line({lx0, cy, 0}, {lx1, cy, 0}, colour, stroke);
      if (r.marker >= 0)
        add_shape(legend, {(lx0 + lx1) * 0.5f, cy}, series_marker(std::size_t(r.marker)), marker_r,
                  colour);
      legend.add_text(label({lx1 + font_px * 0.6f, cy}, r.name, TextAnchor::left));
    }
    renderer.draw_2d(legend);
  }
  return renderer.finish_frame();
}

render::RgbaImage paint_table(render::GlContext& context, const TableSpec& spec,
                              const ChartOptions& options) {
  context.make_current();
  render::Renderer renderer(context, renderer_options(options));
  const float font_px = chart_font_px(options);
  const float line = font_px * 1.5f;
  std::size_t columns = spec.header.size();
  for (const auto& r : spec.rows) columns = std::max(columns, r.size());
  auto cell = [](const std::vector<std::string>& row, std::size_t c) {
    return c < row.size() ? row[c] : std::string();
  };

  // Column widths from the longest cell, scaled down together if the table is too wide.
  std::vector<float> widths(columns, 0.0f);
  for (std::size_t c = 0; c < columns; ++c) {
    widths[c] = estimate_width(cell(spec.header, c), font_px);
    for (const auto& r : spec.rows)
      widths[c] = std::max(widths[c], estimate_width(cell(r, c), font_px));
    widths[c] += font_px * 1.2f;
  }
  const float margin = font_px * 1.5f;
  float total = 0.0f;
  for (float w : widths) total += w;
  const float avail = float(options.width) - 2.0f * margin;
  if (total > avail && total > 0.0f)
    for (float& w : widths) w *= avail / total;
  total = std::min(total, avail);

  renderer.begin_frame(kPaper);
  DrawList list;
  const float left = std::max(margin, (float(options.width) - total) * 0.5f);
  float y = font_px * 0.8f;
  if (!spec.title.empty()) {
    list.add_text(label({float(options.width) * 0.5f, y}, spec.title, TextAnchor::top));
    y += line * 1.3f;
  }
  const float rule_heavy = std::max(1.5f, font_px * 0.1f);
  list.add_line({left, y, 0}, {left + total, y, 0}, kInk, rule_heavy);
  auto write_row = [&](const std::vector<std::string>& row, float top, const glm::vec4& colour) {
    float x = left;
    for (std::size_t c = 0; c < columns; ++c) {
      list.add_text(
          label({x + font_px * 0.4f, top + line * 0.5f}, cell(row, c), TextAnchor::left, colour));
      x += widths[c];
    }
  };
  if (!spec.header.empty()) {
    write_row(spec.header, y, kInk);
    y += line;
    list.add_line({left, y, 0}, {left + total, y, 0}, kInk, 1.0f);
  }
  const float bottom_limit = float(options.height) - font_px;
  std::size_t shown = 0;
  for (const auto& r : spec.rows) {
    if (y + line > bottom_limit - line) break;
    if (shown % 2 == 1)
      list.add_rect({left, y}, {left + total, y + line}, {0.0f, 0.0f, 0.0f, 0.04f});
    write_row(r, y, kInk);
    y += line;
    ++shown;
  }
  list.add_line({left, y, 0}, {left + total, y, 0}, kInk, rule_heavy);
  if (shown < spec.rows.size()) {
    char more[64];
    std::snprintf(more, sizeof more, "(%zu more rows not shown)", spec.rows.size() - shown);
    list.add_text(
        label({left, y + font_px * 0.4f}, more, TextAnchor::top_left, {0.4f, 0.4f, 0.4f, 1.0f}));
  }
  renderer.draw_2d(list);
  return renderer.finish_frame();
}

// --- Heat maps -----------------------------------------------------------------

namespace {

const render::ColourMap& heat_map() {
  static const render::ColourMap map = render::ColourMap::time();
  return map;
}

double plotted(const HeatMapSpec& spec, double v) {
  if (!std::isfinite(v)) return kNaN;
  if (spec.log_scale) return v > 0.0 ? std::log10(v) : kNaN;
  return v;
}

// The value of a cell; NaN where the spec's values stop short of its rows or columns.
double cell_value(const HeatMapSpec& spec, std::size_t row, std::size_t column) {
  if (row >= spec.values.size() || column >= spec.values[row].size()) return kNaN;
  return spec.values[row][column];
}

std::string heat_value_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

HeatMapLayout heat_map_layout(const HeatMapSpec& spec, int width, int height, float font_px) {
  HeatMapLayout l;
  Span span;
  bool any_missing = false;
  for (std::size_t i = 0; i < spec.rows.size(); ++i)
    for (std::size_t j = 0; j < spec.columns.size(); ++j) {
      const double v = plotted(spec, cell_value(spec, i, j));
      span.add(v);
      any_missing |= std::isnan(v);
    }
  finish_span(span, spec.log_scale);
  if (!spec.log_scale && !span.empty()) {
    // finish_span pads a linear range; a colour scale wants the values' own ends.
    const double pad = (span.hi - span.lo) / 1.08 * 0.04;
    span.lo += pad;
    span.hi -= pad;
  }
  // A fixed range is taken as given (not rounded to decades): maps that share
  // it colour the same value alike.
  if (const double v = plotted(spec, spec.range_min); std::isfinite(v)) span.lo = v;
  if (const double v = plotted(spec, spec.range_max); std::isfinite(v)) span.hi = v;
  if (!(span.hi > span.lo)) span.hi = span.lo + 1.0;
  l.lo = span.lo;
  l.hi = span.hi;

  const float line = font_px * 1.35f;
  float widest_row = estimate_width(spec.y_label, font_px);
  for (const auto& r : spec.rows) widest_row = std::max(widest_row, estimate_width(r, font_px));
  float widest_column = 0.0f;
  for (const auto& c : spec.columns)
    widest_column = std::max(widest_column, estimate_width(c, font_px));
  float widest_tick = 0.0f;
  for (const auto& t : axis_ticks(l.lo, l.hi, spec.log_scale, 8))
    widest_tick = std::max(widest_tick, estimate_width(t.label, font_px));
  float widest_value = 0.0f;
  for (const auto& row : spec.values)
    for (double v : row)
      if (!std::isnan(plotted(spec, v)))
        widest_value = std::max(widest_value, estimate_width(heat_value_text(v), font_px));
  if (any_missing) widest_value = std::max(widest_value, estimate_width(spec.missing, font_px));
  const float bar_w = font_px * 1.1f;
  const float right =
      std::max(estimate_width(spec.value_label, font_px), bar_w + font_px * 0.5f + widest_tick) +
      font_px * 2.5f;
  const int left = int(std::ceil(widest_row + font_px * 1.4f));
  const int top = int(std::ceil(font_px * 0.8f + line * 1.3f + line * 1.2f));
  const int grid_w = std::max(16, width - left - int(std::ceil(right)));
  const std::size_t columns = std::max<std::size_t>(1, spec.columns.size());
  const std::size_t rows = std::max<std::size_t>(1, spec.rows.size());
  const float cell_w = float(grid_w) / float(columns);
  // Column labels side by side where they fit a cell, on two lines where they
  // fit two, else every k-th one (with a gap of most of a character).
  const float column_gap = font_px * 0.5f;
  if (widest_column + column_gap * 0.5f > cell_w) {
    if (widest_column + column_gap <= 2.0f * cell_w)
      l.staggered_columns = true;
    else
      l.column_stride = std::size_t(std::ceil((widest_column + column_gap) / cell_w));
  }
  // The lines under the grid: column labels, the x axis title, the note, the
  // key to grey cells when they carry no text (known only once the rows'
  // height is: hence a second pass with that line when the first finds it needed).
  const float cell_h_max = font_px * 2.6f;
  auto place = [&](bool key) {
    const float under = font_px * 0.6f + line * (l.staggered_columns ? 2.0f : 1.0f) +
                        (spec.x_label.empty() ? 0.0f : line * 1.2f) +
                        (spec.note.empty() ? 0.0f : line * 1.4f) + (key ? line * 1.4f : 0.0f) +
                        font_px * 0.6f;
    const int bottom = int(std::ceil(under));
    const float cell_h =
        std::min(cell_h_max, float(std::max(16, height - top - bottom)) / float(rows));
    l.natural_height = top + int(std::ceil(cell_h_max * float(rows))) + bottom;
    // All values as text or none: a grid where only some cells say their value
    // would read as if the others had none.
    l.value_text = widest_value + font_px * 0.4f <= cell_w && font_px * 1.15f <= cell_h;
    l.missing_key = any_missing && !l.value_text;
    l.row_stride = std::size_t(std::ceil(line / std::max(cell_h, 1.0f) - 1e-4f));
    return cell_h;
  };
  float cell_h = place(false);
  if (l.missing_key) cell_h = place(true);
  const int grid_h = int(std::floor(cell_h * float(rows)));
  l.grid = {left, top, grid_w, grid_h};
  l.cells.assign(spec.rows.size(), {});
  for (std::size_t i = 0; i < spec.rows.size(); ++i)
    for (std::size_t j = 0; j < spec.columns.size(); ++j) {
      const int x0 = left + int(std::round(cell_w * float(j))),
                x1 = left + int(std::round(cell_w * float(j + 1)));
      const int y0 = top + int(std::round(cell_h * float(i))),
                y1 = top + int(std::round(cell_h * float(i + 1)));
      l.cells[i].push_back({x0, y0, x1 - x0, y1 - y0});
    }
  l.colour_bar = {left + grid_w + int(font_px * 1.5f), top, int(bar_w), grid_h};
  return l;
}

std::optional<glm::vec4> heat_map_colour(const HeatMapSpec& spec, const HeatMapLayout& l,
                                         double value) {
  const double v = plotted(spec, value);
  if (std::isnan(v)) return std::nullopt;
  double t = l.hi > l.lo ? (v - l.lo) / (l.hi - l.lo) : 0.5;
  t = std::clamp(t, 0.0, 1.0);
  if (!spec.larger_is_better) t = 1.0 - t;
  return heat_map()(float(t), 1.0f);
}

render::RgbaImage paint_heat_map(render::GlContext& context, const HeatMapSpec& spec,
                                 const ChartOptions& options) {
  context.make_current();
  render::Renderer renderer(context, renderer_options(options));
  const float font_px = chart_font_px(options);
  const float line = font_px * 1.35f;
  const HeatMapLayout l = heat_map_layout(spec, options.width, options.height, font_px);
  renderer.begin_frame(kPaper);
  DrawList list;
  if (!spec.title.empty())
    list.add_text(
        label({float(options.width) * 0.5f, font_px * 0.6f}, spec.title, TextAnchor::top));
  const glm::vec4 missing{0.88f, 0.88f, 0.89f, 1.0f};
  const glm::vec4 hatch{0.62f, 0.62f, 0.64f, 1.0f};
  const glm::vec4 quiet_ink{0.35f, 0.35f, 0.38f, 1.0f};
  const float tick = font_px * 0.3f;
  const float grid_bottom = float(l.grid.y + l.grid.height);
  for (std::size_t i = 0; i < l.cells.size(); ++i) {
    const Viewport& first = l.cells[i].empty() ? l.grid : l.cells[i][0];
    const float row_y = float(first.y) + first.height * 0.5f;
    if (i % l.row_stride == 0) {
      list.add_text(
          label({float(l.grid.x) - font_px * 0.5f, row_y}, spec.rows[i], TextAnchor::right));
      if (l.row_stride > 1)  // which row a thinned label names
        list.add_line({float(l.grid.x) - tick, row_y, 0}, {float(l.grid.x), row_y, 0}, kFrame,
                      1.0f);
    }
    for (std::size_t j = 0; j < l.cells[i].size(); ++j) {
      const Viewport& c = l.cells[i][j];
      const double v = cell_value(spec, i, j);
      const auto colour = heat_map_colour(spec, l, v);
      const glm::vec4 fill = colour.value_or(missing);
      // One pixel of paper between cells that hold text (a table of values);
      // colour-only cells touch, so that a large grid reads as one picture.
      const float gap = l.value_text ? 1.0f : 0.0f;
      const glm::vec2 a{float(c.x) + gap, float(c.y) + gap};
      const glm::vec2 b{float(c.x + c.width) - gap, float(c.y + c.height) - gap};
      list.add_rect(a, b, fill);
      if (!l.value_text) {
        // No text to say so: a diagonal marks the grey as no value rather than a colour.
        if (!colour) list.add_line({a.x, b.y, 0}, {b.x, a.y, 0}, hatch, 1.0f);
        continue;
      }
      const bool light = 0.299f * fill.r + 0.587f * fill.g + 0.114f * fill.b > 0.55f;
      const glm::vec4 ink = light ? kInk : glm::vec4(1.0f);
      list.add_text(label({float(c.x) + c.width * 0.5f, float(c.y) + c.height * 0.5f},
                          colour ? heat_value_text(v) : spec.missing, TextAnchor::centre,
                          colour ? ink : quiet_ink));
    }
  }
  // Column labels under the grid, on two lines where they are wider than a
  // cell, every k-th one (with a tick) where even two lines would overlap.
  for (std::size_t j = 0; j < spec.columns.size(); j += l.column_stride) {
    const Viewport& c = l.cells.empty() ? l.grid : l.cells[0][j];
    const float x = float(c.x) + c.width * 0.5f;
    const float y =
        grid_bottom + font_px * 0.5f + (l.staggered_columns && j % 2 == 1 ? line : 0.0f);
    list.add_text(label({x, y}, spec.columns[j], TextAnchor::top));
    if (l.column_stride > 1)
      list.add_line({x, grid_bottom, 0}, {x, grid_bottom + tick, 0}, kFrame, 1.0f);
  }
  float under = grid_bottom + font_px * 0.5f + line * (l.staggered_columns ? 2.0f : 1.0f);
  if (!spec.x_label.empty()) {
    list.add_text(label({float(l.grid.x) + float(l.grid.width) * 0.5f, under + line * 0.2f},
                        spec.x_label, TextAnchor::top));
    under += line * 1.2f;
  }
  if (!spec.y_label.empty())
    list.add_text(label({float(l.grid.x) - font_px * 0.5f, float(l.grid.y) - font_px * 0.9f},
                        spec.y_label, TextAnchor::bottom_right));
  if (!spec.note.empty()) {
    list.add_text(
        label({float(l.grid.x), under + line * 0.4f}, spec.note, TextAnchor::top_left, quiet_ink));
    under += line * 1.4f;
  }
  if (l.missing_key) {
    const glm::vec2 a{float(l.grid.x), under + line * 0.4f};
    const glm::vec2 b{a.x + font_px * 1.2f, a.y + font_px * 0.9f};
    list.add_rect(a, b, missing);
    list.add_line({a.x, b.y, 0}, {b.x, a.y, 0}, hatch, 1.0f);
    list.add_text(label({b.x + font_px * 0.5f, (a.y + b.y) * 0.5f}, spec.missing, TextAnchor::left,
                        quiet_ink));
  }
  // The colour bar: a strip per pixel row, low values at the bottom.
  const Viewport& b = l.colour_bar;
  std::vector<render::ColouredVertex> strip;
  constexpr int kSteps = 64;
  for (int k = 0; k < kSteps; ++k) {
    const float y1 = float(b.y + b.height) - float(b.height) * float(k) / kSteps;
    const float y0 = float(b.y + b.height) - float(b.height) * float(k + 1) / kSteps;
    const double v = l.lo + (l.hi - l.lo) * (double(k) + 0.5) / kSteps;
    const double value = spec.log_scale ? std::pow(10.0, v) : v;
    const glm::vec4 c = heat_map_colour(spec, l, value).value_or(missing);
    for (const glm::vec2 p :
         {glm::vec2(b.x, y0), glm::vec2(b.x + b.width, y0), glm::vec2(b.x + b.width, y1),
          glm::vec2(b.x, y0), glm::vec2(b.x + b.width, y1), glm::vec2(b.x, y1)})
      strip.push_back({glm::vec3(p, 0), c});
  }
  list.add_triangles(strip);
  const std::vector<glm::vec3> bar_frame{{float(b.x), float(b.y), 0},
                                         {float(b.x + b.width), float(b.y), 0},
                                         {float(b.x + b.width), float(b.y + b.height), 0},
                                         {float(b.x), float(b.y + b.height), 0}};
  list.add_polyline(bar_frame, kFrame, 1.0f, true);
  const int max_labels = std::clamp(int(float(b.height) / (font_px * 1.6f)), 2, 8);
  for (const auto& t : axis_ticks(l.lo, l.hi, spec.log_scale, max_labels)) {
    if (t.label.empty()) continue;
    const float y = float(b.y + b.height) - float((t.at - l.lo) / (l.hi - l.lo)) * float(b.height);
    list.add_line({float(b.x + b.width), y, 0}, {float(b.x + b.width) + font_px * 0.3f, y, 0},
                  kFrame, 1.0f);
    list.add_text(label({float(b.x + b.width) + font_px * 0.45f, y}, t.label, TextAnchor::left));
  }
  list.add_text(
      label({float(b.x), float(b.y) - font_px * 0.9f}, spec.value_label, TextAnchor::bottom_left));
  renderer.draw_2d(list);
  return renderer.finish_frame();
}

render::RgbaImage paint_figure(render::GlContext& context, const Figure& figure,
                               const ChartOptions& options) {
  if (const auto* chart = std::get_if<ChartSpec>(&figure.content))
    return paint_chart(context, *chart, options);
  if (const auto* heat = std::get_if<HeatMapSpec>(&figure.content)) {
    ChartOptions o = options;
    o.font_px = chart_font_px(options);
    o.height =
        std::min(o.height, heat_map_layout(*heat, o.width, o.height, o.font_px).natural_height);
    return paint_heat_map(context, *heat, o);
  }
  const auto& table = std::get<TableSpec>(figure.content);
  ChartOptions o = options;
  // Tall enough for every row: the title, the header, the rules and the
  // margins take five and a half lines (paint_table's layout); one more spare.
  o.font_px = chart_font_px(options);
  const float line = o.font_px * 1.5f;
  o.height = std::max(o.height, int(std::ceil(line * float(table.rows.size() + 8))));
  return paint_table(context, table, o);
}

}  // namespace epviz::paint
