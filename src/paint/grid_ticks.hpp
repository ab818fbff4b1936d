#pragma once
// Tick marks for a numeric axis of a grid of cells (a heat map's columns or
// rows): round values (1-2-5 steps; on a log-spaced axis decades, or 1, 2
// and 5 times each power of ten where it spans less than three) placed
// where they fall between the cells' own values, rather than the cells' raw
// values (-0.739, 0.0452), which a reader cannot interpolate from.
#include <string>
#include <vector>

namespace epviz::paint {

struct GridTick {
  double value = 0.0;
  // In cells: 0 is the first cell's centre, n-1 the last's; -0.5 and n-0.5
  // are the grid's edges.
  double position = 0.0;
  std::string label;
};

// `values`: the value at each cell's centre, strictly monotone (ascending or
// descending), at least two. A grid whose values are positive and evenly
// spaced in log10 (ratio steps) is read on a log scale. Ticks lie on the
// grid (positions within [-0.5, n-0.5]), about `max_labels` of them, in
// the order of their positions; within a cell they are interpolated
// linearly (in log10 on a log scale), beyond the outer centres extrapolated
// from the outer cells. Empty when `values` is not of that kind.
std::vector<GridTick> grid_ticks(const std::vector<double>& values, int max_labels);

// Whether `values` is log-spaced as grid_ticks reads it.
bool log_spaced(const std::vector<double>& values);

}  // namespace epviz::paint
