#pragma once
// The separation of each run of a comparison scene from the first, |delta
// gamma| over time on a log scale: where two methods part, and how fast
// nearby initial states diverge (chaos).
#include "render/draw_list.hpp"
#include "scene/frame.hpp"
#include "scene/layout.hpp"
#include "scene/theme.hpp"

namespace epviz::paint {

void draw_separation_chart(render::DrawList& flat, const scene::Comparison& c,
                           const scene::Rect& area, const scene::Theme& ink, float px);

}  // namespace epviz::paint
