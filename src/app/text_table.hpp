#pragma once
// Plain-text tables on stdout: a title, a header and rows of cells, each
// column as wide as its widest cell. A table is described by its columns, each
// a header and how to read the cell from a row.
#include <functional>
#include <string>
#include <vector>

namespace epviz::app {

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

// Prints a blank line, the title, the header and the rows, columns separated
// by a space and padded to their widest cell; nothing when there are no rows.
void print_text_table(const std::string& title, const std::vector<std::string>& header,
                      const std::vector<std::vector<std::string>>& rows);

template <class Row>
void print_table(const TextTable<Row>& table, const std::vector<const Row*>& rows) {
  std::vector<std::string> header;
  for (const auto& c : table.columns) header.push_back(c.header);
  std::vector<std::vector<std::string>> cells;
  for (const Row* r : rows) {
    auto& line = cells.emplace_back();
    for (const auto& c : table.columns) line.push_back(c.cell(*r));
  }
  print_text_table(table.title, header, cells);
}

// A number to three significant digits, "-" when it is not finite.
std::string cell_number(double x);

}  // namespace epviz::app
