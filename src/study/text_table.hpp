#pragma once
// Plain-text tables, as `epviz bench` prints them: a title, a header and rows
// of cells, each column as wide as its widest cell. A table is described by
// its columns, each a header and how to read the cell from a row.
#include <functional>
#include <string>
#include <vector>

namespace epviz::study {

template <class Row>
struct TextColumn {
  std::string header;
  std::function<std::string(const Row&)> cell;
};

template <class Row>
struct TextTable {
  std::string title;
  std::vector<TextColumn<Row>> columns;
};

// A blank line, the title, the header and the rows, each line ending in a
// newline, columns followed by a space and padded to their widest cell; ""
// when there are no rows.
std::string text_table(const std::string& title, const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows);

template <class Row>
std::string text_table(const TextTable<Row>& table, const std::vector<const Row*>& rows) {
  std::vector<std::string> header;
  for (const auto& c : table.columns) header.push_back(c.header);
  std::vector<std::vector<std::string>> cells;
  for (const Row* r : rows) {
    auto& line = cells.emplace_back();
    for (const auto& c : table.columns) line.push_back(c.cell(*r));
  }
  return text_table(table.title, header, cells);
}

// A number to three significant digits, "-" when it is not finite.
std::string cell_number(double x);

}  // namespace epviz::study
