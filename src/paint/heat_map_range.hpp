#pragma once
// Values beyond a heat map's fixed colour range (HeatMapSpec::range_min,
// range_max): they take the colour bar's end colour, which alone would pass
// them off as the end value. Such a cell carries a triangle (up: above the
// range, down: below), the colour bar an end triangle with its bound ("> 0.3"),
// and a key under the grid says how many cells are beyond it.
#include <cstddef>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "paint/figure_common.hpp"
#include "render/draw_list.hpp"

namespace epviz::paint {

enum class Beyond { no, above, below };

// Where `value` lies against the spec's fixed ends; an end the spec leaves
// open (NaN) is the values' own and nothing lies beyond it. NaN: no.
Beyond beyond_range(const HeatMapSpec& spec, double value);

struct OutOfRangeCount {
  std::size_t above = 0, below = 0;
};

// "> 0.3" (above) or "< 0" (below): the colour bar's end label.
std::string beyond_bound_text(const HeatMapSpec& spec, Beyond side);
// "23 cells above 0.3, drawn in the top colour": the key under the grid.
std::string beyond_key_text(const HeatMapSpec& spec, Beyond side, std::size_t cells);

// A triangle pointing up (above) or down (below), centred at `centre`,
// `size` pixels wide and high.
void add_beyond_triangle(render::DrawList& list, glm::vec2 centre, float size, Beyond side,
                         const glm::vec4& colour);

}  // namespace epviz::paint
