#include "app/text_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace epviz::app {

void print_text_table(const std::string& title, const std::vector<std::string>& header,
                      const std::vector<std::vector<std::string>>& rows) {
  if (rows.empty()) return;
  std::vector<std::size_t> width;
  for (const auto& h : header) width.push_back(h.size());
  for (const auto& row : rows)
    for (std::size_t i = 0; i < row.size() && i < width.size(); ++i)
      width[i] = std::max(width[i], row[i].size());
  auto print_line = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < width.size(); ++i)
      std::printf("%-*s ", int(width[i]), i < cells.size() ? cells[i].c_str() : "");
    std::printf("\n");
  };
  std::printf("\n%s\n", title.c_str());
  print_line(header);
  for (const auto& row : rows) print_line(row);
}

std::string cell_number(double x) {
  if (!std::isfinite(x)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

}  // namespace epviz::app
