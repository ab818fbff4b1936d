#pragma once
// A heat map as plain data: a grid of values over two axes whose columns and
// rows are named by labels (the values of two sweep axes, evenly spaced
// whatever their numeric spacing), drawn by paint/heat_map_painter.hpp with
// a colour bar. Who knows what the numbers mean (a sweep's atlas) builds it.
#include <limits>
#include <string>
#include <vector>

namespace epviz::chart {

struct HeatMapSpec {
  std::string title;
  std::string x_label, y_label;
  std::string value_label;           // the colour bar's caption
  std::vector<std::string> columns;  // x labels, left to right
  std::vector<std::string> rows;     // y labels, bottom to top
  std::vector<double> values;        // rows.size() * columns.size(), row by row from the bottom;
                                     // non-finite: no value (drawn as a grey hatch)
  bool log_values = false;
  // The colour bar's range (values beyond take its end colours); NaN: the
  // values' own range.
  double range_min = std::numeric_limits<double>::quiet_NaN();
  double range_max = std::numeric_limits<
      double>::quiet_NaN();                // colour by log10 of the value (values <= 0: no value)
  std::string missing_label = "no value";  // what a grey cell means, in the legend
};

}  // namespace epviz::chart
