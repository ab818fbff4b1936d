#pragma once
// JSON objects of one kind (a sweep's rows) as the columns of an HDF5 file
// (columns_file.hpp), one dataset per leaf, so that a reader gets a
// contiguous array per quantity instead of parsing JSON Lines.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "h5/columns_file.hpp"

namespace epviz::h5 {

// Writes `rows` (objects, in their order) into `file` as whole columns: every
// leaf of a row, named by its path ("steps", "max_relative_drift.energy",
// "initial.omega[0]"). A leaf that is a number in every row that has one
// (true and false count as 1 and 0) is a float64 dataset, NaN where a row
// holds null or lacks it; any other leaf is a dataset of UTF-8 strings (text
// as it is, other values as their JSON), "" where a row holds null or lacks it. A null
// where other rows hold an object ("failure": null beside "failure": {...})
// makes no column of its own. Returns the number of columns written.
std::size_t write_json_rows(ColumnsFile& file, const std::vector<nlohmann::json>& rows);

// The same columns, as values (the Python module's epviz.sweep): each
// numbers or text, by the rule above.
struct JsonColumn {
  std::string name;
  bool text = false;
  std::vector<double> numbers;     // when not text: one per row
  std::vector<std::string> texts;  // when text: one per row
};
std::vector<JsonColumn> json_columns(const std::vector<nlohmann::json>& rows);

}  // namespace epviz::h5
