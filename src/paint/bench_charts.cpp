#include "paint/bench_charts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "io/png_writer.hpp"
#include "render/gl_context.hpp"

namespace epviz::paint {
namespace {

using nlohmann::json;

std::string text_of(const json& row, const char* key) {
  const auto it = row.find(key);
  if (it == row.end() || it->is_null()) return {};
  if (it->is_string()) return it->get<std::string>();
  if (it->is_number()) {
    const double v = it->get<double>();
    char buf[32];
    if (v == std::floor(v) && std::abs(v) < 1e7)
      std::snprintf(buf, sizeof buf, "%.0f", v);
    else
      std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
  }
  return it->dump();
}

double number_of(const json& row, const char* key) {
  const auto it = row.find(key);
  return it != row.end() && it->is_number() ? it->get<double>() : std::nan("");
}

const json& rows_of(const json& bench) {
  static const json empty = json::array();
  if (bench.is_object() && bench.contains("rows") && bench["rows"].is_array()) return bench["rows"];
  if (bench.is_array()) return bench;
  return empty;
}

bool ok(const json& row) {
  const std::string status = text_of(row, "status");
  return status.empty() || status == "ok";
}

// Series name of a row: formulation/method, with the impl when it is not ours.
std::string series_name(const json& row) {
  std::string name = text_of(row, "method");
  const std::string f = text_of(row, "formulation");
  if (!f.empty() && f != "direct") name = f + " " + name;
  const std::string impl = text_of(row, "impl");
  if (!impl.empty() && impl != "epviz") name += " (" + impl + ")";
  return name;
}

void sort_by_x(ChartSeries& s) {
  std::sort(s.points.begin(), s.points.end(), [](const ChartPoint& a, const ChartPoint& b) { return a.x < b.x; });
}

}  // namespace

std::vector<NamedChart> bench_chart_specs(const json& bench) {
  std::vector<NamedChart> charts;
  // case -> series name -> (cost, error) points, for both cost measures.
  std::map<std::string, std::map<std::string, std::pair<ChartSeries, ChartSeries>>> wp;
  std::map<std::string, std::vector<ChartSeries>> drift;
  for (const auto& row : rows_of(bench)) {
    if (!row.is_object()) continue;
    const std::string study = text_of(row, "study");
    const std::string c = text_of(row, "case");
    if (study == "work_precision" && ok(row)) {
      const double error = number_of(row, "error");
      if (!(error > 0.0)) continue;
      auto& [by_cpu, by_evals] = wp[c][series_name(row)];
      by_cpu.name = by_evals.name = series_name(row);
      const double cpu = number_of(row, "cpu_ms"), evals = number_of(row, "rhs_evals");
      if (cpu > 0.0) by_cpu.points.push_back({cpu, error});
      if (evals > 0.0) by_evals.points.push_back({evals, error});
    } else if (study == "drift" && row.contains("series_t") && row["series_t"].is_array()) {
      const auto& t = row["series_t"];
      for (const auto& [key, what] : {std::pair{"series_drift_C1", "C1"}, std::pair{"series_drift_extra", "4th integral"}}) {
        if (!row.contains(key) || !row[key].is_array()) continue;
        const auto& v = row[key];
        ChartSeries s;
        s.name = series_name(row) + ", " + what;
        for (std::size_t i = 0; i < std::min(t.size(), v.size()); ++i)
          if (t[i].is_number() && v[i].is_number()) s.points.push_back({t[i].get<double>(), std::abs(v[i].get<double>())});
        drift[c].push_back(std::move(s));
      }
    }
  }
  for (auto& [c, by_name] : wp) {
    NamedChart cpu{"work_precision_" + c + ".png",
                   {"Work-precision: " + c, "CPU time [ms]", "error at t_end", true, true, {}}};
    NamedChart evals{"work_precision_evals_" + c + ".png",
                     {"Work-precision: " + c, "right-hand side evaluations", "error at t_end", true, true, {}}};
    for (auto& [name, pair] : by_name) {
      sort_by_x(pair.first);
      sort_by_x(pair.second);
      if (!pair.first.points.empty()) cpu.spec.series.push_back(pair.first);
      if (!pair.second.points.empty()) evals.spec.series.push_back(pair.second);
    }
    charts.push_back(std::move(cpu));
    charts.push_back(std::move(evals));
  }
  for (auto& [c, series] : drift)
    charts.push_back({"drift_" + c + ".png",
                      {"Relative drift of the integrals: " + c, "time", "relative drift", false, true, series}});
  return charts;
}

TableSpec bench_stability_table(const json& bench) {
  TableSpec t;
  t.title = "Stability studies";
  t.header = {"study", "case", "method", "formulation", "status", "result"};
  for (const auto& row : rows_of(bench)) {
    if (!row.is_object()) continue;
    const std::string study = text_of(row, "study");
    if (study.rfind("stability_", 0) != 0) continue;
    std::string result;
    auto add = [&](const char* label, const char* key) {
      const std::string v = text_of(row, key);
      if (v.empty()) return;
      if (!result.empty()) result += ", ";
      result += std::string(label) + " " + v;
    };
    if (study == "stability_max_step") {
      add("max step", "max_step");
      add("h/period", "max_step_over_period");
    } else if (study == "stability_separatrix") {
      add("step", "step");
      add("flip time err", "flip_time_error");
    } else if (study == "stability_sleeping_top") {
      add("step", "step");
      add("gamma err", "gamma_error");
      add("reached", "reached");
    } else if (study == "stability_chaos") {
      add("step", "step");
      add("separated", "separated");
      add("at", "separation_time");
    } else if (study == "stability_pole") {
      add("variant", "variant");
      add("error", "error");
    } else {
      add("error", "error");
    }
    std::string status = text_of(row, "status");
    if (status.empty()) status = text_of(row, "failure_reason").empty() ? "ok" : "limit";
    t.rows.push_back({study.substr(10), text_of(row, "case"), text_of(row, "method"), text_of(row, "formulation"),
                      status, result});
  }
  return t;
}

std::vector<std::filesystem::path> write_bench_charts(const json& bench, const std::filesystem::path& out_dir,
                                                      const std::string& gl_backend, const ChartOptions& options) {
  std::vector<std::filesystem::path> written;
  const auto charts = bench_chart_specs(bench);
  const TableSpec table = bench_stability_table(bench);
  if (charts.empty() && table.rows.empty()) return written;
  std::filesystem::create_directories(out_dir);
  auto context = render::make_gl_context(gl_backend, 16, 16);
  auto save = [&](const std::string& name, const render::RgbaImage& img) {
    const auto path = out_dir / name;
    io::write_png_rgba(path, img.width, img.height, img.pixels);
    written.push_back(path);
  };
  for (const auto& c : charts) save(c.file_name, paint_chart(*context, c.spec, options));
  if (!table.rows.empty()) {
    ChartOptions o = options;
    // Tall enough for every row.
    o.font_px = chart_font_px(options);
    const float line = o.font_px * 1.5f;
    o.height = std::max(o.height, int(line * float(table.rows.size() + 4)));
    save("stability.png", paint_table(*context, table, o));
  }
  return written;
}

}  // namespace epviz::paint
