#include "sweep/ftle_curves.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "io/json_reader.hpp"
#include "io/json_text.hpp"
#include "io/number_text.hpp"
#include "sweep/atlas_labels.hpp"

namespace epviz::sweep {

namespace {

using Json = nlohmann::json;

// The guide: a grey line (paint's series colour 12) without markers, dense
// enough to look smooth on the log axes.
constexpr int kGuideColour = 12, kGuidePoints = 40;

std::string value_text(const Json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number()) return io::number_text(v.get<double>(), 4);
  if (v.is_array()) {
    std::string s = "(";
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i > 0) s += ", ";
      s += value_text(v[i]);
    }
    return s + ")";
  }
  return io::json_text(v);
}

// "case kovalevskaya, γ₁ = 0.3": the point's axis values, or its index when it has none.
std::string point_name(const Json& row) {
  std::string name;
  if (row.contains("axes") && row["axes"].is_object())
    for (const auto& [field, v] : row["axes"].items()) {
      if (!name.empty()) name += ", ";
      name += v.is_string() ? field + " " + v.get<std::string>()
                            : axis_symbol(field) + " = " + value_text(v);
    }
  if (name.empty()) name = "point " + std::to_string(row.value("index", 0L));
  return name;
}

}  // namespace

std::string ftle_curve_problem(const Json& row) {
  const auto it = row.find("ftle_curve");
  if (it == row.end()) return "";
  const std::string allowed =
      "key 'ftle_curve': expected a list of [T, λ] pairs, T a positive number and λ a number or "
      "null";
  if (!it->is_array()) return allowed + ", got " + io::describe(*it);
  for (std::size_t i = 0; i < it->size(); ++i) {
    const Json& p = (*it)[i];
    const bool ok = p.is_array() && p.size() == 2 && p[0].is_number() && p[0].get<double>() > 0.0 &&
                    (p[1].is_number() || p[1].is_null());
    if (!ok) return allowed + "; item " + std::to_string(i) + " is " + io::describe(p);
  }
  return "";
}

std::optional<chart::Figure> ftle_curve_figure(const std::vector<Json>& rows,
                                               const std::optional<FtleSettings>& ftle) {
  chart::ChartSpec c;
  c.title = "λ(T): the FTLE over the first T of each run";
  c.x_label = "time T";
  if (ftle)
    c.x_label += " (window " + io::number_text(ftle->window, 3) + ", separation " +
                 io::number_text(ftle->separation, 2) + ")";
  c.y_label = "λ(T) (1/time)";
  c.log_x = c.log_y = true;
  // A regular orbit's λ(T) may be negative at small T (neighbours first
  // approach): those points are marked in a row of their own under the log axis.
  c.nonpositive_label = "λ ≤ 0";
  // The guide goes through the lowest last point (the most regular orbit).
  double lowest = std::numeric_limits<double>::infinity(), lowest_t = 0.0, t_min = 0.0, t_max = 0.0;
  for (const auto& row : rows) {
    if (!row.contains("ftle_curve") || !row["ftle_curve"].is_array()) continue;
    chart::ChartSeries s;
    s.name = point_name(row);
    for (const auto& p : row["ftle_curve"]) {
      if (!p[1].is_number()) continue;  // null: λ was not finite there
      const double t = p.at(0).get<double>(), lambda = p.at(1).get<double>();
      s.points.push_back({t, lambda});
      t_min = t_min > 0.0 ? std::min(t_min, t) : t;
      t_max = std::max(t_max, t);
    }
    if (!s.points.empty() && s.points.back().y > 0.0 && s.points.back().y < lowest) {
      lowest = s.points.back().y;
      lowest_t = s.points.back().x;
    }
    c.series.push_back(std::move(s));
  }
  if (c.series.empty()) return std::nullopt;
  // c · ln T / T is 0 at T = 1 and negative before; drawn where ln T > 0.
  if (std::isfinite(lowest) && lowest_t > 1.0) {
    chart::ChartSeries guide;
    guide.name = "∝ ln T / T (regular orbit)";
    guide.colour_key = kGuideColour;
    guide.style = chart::SeriesStyle::line;
    const double scale = lowest * lowest_t / std::log(lowest_t);
    const double from = std::max(t_min, 2.0);
    for (int i = 0; i <= kGuidePoints; ++i) {
      const double t = from * std::pow(t_max / from, double(i) / kGuidePoints);
      guide.points.push_back({t, scale * std::log(t) / t});
    }
    c.series.push_back(std::move(guide));
  }
  return chart::Figure{"ftle_curves.png", std::move(c)};
}

}  // namespace epviz::sweep
