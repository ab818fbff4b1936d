#pragma once
// Figures side by side (small multiples): the drawings of several figures,
// each laid out at its own size, placed left to right with a gap, tops
// aligned, as one drawing that either backend paints (the GL renderer into a
// PNG, cairo into SVG or PDF). Only placement: each panel is drawn as it
// would be alone.
#include <vector>

#include "paint/figure_drawing.hpp"

namespace epviz::paint {

// Panel k's drawing moved right by the widths of the panels before it and
// `gap` pixels each; the result as wide as all of them and as tall as the tallest.
FigureDrawing side_by_side(const std::vector<FigureDrawing>& panels, int gap);
// Row k's drawing moved down by the heights of the rows before it and `gap`
// pixels each, left edges aligned; as tall as all of them and as wide as the widest.
FigureDrawing stacked(const std::vector<FigureDrawing>& rows, int gap);
// The panels in rows of `columns` (side_by_side), the rows stacked, `gap`
// pixels apart both ways: panels too narrow side by side on a printed page
// go onto more rows. `columns` < 1 or at least the panels' count: one row.
FigureDrawing panel_grid(const std::vector<FigureDrawing>& panels, int columns, int gap);

}  // namespace epviz::paint
