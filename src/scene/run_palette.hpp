#pragma once
// The colours that tell the runs of a comparison scene apart: a qualitative
// palette (after Okabe and Ito's, for colour-blind readers), its order
// picked so that the first runs read on both the dark and the light theme.
#include "scene/frame.hpp"

namespace epviz::scene {

// The colour of run `index` (0 = the first) on a light or a dark background.
Rgba run_colour(int index, bool light_background);

}  // namespace epviz::scene
