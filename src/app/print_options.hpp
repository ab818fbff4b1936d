#pragma once
// --figure-width, --font-size and --dpi of every command that draws charts
// (bench, section, diagram, merge), defined once, and a chart's layout at
// the printed size they give (io/print_size.hpp): the layout in units of
// 1/dpi inch, the PNG that many pixels, the SVG or PDF page scaled to points.
#include <optional>
#include <string>

#include "app/cli.hpp"
#include "io/print_size.hpp"
#ifdef EPVIZ_HAVE_RENDER
#include "paint/figure_common.hpp"
#endif

namespace epviz::app {

// Adds the three options; each value stays "" when not given.
void add_print_options(cli::Command command, io::PrintSizeText& text);

// The command line's values, each where given, else `file`'s (a section
// file's keys), checked and named by where each came from: `file_names` are
// the file's keys as messages name them.
std::optional<io::PrintSize> print_size_over(const io::PrintSizeText& command_line,
                                             const io::PrintSizeText& file,
                                             const io::PrintSizeText& file_names);

#ifdef EPVIZ_HAVE_RENDER
// `screen` (a command's usual size) as it is without a print size; with one,
// `panels` of its aspect side by side, `gap` apart, as wide as the print size
// together, the text at its font size, and the vector page scaled to points.
paint::ChartOptions chart_options(const paint::ChartOptions& screen,
                                  const std::optional<io::PrintSize>& print, int panels = 1,
                                  int gap = 0);
// How many of `panels` go side by side: all of them without a print size;
// at one, as many as are each at least 24 lines of text wide (a plot with
// its tick labels and a title of a few lines), the others on more rows.
int panel_columns(int panels, const std::optional<io::PrintSize>& print, int gap);
// The gap between side-by-side panels: `screen_gap` pixels, or one line of
// text at a print size (the screen gap is about that at its font).
int panel_gap(int screen_gap, const std::optional<io::PrintSize>& print);
#endif

}  // namespace epviz::app
