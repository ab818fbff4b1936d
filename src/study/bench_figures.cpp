#include "study/bench_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

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

}  // namespace

TableSpec stability_table(const std::vector<StudyRow>& rows) {
  TableSpec t;
  t.title = "Stability studies";
  t.header = {"study", "case", "method", "formulation", "status", "result"};
  for (const auto& row : rows) {
    if (const auto* max_step = std::get_if<MaxStepRow>(&row)) {
      const auto result = Result()
                              .add("max step", max_step->max_step)
                              .add("h/period", max_step->max_step_over_period);
      t.rows.push_back({"max_step", max_step->case_name, max_step->method, max_step->formulation,
                        max_step->failure_reason.empty() ? "ok" : "limit", result.text()});
    } else if (const auto* pole = std::get_if<PolePassageRow>(&row)) {
      t.rows.push_back(table_row("pole", pole->run,
                                 Result().add("variant", pole->variant).add("error", pole->error)));
    } else if (const auto* separatrix = std::get_if<SeparatrixRow>(&row)) {
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
    } else if (const auto* chaos = std::get_if<ChaosRow>(&row)) {
      t.rows.push_back(table_row("chaos", chaos->run,
                                 Result()
                                     .add("step", chaos->run.step)
                                     .add("separated", chaos->separated ? "yes" : "no")
                                     .add("at", chaos->separation_time)));
    }
  }
  return t;
}

std::vector<chart::Figure> bench_figures(const std::vector<StudyRow>& rows) {
  std::vector<chart::Figure> figures;
  // case -> series name -> (cost, error) points, for both cost measures.
  std::map<std::string, std::map<std::string, std::pair<ChartSeries, ChartSeries>>> wp;
  std::map<std::string, std::vector<ChartSeries>> drift;
  for (const auto* r : rows_of<WorkPrecisionRow>(rows)) {
    if (!r->run.ok || !(r->error > 0.0)) continue;
    const std::string name = series_name(r->run);
    auto& [by_cpu, by_evals] = wp[r->run.case_name][name];
    by_cpu.name = by_evals.name = name;
    if (r->run.cpu_ms > 0.0) by_cpu.points.push_back({r->run.cpu_ms, r->error});
    if (r->run.rhs_evals > 0) by_evals.points.push_back({double(r->run.rhs_evals), r->error});
  }
  for (const auto* r : rows_of<DriftRow>(rows)) {
    for (const auto& [values, what] : {std::pair{&r->series_drift_C1, "C1"},
                                       std::pair{&r->series_drift_extra, "4th integral"}}) {
      ChartSeries s;
      s.name = series_name(r->run) + ", " + what;
      for (std::size_t i = 0; i < std::min(r->series_t.size(), values->size()); ++i)
        if (std::isfinite(r->series_t[i]) && std::isfinite((*values)[i]))
          s.points.push_back({r->series_t[i], std::abs((*values)[i])});
      drift[r->run.case_name].push_back(std::move(s));
    }
  }
  for (auto& [c, by_name] : wp) {
    ChartSpec cpu{"Work-precision: " + c, "CPU time [ms]", "error at t_end", true, true, {}};
    ChartSpec evals{
        "Work-precision: " + c, "right-hand side evaluations", "error at t_end", true, true, {}};
    for (auto& [name, pair] : by_name) {
      sort_by_x(pair.first);
      sort_by_x(pair.second);
      if (!pair.first.points.empty()) cpu.series.push_back(pair.first);
      if (!pair.second.points.empty()) evals.series.push_back(pair.second);
    }
    figures.push_back({"work_precision_" + c + ".png", std::move(cpu)});
    figures.push_back({"work_precision_evals_" + c + ".png", std::move(evals)});
  }
  for (auto& [c, series] : drift)
    figures.push_back(
        {"drift_" + c + ".png", ChartSpec{"Relative drift of the integrals: " + c, "time",
                                          "relative drift", false, true, std::move(series)}});
  auto table = stability_table(rows);
  if (!table.rows.empty()) figures.push_back({"stability.png", std::move(table)});
  return figures;
}

}  // namespace epviz::study
