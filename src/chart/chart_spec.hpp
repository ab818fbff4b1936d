#pragma once
// What a chart or table figure shows, as plain data: series of points, axis
// labels and scales, a title; or a table's header and cells. Whoever knows
// what the numbers mean (the bench studies) builds these; the painter
// (paint/chart_painter.hpp) draws them without knowing what they mean. No GL
// here, so that modules without a renderer can describe figures too.
#include <string>
#include <variant>
#include <vector>

namespace epviz::chart {

struct ChartPoint {
  double x = 0.0;
  double y = 0.0;
};

struct ChartSeries {
  std::string name;
  std::vector<ChartPoint>
      points;  // drawn in this order; non-finite (or <= 0 on a log axis) points break the line
};

struct ChartSpec {
  std::string title;
  std::string x_label;
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  std::vector<ChartSeries> series;
};

struct TableSpec {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // short rows are padded with empty cells
};

// One picture and the file name it is meant to be saved under ("drift_euler.png").
struct Figure {
  std::string file_name;
  std::variant<ChartSpec, TableSpec> content;
};

}  // namespace epviz::chart
