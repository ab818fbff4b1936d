#include "paint/figure_common.hpp"

#include <algorithm>
#include <cmath>

#include "render/panel_2d.hpp"

namespace epviz::paint {

float chart_font_px(const ChartOptions& options) {
  if (options.builtin_font) return 13.0f;
  if (options.font_px > 0.0f) return options.font_px;
  return std::clamp(float(options.height) / 40.0f, 13.0f, 30.0f);
}

std::string decade_label(int exponent) {
  if (exponent == 0) return "1";
  return "1e" + std::to_string(exponent);
}

void Span::add(double v) {
  if (std::isfinite(v)) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
}

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

render::TextLabel label(glm::vec2 at, std::string text, render::TextAnchor anchor,
                        glm::vec4 colour) {
  render::TextLabel l;
  l.position = glm::vec3(at, 0.0f);
  l.text = std::move(text);
  l.colour = colour;
  l.anchor = anchor;
  return l;
}

}  // namespace epviz::paint
