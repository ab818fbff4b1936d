#pragma once
// A frame's text as a figure prints it: the numbers the scene wrote with
// printf ("tol 6.7e-06", "t = -20") set with a minus sign and powers of ten
// ("tol 6.7×10⁻⁶", "t = −20"), as the charts' tick labels are
// (figure_common.hpp). The scene's strings stay plain for the reports and
// summary lines that scripts read; only what is drawn is set so.
#include <string>

#include "scene/frame.hpp"

namespace epviz::paint {

// `text` with each number in exponent form ("6.7e-06", "1e-10", "2E+03")
// written "6.7×10⁻⁶", "10⁻¹⁰", "2×10³", and each hyphen before a number
// that is not inside a word a minus sign. Digits inside names ("dop853",
// "rk4", "Gauss-4") are left as they are.
std::string print_numbers_in(const std::string& text);

// The overlay's title and lines, a comparison's run labels, the caption and
// the horizon's note, each through print_numbers_in.
void typeset_frame_text(scene::Frame& frame);

}  // namespace epviz::paint
