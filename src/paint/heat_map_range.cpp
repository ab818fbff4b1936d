#include "paint/heat_map_range.hpp"

#include <cmath>
#include <vector>

namespace epviz::paint {

Beyond beyond_range(const HeatMapSpec& spec, double value) {
  if (!std::isfinite(value)) return Beyond::no;
  // Compared in values, not in plotted units: log10 of a bound and of a
  // value equal to it agree, but an exact comparison is what a reader means.
  if (std::isfinite(spec.range_max) && value > spec.range_max) return Beyond::above;
  if (std::isfinite(spec.range_min) && value < spec.range_min) {
    // On a log scale a value <= 0 has no colour at all (drawn as missing).
    if (spec.log_scale && value <= 0.0) return Beyond::no;
    return Beyond::below;
  }
  return Beyond::no;
}

std::string beyond_bound_text(const HeatMapSpec& spec, Beyond side) {
  return side == Beyond::above ? "> " + print_number(spec.range_max, 3)
                               : "< " + print_number(spec.range_min, 3);
}

std::string beyond_key_text(const HeatMapSpec& spec, Beyond side, std::size_t cells) {
  const bool above = side == Beyond::above;
  return std::to_string(cells) + (cells == 1 ? " cell " : " cells ") +
         (above ? "above " + print_number(spec.range_max, 3) + ", drawn in the top colour"
                : "below " + print_number(spec.range_min, 3) + ", drawn in the bottom colour");
}

void add_beyond_triangle(render::DrawList& list, glm::vec2 centre, float size, Beyond side,
                         const glm::vec4& colour) {
  const float h = size * 0.5f, sign = side == Beyond::above ? -1.0f : 1.0f;  // y grows downwards
  const std::vector<render::ColouredVertex> v{{{centre.x, centre.y + sign * h, 0}, colour},
                                              {{centre.x - h, centre.y - sign * h, 0}, colour},
                                              {{centre.x + h, centre.y - sign * h, 0}, colour}};
  list.add_triangles(v);
}

}  // namespace epviz::paint
