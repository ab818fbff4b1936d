#include "study/text_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace epviz::study {

std::string text_table(const std::string& title, const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows) {
  if (rows.empty()) return "";
  std::vector<std::size_t> width;
  for (const auto& h : header) width.push_back(h.size());
  for (const auto& row : rows)
    for (std::size_t i = 0; i < row.size() && i < width.size(); ++i)
      width[i] = std::max(width[i], row[i].size());
  std::string text = "\n";
  text += title;
  text += '\n';
  auto add_line = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < width.size(); ++i) {
      const std::string cell = i < cells.size() ? cells[i] : "";
      text += cell;
      text.append(width[i] - std::min(width[i], cell.size()) + 1, ' ');
    }
    text += '\n';
  };
  add_line(header);
  for (const auto& row : rows) add_line(row);
  return text;
}

std::string cell_number(double x) {
  if (!std::isfinite(x)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

}  // namespace epviz::study
