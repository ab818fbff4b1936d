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

// `measure` gives a text's size: the title says what Δγ is where it has room.
void draw_separation_chart(render::DrawList& flat, const scene::Comparison& c,
                           const scene::Rect& area, const scene::Theme& ink, float px,
                           const std::function<glm::vec2(const std::string&)>& measure);

}  // namespace epviz::paint
