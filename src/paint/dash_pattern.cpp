#include "paint/dash_pattern.hpp"

#include <optional>

#include <glm/geometric.hpp>

namespace epviz::paint {

std::vector<DashSpan> dash_spans(std::span<const glm::vec2> pixels,
                                 std::span<const float> pattern) {
  std::vector<DashSpan> spans;
  if (pixels.size() < 2) return spans;
  const std::size_t last = pixels.size() - 2;  // the last segment
  if (pattern.empty()) return {{{0, 0.0f}, {last, 1.0f}}};
  float period = 0.0f;
  for (float p : pattern) period += p;
  if (!(period > 0.0f)) return {{{0, 0.0f}, {last, 1.0f}}};

  std::size_t phase = 0;                                    // which entry of the pattern we are in
  float left = pattern[0];                                  // pixels left of it
  std::optional<PolylineAt> started = PolylineAt{0, 0.0f};  // the current dash's start, while on
  for (std::size_t i = 0; i <= last; ++i) {
    const float length = glm::length(pixels[i + 1] - pixels[i]);
    float used = 0.0f;
    while (length - used > left) {
      used += left;
      const PolylineAt at{i, used / length};
      if (phase % 2 == 0) {
        if (started) spans.push_back({*started, at});
        started.reset();
      } else {
        started = at;
      }
      phase = (phase + 1) % pattern.size();
      left = pattern[phase];
    }
    left -= length - used;
  }
  if (started) spans.push_back({*started, {last, 1.0f}});
  return spans;
}

std::vector<float> dash_pattern(scene::LineStyle style, float width, bool open) {
  // In multiples of the line's width, so that a dot is as long as it is wide.
  std::vector<float> p;
  switch (style) {
    case scene::LineStyle::solid:
      p = open ? std::vector<float>{3.0f, 2.5f} : std::vector<float>{};
      break;
    case scene::LineStyle::dashed: p = {3.5f, 2.5f}; break;
    case scene::LineStyle::dotted: p = {1.0f, 1.6f}; break;
    case scene::LineStyle::dash_dot: p = {4.0f, 1.6f, 1.0f, 1.6f}; break;
    case scene::LineStyle::long_dash: p = {7.0f, 2.5f}; break;
    case scene::LineStyle::dash_dot_dot: p = {4.0f, 1.5f, 1.0f, 1.5f, 1.0f, 1.5f}; break;
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (open && style != scene::LineStyle::solid && i % 2 == 1) p[i] *= 1.7f;
    p[i] *= width;
  }
  return p;
}

}  // namespace epviz::paint
