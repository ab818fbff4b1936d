#include "h5/json_rows.hpp"

#include <limits>
#include <map>
#include <string>

namespace epviz::h5 {
namespace {

using Json = nlohmann::json;

struct Column {
  std::string name;
  std::vector<const Json*> cells;  // one per row; nullptr: the row lacks it
};

class Table {
 public:
  explicit Table(std::size_t rows) : rows_(rows) {}

  void add(std::size_t row, const std::string& path, const Json& value) {
    if (value.is_object() || value.is_array()) {
      std::size_t i = 0;
      if (value.is_object()) {
        for (const auto& [key, child] : value.items())
          add(row, path.empty() ? key : path + "." + key, child);
      } else {
        for (const auto& child : value) add(row, path + "[" + std::to_string(i++) + "]", child);
      }
      return;
    }
    auto [at, fresh] = index_.try_emplace(path, columns_.size());
    if (fresh) columns_.push_back({path, std::vector<const Json*>(rows_, nullptr)});
    columns_[at->second].cells[row] = &value;
  }

  const std::vector<Column>& columns() const { return columns_; }

  // A column of nulls only, named as the parent of other columns.
  bool is_bare_parent(const Column& c) const {
    for (const Json* v : c.cells)
      if (v && !v->is_null()) return false;
    const auto next = index_.upper_bound(c.name);
    if (next == index_.end()) return false;
    const std::string& other = next->first;
    return other.size() > c.name.size() && other.compare(0, c.name.size(), c.name) == 0 &&
           (other[c.name.size()] == '.' || other[c.name.size()] == '[');
  }

 private:
  std::size_t rows_;
  std::vector<Column> columns_;
  std::map<std::string, std::size_t> index_;
};

bool is_numeric(const Column& c) {
  for (const Json* v : c.cells)
    if (v && !(v->is_null() || v->is_number() || v->is_boolean())) return false;
  return true;
}

}  // namespace

std::vector<JsonColumn> json_columns(const std::vector<Json>& rows) {
  Table table(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) table.add(r, "", rows[r]);
  std::vector<JsonColumn> out;
  for (const auto& c : table.columns()) {
    if (table.is_bare_parent(c)) continue;
    JsonColumn column{c.name, !is_numeric(c), {}, {}};
    for (const Json* v : c.cells) {
      if (!column.text)
        column.numbers.push_back(!v || v->is_null() ? std::numeric_limits<double>::quiet_NaN()
                                 : v->is_boolean()  ? (v->get<bool>() ? 1.0 : 0.0)
                                                    : v->get<double>());
      else
        column.texts.push_back(!v || v->is_null() ? std::string()
                               : v->is_string()   ? v->get<std::string>()
                                                  : v->dump());
    }
    out.push_back(std::move(column));
  }
  return out;
}

std::size_t write_json_rows(ColumnsFile& file, const std::vector<Json>& rows) {
  const auto columns = json_columns(rows);
  for (const auto& c : columns) {
    if (c.text)
      file.write_text_column(c.name, c.texts);
    else
      file.write_column(c.name, c.numbers);
  }
  return columns.size();
}

}  // namespace epviz::h5
