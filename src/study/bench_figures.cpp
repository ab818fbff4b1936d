#include "study/bench_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <string_view>

#include "physics/cases.hpp"
#include "physics/notation.hpp"
#include "sim/run_spec.hpp"
#include "study/stability.hpp"

namespace epviz::study {
namespace {

using chart::ChartPoint;
using chart::ChartSeries;
using chart::ChartSpec;
using chart::TableSpec;

// A table cell: whole numbers in full, others to three significant digits.
std::string cell_number(double v) {
  char buf[32];
  if (v == std::floor(v) && std::abs(v) < 1e7)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else
    std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// Series name of a run: formulation/method, with the impl when it is not ours.
std::string series_name(const RunRecord& r) {
  std::string name = r.method;
  if (!r.formulation.empty() && r.formulation != "direct") name = r.formulation + " " + name;
  if (!r.impl.empty() && r.impl != "epviz") name += " (" + r.impl + ")";
  return name;
}

// Colour keys: epviz's methods in their table order, so that a method has the
// same colour in every chart; other names (peers' methods) after them, in the
// order first met.
class StyleKeys {
 public:
  int colour(const std::string& method) {
    const auto& all = sim::all_methods();
    for (std::size_t i = 0; i < all.size(); ++i)
      if (sim::name(all[i]) == method) return int(i);
    return other(colours_, method, int(all.size()));
  }
  // Marker keys: epviz's formulations, then other implementations (one shape
  // per peer library, whatever its formulation).
  int marker(const RunRecord& r) {
    const auto& all = sim::all_formulations();
    if (r.impl.empty() || r.impl == "epviz")
      for (std::size_t i = 0; i < all.size(); ++i)
        if (sim::name(all[i]) == r.formulation) return int(i);
    return other(markers_, r.impl, int(all.size()));
  }

 private:
  static int other(std::vector<std::string>& seen, const std::string& name, int first) {
    const auto it = std::find(seen.begin(), seen.end(), name);
    if (it != seen.end()) return first + int(it - seen.begin());
    seen.push_back(name);
    return first + int(seen.size()) - 1;
  }
  std::vector<std::string> colours_, markers_;
};

// The legend of a chart whose series carry keys: each key once, named.
void add_legend_key(std::vector<chart::LegendKey>& legend, int key, const std::string& name) {
  for (const auto& k : legend)
    if (k.key == key) return;
  legend.push_back({name, key});
}

std::string marker_name(const RunRecord& r) {
  if (!r.impl.empty() && r.impl != "epviz") return r.impl;
  return r.formulation.empty() ? "direct" : r.formulation;
}

void sort_by_x(ChartSeries& s) {
  std::sort(s.points.begin(), s.points.end(),
            [](const ChartPoint& a, const ChartPoint& b) { return a.x < b.x; });
}

// The "result" column of the stability table: labelled values, the missing ones left out.
class Result {
 public:
  Result& add(const char* label, double v) {
    return std::isfinite(v) ? add(label, cell_number(v)) : *this;
  }
  Result& add(const char* label, const std::string& v) {
    if (v.empty()) return *this;
    if (!text_.empty()) text_ += ", ";
    text_ += std::string(label) + " " + v;
    return *this;
  }
  std::string text() const { return text_; }

 private:
  std::string text_;
};

std::vector<std::string> table_row(const char* study, const RunRecord& r, const Result& result) {
  return {study, r.case_name, r.method, r.formulation, r.ok ? "ok" : "failed", result.text()};
}

ChartSpec chart_of(std::string title, std::string x_label, std::string y_label, bool log_x) {
  ChartSpec chart;
  chart.title = std::move(title);
  chart.x_label = std::move(x_label);
  chart.y_label = std::move(y_label);
  chart.log_x = log_x;
  chart.log_y = true;
  return chart;
}

// The families the drift chart has a panel for, in the order drawn: methods
// of a family drift alike (explicit ones steadily, symplectic ones bounded),
// so that a panel shows a few lines that differ by their settings.
std::string_view method_family(sim::Method m) { return sim::info(m).family; }

std::string_view method_family(const std::string& method) {
  const auto m = sim::method_from_name(method);
  return m ? method_family(*m) : "other";
}

// The names of the integrals a drift series follows, as the renders and
// atlases write them (physics/notation.hpp): marker key 0 the energy C₁, 1
// the case's own fourth integral (K, Ω₃, ...), 2 the geometric integral |γ|².
constexpr int kEnergyKey = 0, kExtraKey = 1, kGammaKey = 2;
std::string integral_name(const std::string& case_name, int key) {
  if (key == kEnergyKey) return std::string(physics::symbol::energy);
  if (key == kGammaKey) return std::string(physics::symbol::gamma_norm2);
  const auto c = physics::case_from_name(case_name);
  const std::string_view symbol = c ? physics::integral_symbol(*c) : std::string_view();
  return symbol.empty() ? "fourth integral" : std::string(symbol);
}

// The drift series of one case as small multiples: a panel per method family
// (in the methods' order), each with its methods' legend, all on the same axes.
ChartSpec drift_panels(const std::string& case_name, std::vector<ChartSeries> series) {
  ChartSpec chart =
      chart_of("Relative drift of the integrals: " + case_name, "time", "relative drift", false);
  std::vector<std::string_view> families;
  for (const auto m : sim::all_methods())
    if (std::find(families.begin(), families.end(), method_family(m)) == families.end())
      families.push_back(method_family(m));
  for (const auto family : families) {
    ChartSpec panel = chart_of(std::string(family), "time", "relative drift", false);
    for (const auto& one : series) {
      const std::string method = one.name.substr(0, one.name.find(", "));
      if (method_family(method) != family) continue;
      add_legend_key(panel.colour_legend, one.colour_key, method);
      add_legend_key(panel.marker_legend, one.marker_key, integral_name(case_name, one.marker_key));
      panel.series.push_back(one);
    }
    if (!panel.series.empty()) chart.panels.push_back(std::move(panel));
  }
  return chart;
}

}  // namespace

TableSpec stability_table(const std::vector<StudyRow>& rows, bool with_heat_mapped) {
  TableSpec t;
  t.title = "Stability studies";
  t.header = {"study", "case", "method", "formulation", "status", "result"};
  for (const auto& row : rows) {
    if (const auto* max_step = std::get_if<MaxStepRow>(&row); max_step && with_heat_mapped) {
      const auto result = Result()
                              .add("max step", max_step->max_step)
                              .add("h/period", max_step->max_step_over_period);
      t.rows.push_back({"max_step", max_step->case_name, max_step->method, max_step->formulation,
                        max_step->failure_reason.empty() ? "ok" : "limit", result.text()});
    } else if (const auto* pole = std::get_if<PolePassageRow>(&row)) {
      t.rows.push_back(table_row("pole", pole->run,
                                 Result().add("variant", pole->variant).add("error", pole->error)));
    } else if (const auto* separatrix = std::get_if<SeparatrixRow>(&row);
               separatrix && with_heat_mapped) {
      t.rows.push_back(table_row("separatrix", separatrix->run,
                                 Result()
                                     .add("step", separatrix->run.step)
                                     .add("flip time err", separatrix->flip_time_error)));
    } else if (const auto* sleeping = std::get_if<SleepingTopRow>(&row)) {
      t.rows.push_back(table_row("sleeping_top", sleeping->run,
                                 Result()
                                     .add("step", sleeping->run.step)
                                     .add("gamma err", sleeping->gamma_error)
                                     .add("reached", sleeping->reached ? "yes" : "no")));
    } else if (const auto* chaos = std::get_if<ChaosRow>(&row); chaos && with_heat_mapped) {
      t.rows.push_back(table_row("chaos", chaos->run,
                                 Result()
                                     .add("step", chaos->run.step)
                                     .add("separated", !chaos->reference_decides ? "undecided"
                                                       : chaos->separated        ? "yes"
                                                                                 : "no")
                                     .add("at", chaos->separation_time)));
    }
  }
  return t;
}

chart::HeatMapSpec stability_heat_map(const std::vector<StudyRow>& rows) {
  chart::HeatMapSpec h;
  h.title = "Stability: largest fixed step that keeps the motion";
  h.value_label = "step / fastest period";
  h.note = "bisection on the step over t = 20; fails on blow-up, drift of " +
           std::string(physics::symbol::energy) + " or " +
           std::string(physics::symbol::gamma_norm2) + " > 1, or error > 0.1";
  const auto max_step = rows_of<MaxStepRow>(rows);
  auto index_of = [](std::vector<std::string>& names, const std::string& n) {
    const auto it = std::find(names.begin(), names.end(), n);
    if (it != names.end()) return std::size_t(it - names.begin());
    names.push_back(n);
    return names.size() - 1;
  };
  for (const auto* r : max_step) {
    index_of(h.rows, r->formulation.empty() || r->formulation == "direct"
                         ? r->method
                         : r->method + " (" + r->formulation + ")");
    index_of(h.columns, r->case_name);
  }
  h.values.assign(h.rows.size(), std::vector<double>(h.columns.size(), kNaN));
  for (const auto* r : max_step) {
    const std::size_t i = index_of(h.rows, r->formulation.empty() || r->formulation == "direct"
                                               ? r->method
                                               : r->method + " (" + r->formulation + ")");
    const std::size_t j = index_of(h.columns, r->case_name);
    h.values[i][j] = r->max_step_over_period;
  }
  h.missing = "fails";
  return h;
}

namespace {

std::size_t index_in(std::vector<std::string>& names, const std::string& n) {
  const auto it = std::find(names.begin(), names.end(), n);
  if (it != names.end()) return std::size_t(it - names.begin());
  names.push_back(n);
  return names.size() - 1;
}

// A heat map of method x accuracy level: each method's runs in the order the
// study made them (coarsest first), a column per level, labelled with the
// steps and tolerances it stands for.
template <class Row, class Value>
chart::HeatMapSpec accuracy_heat_map(const std::vector<const Row*>& runs, Value value) {
  chart::HeatMapSpec h;
  std::vector<std::vector<double>> steps, tols;  // per column: the levels used there
  std::vector<std::size_t> next;                 // per row: its next column
  for (const auto* r : runs) {
    const std::size_t i = index_in(h.rows, r->run.method);
    if (next.size() <= i) next.resize(i + 1, 0);
    const std::size_t j = next[i]++;
    if (h.values.size() <= i) h.values.resize(i + 1);
    if (h.values[i].size() <= j) h.values[i].resize(j + 1, kNaN);
    h.values[i][j] = value(*r);
    if (steps.size() <= j) {
      steps.resize(j + 1);
      tols.resize(j + 1);
    }
    auto& used = std::isfinite(r->run.tol) ? tols[j] : steps[j];
    const double level = std::isfinite(r->run.tol) ? r->run.tol : r->run.step;
    if (std::isfinite(level) && std::find(used.begin(), used.end(), level) == used.end())
      used.push_back(level);
  }
  for (std::size_t j = 0; j < steps.size(); ++j) {
    std::string label;
    for (double v : steps[j]) label += (label.empty() ? "h " : ", ") + cell_number(v);
    std::string tol;
    for (double v : tols[j]) tol += (tol.empty() ? "tol " : ", ") + cell_number(v);
    h.columns.push_back(label + (label.empty() || tol.empty() ? "" : " | ") + tol);
  }
  for (auto& row : h.values) row.resize(h.columns.size(), kNaN);
  return h;
}

}  // namespace

chart::HeatMapSpec chaos_heat_map(const std::vector<StudyRow>& rows) {
  const auto runs = rows_of<ChaosRow>(rows);
  auto h = accuracy_heat_map(
      runs, [](const ChaosRow& r) { return r.run.ok && r.separated ? r.separation_time : kNaN; });
  h.title = "Stability: time until a chaotic motion leaves the reference";
  h.value_label = "time of separation";
  h.missing = "none";
  h.undecided_label = "reference not converged";
  // The same cells as the values: each method's runs in order.
  std::vector<std::size_t> next(h.rows.size(), 0);
  h.undecided.assign(h.rows.size(), std::vector<bool>(h.columns.size(), false));
  double horizon = kNaN, margin = kNaN;
  for (const auto* r : runs) {
    const std::size_t i = index_in(h.rows, r->run.method);
    h.undecided[i][next[i]++] = r->run.ok && !r->reference_decides;
    horizon = r->reference_horizon;
    margin = r->threshold * kReferenceMargin;
  }
  const double t_end = runs.empty() ? kNaN : runs.front()->run.t_end;
  // One line under the grid: the two references' agreement in full is in the rows.
  h.note = "separated: error > 1e-3; none: not by t = ";
  h.note += cell_number(t_end);
  h.note += "; reference DOP853 tol 1e-14, checked by Gauss6: within ";
  h.note += cell_number(margin);
  h.note += " until t = ";
  h.note += cell_number(horizon);
  return h;
}

chart::HeatMapSpec separatrix_heat_map(const std::vector<StudyRow>& rows) {
  // Errors below 1e-16 (an exact hit) are drawn as 1e-16, which a log scale can show.
  auto h = accuracy_heat_map(rows_of<SeparatrixRow>(rows), [](const SeparatrixRow& r) {
    const double e = r.flip_time_error;
    return r.run.ok && std::isfinite(e) ? std::max(e, 1e-16) : kNaN;
  });
  h.title = "Stability: Euler top near the separatrix, error of the first flip's time";
  h.value_label = "|flip time - reference|";
  h.larger_is_better = false;
  h.missing = "no flip";
  h.note = "errors below 1e-16 shown as 1e-16; no flip: the run never flipped";
  return h;
}

std::vector<chart::Figure> bench_figures(const std::vector<StudyRow>& rows) {
  std::vector<chart::Figure> figures;
  StyleKeys keys;
  // case -> series name -> (cost, error) points, for both cost measures.
  std::map<std::string, std::map<std::string, std::pair<ChartSeries, ChartSeries>>> wp;
  std::map<std::string, std::vector<ChartSeries>> drift;
  std::map<std::string, std::pair<std::string, std::string>>
      legend_names;  // series: method, marker
  for (const auto* r : rows_of<WorkPrecisionRow>(rows)) {
    if (!r->run.ok || !(r->error > 0.0)) continue;
    const std::string name = series_name(r->run);
    auto& [by_cpu, by_evals] = wp[r->run.case_name][name];
    by_cpu.name = by_evals.name = name;
    by_cpu.colour_key = by_evals.colour_key = keys.colour(r->run.method);
    by_cpu.marker_key = by_evals.marker_key = keys.marker(r->run);
    legend_names[name] = {r->run.method, marker_name(r->run)};
    if (r->run.cpu_ms > 0.0) by_cpu.points.push_back({r->run.cpu_ms, r->error});
    if (r->run.rhs_evals > 0) by_evals.points.push_back({double(r->run.rhs_evals), r->error});
  }
  for (const auto* r : rows_of<DriftRow>(rows)) {
    for (const auto& [values, key] :
         {std::pair{&r->series_drift_C1, kEnergyKey}, std::pair{&r->series_drift_extra, kExtraKey},
          std::pair{&r->series_drift_gamma_norm2, kGammaKey}}) {
      ChartSeries s;
      s.name = series_name(r->run) + ", " + integral_name(r->run.case_name, key);
      s.colour_key = keys.colour(r->run.method);
      s.marker_key = key;
      for (std::size_t i = 0; i < std::min(r->series_t.size(), values->size()); ++i)
        // The start's drift is 0 by definition: no point of the log axis,
        // nor one of the row under it for values it cannot show.
        if (std::isfinite(r->series_t[i]) && std::isfinite((*values)[i]) &&
            !(i == 0 && (*values)[i] == 0.0))
          s.points.push_back({r->series_t[i], std::abs((*values)[i])});
      // A row without a series of |γ|² draws none (nor names it).
      if (key == kGammaKey && s.points.empty()) continue;
      drift[r->run.case_name].push_back(std::move(s));
    }
  }
  for (auto& [c, by_name] : wp) {
    ChartSpec cpu = chart_of("Work-precision: " + c, "CPU time [ms]", "error at t_end", true);
    ChartSpec evals =
        chart_of("Work-precision: " + c, "right-hand side evaluations", "error at t_end", true);
    for (auto& [name, pair] : by_name) {
      sort_by_x(pair.first);
      sort_by_x(pair.second);
      // A series without points (a splitting's cost is not in rhs
      // evaluations) is left out, and so is its legend key.
      for (auto [chart, series] : {std::pair{&cpu, &pair.first}, std::pair{&evals, &pair.second}}) {
        if (series->points.empty()) continue;
        add_legend_key(chart->colour_legend, series->colour_key, legend_names[name].first);
        add_legend_key(chart->marker_legend, series->marker_key, legend_names[name].second);
        chart->series.push_back(*series);
      }
    }
    // Keys in order: epviz's methods and formulations first, then the peers'.
    for (ChartSpec* chart : {&cpu, &evals})
      for (auto* legend : {&chart->colour_legend, &chart->marker_legend})
        std::sort(
            legend->begin(), legend->end(),
            [](const chart::LegendKey& a, const chart::LegendKey& b) { return a.key < b.key; });
    figures.push_back({"work_precision_" + c + ".png", std::move(cpu)});
    figures.push_back({"work_precision_evals_" + c + ".png", std::move(evals)});
  }
  for (auto& [c, series] : drift)
    figures.push_back({"drift_" + c + ".png", drift_panels(c, std::move(series))});
  auto heat = stability_heat_map(rows);
  if (!heat.rows.empty()) figures.push_back({"stability.png", std::move(heat)});
  auto chaos = chaos_heat_map(rows);
  if (!chaos.rows.empty()) figures.push_back({"stability_chaos.png", std::move(chaos)});
  auto separatrix = separatrix_heat_map(rows);
  if (!separatrix.rows.empty())
    figures.push_back({"stability_separatrix.png", std::move(separatrix)});
  auto table = stability_table(rows, false);
  if (!table.rows.empty()) figures.push_back({"stability_runs.png", std::move(table)});
  return figures;
}

}  // namespace epviz::study
