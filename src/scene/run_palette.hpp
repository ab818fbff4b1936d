#pragma once
// What tells the runs of a comparison scene apart: a colour from a
// qualitative palette (after Okabe and Ito's, for colour-blind readers) and a
// line style, so that runs stay apart in greyscale too and where they
// coincide (a dashed run drawn over a solid one shows both). Each palette's
// colours are at least 20 apart in CIELAB and at least 3:1 in contrast
// against its theme's background (tests/paint/comparison_figure_test.cpp).
#include <string_view>

#include "scene/frame.hpp"

namespace epviz::scene {

// The colour of run `index` (0 = the first) on a light or a dark background.
Rgba run_colour(int index, bool light_background);
// The line style of run `index`: solid, dashed, dotted, dash-dot, ...
LineStyle run_line_style(int index);
std::string_view name(LineStyle style);

// How many runs have a colour and a line style of their own; further runs repeat them.
constexpr int kDistinctRuns = 6;

}  // namespace epviz::scene
