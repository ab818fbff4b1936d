#pragma once
// The separation of each run of a comparison scene from the first, |Δγ| over
// time on a log scale: where two methods part, and how fast nearby initial
// states diverge (chaos).
#include <functional>
#include <string>

#include <glm/vec2.hpp>

#include "render/draw_list.hpp"
#include "scene/frame.hpp"
#include "scene/layout.hpp"
#include "scene/theme.hpp"

namespace epviz::paint {

// The chart's vertical range in log10 units: from the decade under the
// smallest positive separation (at least three decades, at most down to
// 10⁻¹⁶) to |Δγ| = 2, the most two unit vectors can differ.
struct SeparationRange {
  int lo = -3;
  double hi = 0.0;
};
SeparationRange separation_range(const scene::Comparison& c);

// Within `area`: a title saying what is plotted (what Δγ is where it has
// room), y ticks at every decade and labels at as many as fit, a time axis
// with ticks. Values under the range are drawn on its bottom edge, marked.
// `measure` gives a text's size.
void draw_separation_chart(render::DrawList& flat, const scene::Comparison& c,
                           const scene::Rect& area, const scene::Theme& ink, float px,
                           const std::function<glm::vec2(const std::string&)>& measure);

}  // namespace epviz::paint
