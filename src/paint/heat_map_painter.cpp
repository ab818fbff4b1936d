#include "paint/heat_map_painter.hpp"

#include <algorithm>
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

const glm::vec4 kPaper{1.0f, 1.0f, 1.0f, 1.0f};
const glm::vec4 kInk{0.10f, 0.10f, 0.12f, 1.0f};
const glm::vec4 kFrame{0.20f, 0.20f, 0.22f, 1.0f};
const glm::vec4 kMissing{0.86f, 0.86f, 0.87f, 1.0f};
const glm::vec4 kHatch{0.62f, 0.62f, 0.64f, 1.0f};

float text_width(const std::string& s, float font_px) { return float(s.size()) * font_px * 0.58f; }

TextLabel label(glm::vec2 at, std::string text, TextAnchor anchor) {
  TextLabel l;
  l.position = glm::vec3(at, 0.0f);
  l.text = std::move(text);
  l.colour = kInk;
  l.anchor = anchor;
  return l;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// The value as coloured (log10 on a log scale); NaN when it has no colour.
double shade(double v, bool log_values) {
  if (!std::isfinite(v)) return std::numeric_limits<double>::quiet_NaN();
  if (log_values) return v > 0.0 ? std::log10(v) : std::numeric_limits<double>::quiet_NaN();
  return v;
}

// Every k-th label, so that labels `extent` pixels long fit into cells `cell` pixels apart.
std::size_t label_stride(float cell, float extent) {
  return std::max<std::size_t>(1, std::size_t(std::ceil(extent / std::max(cell, 1.0f))));
}

}  // namespace

render::RgbaImage paint_heat_map(render::GlContext& context, const HeatMapSpec& spec,
                                 const ChartOptions& options) {
  context.make_current();
  const float font_px = chart_font_px(options);
  render::RendererOptions ro;
  ro.width = options.width;
  ro.height = options.height;
  ro.msaa_samples = options.msaa_samples;
  ro.overlay = true;
  ro.overlay_options.builtin_font = options.builtin_font;
  ro.overlay_options.font_size_px = font_px;
  ro.overlay_options.light_style = true;
  render::Renderer renderer(context, ro);

  const std::size_t nx = std::max<std::size_t>(1, spec.columns.size());
  const std::size_t ny = std::max<std::size_t>(1, spec.rows.size());
  float widest_row = 0.0f;
  for (const auto& r : spec.rows) widest_row = std::max(widest_row, text_width(r, font_px));
  const float line = font_px * 1.35f;
  const float left = font_px + widest_row + line * 1.2f;
  const float top = line * 2.4f;
  const float bar_w = font_px * 1.2f;
  const float right = bar_w + font_px * 6.5f;
  const float bottom = line * 3.0f;
  const float x0 = left, x1 = float(options.width) - right;
  const float y0 = top, y1 = float(options.height) - bottom;
  const float cw = (x1 - x0) / float(nx), ch = (y1 - y0) / float(ny);

  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (double v : spec.values) {
    const double s = shade(v, spec.log_values);
    if (std::isfinite(s)) {
      lo = std::min(lo, s);
      hi = std::max(hi, s);
    }
  }
  if (std::isfinite(shade(spec.range_min, spec.log_values)))
    lo = shade(spec.range_min, spec.log_values);
  if (std::isfinite(shade(spec.range_max, spec.log_values)))
    hi = shade(spec.range_max, spec.log_values);
  const bool any = lo <= hi;
  if (any && hi - lo < 1e-12) {
    lo -= 0.5;
    hi += 0.5;
  }
  const auto map = render::ColourMap::time();

  renderer.begin_frame(kPaper);
  DrawList cells;
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t k = j * nx + i;
      const double s = k < spec.values.size() ? shade(spec.values[k], spec.log_values) : NAN;
      const glm::vec2 a{x0 + cw * float(i), y1 - ch * float(j + 1)};
      const glm::vec2 b{a.x + cw, a.y + ch};
      if (std::isfinite(s)) {
        cells.add_rect(a, b, map(float((s - lo) / (hi - lo))));
      } else {
        cells.add_rect(a, b, kMissing);
        // One diagonal per cell: a grey that cannot be read as a value.
        cells.add_line({a.x, b.y, 0}, {b.x, a.y, 0}, kHatch, 1.0f);
      }
    }
  }
  renderer.draw_2d(cells);

  DrawList axes;
  const std::vector<glm::vec3> frame{{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}};
  axes.add_polyline(frame, kFrame, 1.25f, true);
  float widest_col = 0.0f;
  for (const auto& c : spec.columns) widest_col = std::max(widest_col, text_width(c, font_px));
  const std::size_t sx = label_stride(cw, widest_col + font_px);
  for (std::size_t i = 0; i < spec.columns.size(); i += sx) {
    const float x = x0 + cw * (float(i) + 0.5f);
    axes.add_line({x, y1, 0}, {x, y1 + font_px * 0.3f, 0}, kFrame, 1.0f);
    axes.add_text(label({x, y1 + font_px * 0.45f}, spec.columns[i], TextAnchor::top));
  }
  const std::size_t sy = label_stride(ch, line);
  for (std::size_t j = 0; j < spec.rows.size(); j += sy) {
    const float y = y1 - ch * (float(j) + 0.5f);
    axes.add_line({x0 - font_px * 0.3f, y, 0}, {x0, y, 0}, kFrame, 1.0f);
    axes.add_text(label({x0 - font_px * 0.45f, y}, spec.rows[j], TextAnchor::right));
  }
  if (!spec.title.empty())
    axes.add_text(
        label({float(options.width) * 0.5f, font_px * 0.6f}, spec.title, TextAnchor::top));
  if (!spec.x_label.empty())
    axes.add_text(
        label({(x0 + x1) * 0.5f, y1 + font_px * 0.45f + line}, spec.x_label, TextAnchor::top));
  if (!spec.y_label.empty())
    axes.add_text(label({x0, y0 - font_px * 0.4f}, spec.y_label, TextAnchor::bottom_right));

  // The colour bar: the map from bottom (lowest) to top, its range and caption.
  const float bx0 = x1 + font_px * 1.2f, bx1 = bx0 + bar_w;
  const int steps = 64;
  for (int s = 0; s < steps; ++s) {
    const float t0 = float(s) / steps, t1 = float(s + 1) / steps;
    axes.add_rect({bx0, y1 - (y1 - y0) * t1}, {bx1, y1 - (y1 - y0) * t0},
                  any ? map((t0 + t1) * 0.5f) : kMissing);
  }
  const std::vector<glm::vec3> bar{{bx0, y0, 0}, {bx1, y0, 0}, {bx1, y1, 0}, {bx0, y1, 0}};
  axes.add_polyline(bar, kFrame, 1.0f, true);
  if (any) {
    auto shown = [&](double s) { return number(spec.log_values ? std::pow(10.0, s) : s); };
    for (int q = 0; q <= 4; ++q) {
      const double s = lo + (hi - lo) * q / 4.0;
      const float y = y1 - (y1 - y0) * float(q) / 4.0f;
      axes.add_line({bx1, y, 0}, {bx1 + font_px * 0.3f, y, 0}, kFrame, 1.0f);
      axes.add_text(label({bx1 + font_px * 0.45f, y}, shown(s), TextAnchor::left));
    }
  }
  if (!spec.value_label.empty())
    axes.add_text(label({bx1, y0 - font_px * 0.4f}, spec.value_label, TextAnchor::bottom_right));
  axes.add_rect({x0, y1 + line * 1.9f}, {x0 + font_px, y1 + line * 1.9f + font_px * 0.8f},
                kMissing);
  axes.add_text(label({x0 + font_px * 1.4f, y1 + line * 1.9f + font_px * 0.4f}, spec.missing_label,
                      TextAnchor::left));
  renderer.draw_2d(axes);
  return renderer.finish_frame();
}

}  // namespace epviz::paint
