#include "sweep/atlas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

#include "io/json_text.hpp"
#include "io/printable.hpp"
#include "physics/notation.hpp"
#include "sweep/atlas_labels.hpp"

namespace epviz::sweep {
namespace {

using Json = nlohmann::json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string label_of(const Json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v.get<double>());
    return buf;
  }
  return io::json_text(v);
}

// The metric of one row; NaN when the row has none (null, or a failure's
// time for a run that did not fail).
double metric_of(const Json& row, const std::string& metric) {
  if (metric == "time_to_failure") {
    if (row.contains("failure") && row["failure"].is_object())
      return row["failure"]["t"].get<double>();
    return row.contains("t_end") ? row["t_end"].get<double>() : kNaN;
  }
  const Json* v = &row;
  std::size_t pos = 0;
  while (pos <= metric.size()) {
    const auto dot = metric.find('.', pos);
    const std::string key =
        metric.substr(pos, dot == std::string::npos ? std::string::npos : dot - pos);
    if (!v->is_object() || !v->contains(key)) return kNaN;
    v = &(*v)[key];
    if (dot == std::string::npos) break;
    pos = dot + 1;
  }
  return v->is_number() ? v->get<double>() : kNaN;
}

bool has_metric(const std::vector<Json>& rows, const std::string& metric) {
  const std::string root = metric.substr(0, metric.find('.'));
  for (const auto& r : rows)
    if (r.contains(root)) return true;
  return false;
}

// File names without characters a shell would glob or quote: "gamma[0]" -> "gamma0".
std::string safe(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '[' || c == ']') continue;
    const bool plain =
        std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_' || c == '=';
    out.push_back(plain ? c : '_');
  }
  return out;
}

// The sweep's axes: those of the row of the lowest index (every row has the
// same; a forged row without them has none).
std::vector<std::string> axis_names(const std::vector<Json>& rows) {
  const Json* first = nullptr;
  for (const auto& r : rows)
    if (!first || r["index"].get<long>() < (*first)["index"].get<long>()) first = &r;
  std::vector<std::string> names;
  if (!first) return names;
  const auto axes = first->find("axes");
  if (axes == first->end() || !axes->is_object()) return names;
  for (auto it = axes->begin(); it != axes->end(); ++it) names.push_back(it.key());
  return names;
}

// Each map takes the others as its margin peers (without theirs: one level deep).
void share_plot_area(std::vector<AtlasFigure>& figures) {
  for (auto& f : figures) f.heat_map.margin_peers.clear();
  std::vector<chart::HeatMapSpec> all;
  for (const auto& f : figures) all.push_back(f.heat_map);
  for (std::size_t i = 0; i < figures.size() && figures.size() > 1; ++i)
    for (std::size_t j = 0; j < all.size(); ++j)
      if (j != i) figures[i].heat_map.margin_peers.push_back(all[j]);
}

}  // namespace

AtlasRequest parse_atlas_option(const std::string& text) {
  // The metric may itself hold a ':' ("largest_stable:step"): x and y are the last two fields.
  const auto b = text.rfind(':');
  const auto a = b == std::string::npos || b == 0 ? std::string::npos : text.rfind(':', b - 1);
  if (a == std::string::npos || a == 0 || b == a + 1 || b + 1 >= text.size())
    throw AtlasError(
        "--atlas: expected METRIC:XAXIS:YAXIS (e.g. ftle:gamma[0]:gamma[1] or "
        "largest_stable:step:energy:method), got " +
        io::quoted(text));
  return {text.substr(0, a), text.substr(a + 1, b - a - 1), text.substr(b + 1)};
}

void check_atlas_request(const std::vector<Json>& rows, const AtlasRequest& q) {
  const std::string atlas = "atlas " + io::quoted(q.metric);
  if (rows.empty()) throw AtlasError(atlas + ": the sweep has no rows");
  const std::vector<std::string> names = axis_names(rows);
  auto is_axis = [&](const std::string& n) {
    return std::find(names.begin(), names.end(), n) != names.end();
  };
  std::string allowed;
  for (const auto& n : names) allowed += (allowed.empty() ? "" : ", ") + io::printable(n);
  const std::string stable = "largest_stable:";
  std::vector<std::string> axes{q.x, q.y};
  if (q.metric.starts_with(stable)) axes.push_back(q.metric.substr(stable.size()));
  for (const auto& n : axes)
    if (!is_axis(n))
      throw AtlasError(atlas + ": " + io::quoted(n) +
                       " is not an axis of the sweep (axes: " + allowed + ")");
  if (!q.metric.starts_with(stable) && q.metric != "time_to_failure" && !has_metric(rows, q.metric))
    throw AtlasError(atlas +
                     ": no row has this metric (e.g. ftle, reference_error, "
                     "max_relative_drift.energy, time_to_failure, largest_stable:AXIS, "
                     "cpu_seconds)");
}

std::vector<AtlasFigure> atlas_figures(const std::vector<Json>& rows, const AtlasRequest& q,
                                       const std::optional<FtleSettings>& ftle,
                                       const SelfCheck* check) {
  check_atlas_request(rows, q);
  std::vector<Json> sorted = rows;
  std::sort(sorted.begin(), sorted.end(), [](const Json& a, const Json& b) {
    return a["index"].get<long>() < b["index"].get<long>();
  });
  // Axis names and their values in sweep order (first appearance in index order).
  const std::vector<std::string> names = axis_names(sorted);
  const std::string stable = "largest_stable:";
  const std::string reduced =
      q.metric.starts_with(stable) ? q.metric.substr(stable.size()) : std::string();
  std::map<std::string, std::vector<std::string>> values;  // labels in order
  std::map<std::string, std::map<std::string, std::size_t>> position;
  std::map<std::string, std::map<std::string, double>> number;  // of numeric axes' labels
  std::set<std::string> numeric(names.begin(), names.end());
  for (const auto& r : sorted)
    for (const auto& n : names) {
      const Json& v = r["axes"][n];
      const std::string l = label_of(v);
      if (v.is_number())
        number[n].emplace(l, v.get<double>());
      else
        numeric.erase(n);
      if (!position[n].count(l)) {
        position[n][l] = values[n].size();
        values[n].push_back(l);
      }
    }
  // Numeric x and y axes ascend (left to right, bottom to top) whatever the
  // sweep's order (the stability atlas lists its steps from the largest).
  for (const auto* n : {&q.x, &q.y}) {
    if (!numeric.count(*n)) continue;
    auto& v = values[*n];
    std::stable_sort(v.begin(), v.end(), [&](const std::string& a, const std::string& b) {
      return number[*n][a] < number[*n][b];
    });
    for (std::size_t k = 0; k < v.size(); ++k) position[*n][v[k]] = k;
  }
  // One figure per combination of the axes that are left over.
  std::map<std::string, std::vector<const Json*>> groups;
  for (const auto& r : sorted) {
    std::string key;
    for (const auto& n : names)
      if (n != q.x && n != q.y && n != reduced && values[n].size() > 1)
        key += "_" + n + "=" + label_of(r["axes"][n]);
    groups[key].push_back(&r);
  }
  std::vector<AtlasFigure> out;
  for (const auto& [key, members] : groups) {
    AtlasFigure f;
    auto& h = f.heat_map;
    h.columns = values[q.x];
    // The heat map lists rows top down: a numeric y axis from its largest
    // value, so that it reads upwards; names (methods) in the sweep's order.
    const bool upwards = numeric.count(q.y) > 0;
    if (upwards)
      h.rows.assign(values[q.y].rbegin(), values[q.y].rend());
    else
      h.rows = values[q.y];
    if (numeric.count(q.x))
      for (const auto& c : h.columns) h.column_values.push_back(number[q.x][c]);
    if (upwards)
      for (const auto& r : h.rows) h.row_values.push_back(number[q.y][r]);
    h.x_label = axis_title(q.x, members);
    h.y_label = axis_title(q.y, members);
    h.value_label = metric_label(q.metric, members);
    const std::string over = axis_symbol(q.x) + " and " + axis_symbol(q.y);
    h.title = reduced.empty()
                  ? h.value_label + " over " + over
                  : "largest " + axis_symbol(reduced) + " without a failure, by " + over;
    std::string fixed;  // axes with one value: named in the title only
    for (const auto& n : names)
      if (n != q.x && n != q.y && n != reduced && values[n].size() == 1)
        fixed += ", " + axis_symbol(n) + " = " + values[n][0];
    std::string varied;  // this figure's values of the left-over axes
    for (const auto& n : names)
      if (n != q.x && n != q.y && n != reduced && values[n].size() > 1)
        varied += ", " + axis_symbol(n) + " = " + label_of((*members.front())["axes"][n]);
    if (!varied.empty() || !fixed.empty()) h.title += " (" + (varied + fixed).substr(2) + ")";
    h.note = atlas_caption(members, q.metric, ftle);
    // The verdict on the metric's accuracy heads the figure (the note under
    // the map is one line, already full of how the runs were made).
    if (check)
      if (const auto verdict = self_check_caption(*check, q.metric); !verdict.empty())
        h.title += " — " + verdict;
    h.missing = reduced.empty() ? (q.metric == "ftle" ? "no value (a run failed)" : "no value")
                                : "every " + reduced + " failed";
    // A level near the boundary may have no state on the generator's grid.
    if (members.front()->contains("admissible"))
      h.missing = "no value (no orbit found or all lost)";
    h.values.assign(h.rows.size(), std::vector<double>(h.columns.size(), kNaN));
    for (const Json* r : members) {
      const std::size_t i = position[q.x][label_of((*r)["axes"][q.x])];
      const std::size_t j = position[q.y][label_of((*r)["axes"][q.y])];
      const std::size_t row = upwards ? h.rows.size() - 1 - j : j;
      double& cell = h.values[row][i];
      // A level below the least energy at its C0 has no states: hatched
      // as such, not grey as a failed run (sweep/level_point.hpp).
      if (r->contains("admissible") && (*r)["admissible"] == false) {
        if (h.undecided.empty())
          h.undecided.assign(h.rows.size(), std::vector<bool>(h.columns.size(), false));
        h.undecided[row][i] = true;
        h.undecided_label = "inadmissible: below the least energy at this ";
        h.undecided_label += physics::symbol::area;
        continue;
      }
      if (!reduced.empty()) {
        const bool failed = !(*r)["failure"].is_null();
        const Json& v = (*r)["axes"][reduced];
        if (!failed && v.is_number() && !(cell >= v.get<double>())) cell = v.get<double>();
      } else {
        cell = metric_of(*r, q.metric);
      }
    }
    // Positive values spread over more than two decades read best in log10.
    double lo = HUGE_VAL, hi = 0.0;
    bool positive = true;
    for (const auto& row : h.values)
      for (double v : row)
        if (std::isfinite(v)) {
          positive &= v > 0.0;
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
    // (a largest step on a log grid reads best in log10 whatever its spread).
    // A colour bar fixed to start at zero or below cannot be logarithmic;
    // values all below 1e-3 (a drift of an integral) read only in log10.
    h.log_scale = positive && hi > 0.0 && lo > 0.0 && !(q.min <= 0.0) &&
                  (hi / lo > 100.0 || hi < 1e-3 || (!reduced.empty() && hi / lo > 4.0));
    h.range_min = q.min;
    h.range_max = q.max;
    f.file_name = safe("atlas_" + q.metric + "_" + q.x + "_" + q.y + key + ".png");
    out.push_back(std::move(f));
  }
  share_plot_area(out);
  return out;
}

std::vector<AtlasFigure> atlas_figure_set(const std::vector<Json>& rows,
                                          const std::vector<AtlasRequest>& requests,
                                          const std::optional<FtleSettings>& ftle,
                                          const SelfCheck* check) {
  std::vector<AtlasFigure> out;
  for (const auto& q : requests)
    for (auto& f : atlas_figures(rows, q, ftle, check)) out.push_back(std::move(f));
  share_plot_area(out);
  return out;
}

}  // namespace epviz::sweep
