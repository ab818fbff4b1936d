#pragma once
// What a chart or table figure shows, as plain data: series of points, axis
// labels and scales, a title; or a table's header and cells. Whoever knows
// what the numbers mean (the bench studies) builds these; the painters
// (paint/figure_painter.hpp) draw them without knowing what they mean. No GL
// here, so that modules without a renderer can describe figures too.
#include <limits>
#include <string>
#include <variant>
#include <vector>

namespace epviz::chart {

struct ChartPoint {
  double x = 0.0;
  double y = 0.0;
};

// How a series is drawn.
enum class SeriesStyle {
  // A line through the points, with a marker at every point of a short
  // series (up to 60 points) and at a dozen evenly spaced ones of a longer.
  lines_and_markers,
  // A scatter: a marker at every point, however many, and no line.
  markers,
  // The line alone, no marker (e.g. a guide to the eye).
  line,
};

// The markers' size: `dot` is a small mark without outline, for scatters of
// thousands of points, where full-size markers would merge into blots.
enum class MarkerSize { normal, dot };

struct ChartSeries {
  std::string name;
  std::vector<ChartPoint>
      points;  // drawn in this order; non-finite (or <= 0 on a log axis) points break the line
               // (y <= 0 on a log y axis: marked under the plot, ChartSpec::nonpositive_label)
  // Series with the same colour key share a colour, with the same marker key a
  // marker shape (e.g. colour by method, marker by formulation); -1: by the
  // series' position in the chart.
  int colour_key = -1;
  int marker_key = -1;
  SeriesStyle style = SeriesStyle::lines_and_markers;
  MarkerSize marker_size = MarkerSize::normal;
};

// What one colour or one marker shape of a chart stands for.
struct LegendKey {
  std::string name;
  int key = 0;
};

struct ChartSpec {
  std::string title;
  std::string x_label;
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  std::vector<ChartSeries> series;
  // A legend by key instead of by series, where the series are the product
  // of two things (methods x formulations): a row per colour, then a row per
  // marker shape. Empty: a row per series.
  std::vector<LegendKey> colour_legend;
  std::vector<LegendKey> marker_legend;
  // Points the axes take in besides the series' (not drawn): charts side by
  // side share their axes by taking in each other's points.
  std::vector<ChartPoint> axis_extent;
  // On a log y axis, points with y <= 0 (finite) have no place on it: they
  // are marked, with their series' marker, in a row under the plot labelled
  // this ("≤ 0" when empty), and a note under the x label counts them, so
  // that none is dropped unsaid. (Small multiples' panels do not draw it.)
  std::string nonpositive_label;
  // Small multiples: when given, the chart is these panels (each with its
  // title, series and legend) under this chart's title, `panel_columns` to a
  // row, every panel's axes taking in every panel's points; this chart's own
  // series are not drawn.
  std::vector<ChartSpec> panels;
  int panel_columns = 1;
};

// A grid of values, rows by columns, each cell coloured by its value on a
// sequential colour map with a colour bar to read it (e.g. method x regime,
// the largest stable step; a sweep's metric over two of its axes). NaN (or a
// value <= 0 on a log scale): no value, drawn grey with `missing`. A value
// beyond a fixed range takes the end colour and a triangle in its cell (up:
// above, down: below), so that a clipped value never passes for the end value.
//
// Rows are listed top to bottom as drawn, columns left to right. A numeric
// y axis that should read upwards (small values at the bottom) therefore
// lists its largest value first. Cells show their value as text where it
// fits; on large grids (64 x 64) only their colour, and the column and row
// labels are thinned so that they never overlap.
struct HeatMapSpec {
  std::string title;
  std::string x_label;      // the columns' axis title, under their labels
  std::string y_label;      // the rows' axis title, above their labels
  std::string value_label;  // what the colour means, over the colour bar
  std::vector<std::string> rows, columns;
  // Numeric axes: the value at each column's (row's) centre, in the order of
  // `columns` (`rows`). Given (one per column, strictly monotone) on a grid
  // of many cells, that axis is labelled at round values placed between the
  // cells (paint/grid_ticks.hpp) instead of by the cells' own labels; empty:
  // the labels are names.
  std::vector<double> column_values, row_values;
  std::vector<std::vector<double>> values;  // [row][column], row 0 at the top
  bool log_scale = true;                    // colours by log10 of the value (values > 0)
  bool larger_is_better = true;             // the map's bright end at the better values
  // The colour bar's range, in values (values beyond take its end colours),
  // so that several maps compare by colour; NaN: the values' own range.
  double range_min = std::numeric_limits<double>::quiet_NaN();
  double range_max = std::numeric_limits<double>::quiet_NaN();
  std::string missing = "n/a";  // in a cell without a value, or in a key under a text-less grid
  std::string note;             // one line under the grid: how the values were measured
  // Cells whose value could not be decided ([row][column], true; empty:
  // none), e.g. where the reference a value is measured against is not
  // converged: hatched and labelled `undecided`, in the cell where text fits
  // and in a key under the grid, unlike the grey of a cell without a value.
  std::vector<std::vector<bool>> undecided;
  std::string undecided_label = "undecided";
  // Maps shown together (a sweep's atlas): the room their labels, colour bar
  // and keys need is taken in as well, so that every map of the set has the
  // same plot rectangle (as ChartSpec::axis_extent shares axes). Their own
  // margin_peers are not read.
  std::vector<HeatMapSpec> margin_peers;
};

struct TableSpec {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // short rows are padded with empty cells
};

// One picture and the file name it is meant to be saved under ("drift_euler.png").
struct Figure {
  std::string file_name;
  std::variant<ChartSpec, TableSpec, HeatMapSpec> content;
};

}  // namespace epviz::chart
