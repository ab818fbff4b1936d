#include "study/bench_json.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

namespace epviz::study {
namespace {

using nlohmann::json;

std::string compiler() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("gcc ") + __VERSION__;
#else
  return "unknown";
#endif
}

const char* yes_no(bool b) { return b ? "yes" : "no"; }

json series(const std::vector<double>& v) {
  auto a = json::array();
  for (double x : v) a.push_back(number_or_null(x));
  return a;
}

void put(json& j, const RunRecord& r) {
  j["impl"] = r.impl;
  j["case"] = r.case_name;
  j["formulation"] = r.formulation;
  j["method"] = r.method;
  j["accuracy"] = r.adaptive ? "tol" : "step";
  j["tol"] = number_or_null(r.tol);
  j["step"] = number_or_null(r.step);
  j["t_end"] = number_or_null(r.t_end);
  j["steps"] = r.steps ? json(double(*r.steps)) : json(nullptr);
  j["rhs_evals"] = double(r.rhs_evals);
  j["flow_evals"] = double(r.flow_evals);
  j["cpu_ms"] = number_or_null(r.cpu_ms);
  j["repeats"] = double(r.repeats);
  j["status"] = r.ok ? "ok" : "failed";
  j["failure_t"] = number_or_null(r.failure_t);
  j["failure_reason"] = r.failure_reason;
}

json to_json(const WorkPrecisionRow& r) {
  json j;
  put(j, r.run);
  j["error"] = number_or_null(r.error);
  j["error_resolved"] = yes_no(r.error_resolved);
  return j;
}

json to_json(const ReferenceRow& r) {
  return {{"case", r.case_name},
          {"method", "gauss6-richardson"},
          {"check_method", "dop853"},
          {"check_tol", r.check_tol},
          {"t_end", r.t_end},
          {"step", r.step},
          {"self_check", number_or_null(r.self_check)},
          {"smallest_error", number_or_null(r.smallest_error)},
          {"smallest_error_any", number_or_null(r.smallest_error_any)},
          {"cpu_ms", number_or_null(r.cpu_ms)}};
}

json to_json(const PeerRatioRow& r) {
  return {{"case", r.case_name},
          {"impl", r.impl},
          {"method", r.method},
          {"error", number_or_null(r.error)},
          {"peer_cpu_ms", number_or_null(r.peer_cpu_ms)},
          {"epviz_dop853_cpu_ms", number_or_null(r.epviz_dop853_cpu_ms)},
          {"ratio", number_or_null(r.ratio)}};
}

json to_json(const DriftRow& r) {
  json j;
  put(j, r.run);
  j["budget_evals_per_time"] = r.budget_evals_per_time;
  j["drift_gamma_norm2"] = number_or_null(r.drift_gamma_norm2);
  j["drift_C0"] = number_or_null(r.drift_C0);
  j["drift_C1"] = number_or_null(r.drift_C1);
  j["drift_extra"] = number_or_null(r.drift_extra);
  j["series_t"] = series(r.series_t);
  j["series_drift_C1"] = series(r.series_drift_C1);
  j["series_drift_extra"] = series(r.series_drift_extra);
  j["series_drift_gamma_norm2"] = series(r.series_drift_gamma_norm2);
  return j;
}

json to_json(const InvariantCostRow& r) {
  json j;
  put(j, r.run);
  j["target"] = number_or_null(r.target);
  j["drift_C1"] = number_or_null(r.drift_C1);
  j["drift_extra"] = number_or_null(r.drift_extra);
  j["reached"] = yes_no(r.reached);
  j["cost"] = double(r.run.cost());
  return j;
}

json to_json(const MaxStepRow& r) {
  return {{"impl", r.impl},
          {"case", r.case_name},
          {"method", r.method},
          {"formulation", r.formulation},
          {"t_end", r.t_end},
          {"fastest_period", number_or_null(r.fastest_period)},
          {"max_step", number_or_null(r.max_step)},
          {"max_step_over_period", number_or_null(r.max_step_over_period)},
          {"error_at_max_step", number_or_null(r.error_at_max_step)},
          {"failing_step", number_or_null(r.failing_step)},
          {"failure_reason", r.failure_reason}};
}

json to_json(const PolePassageRow& r) {
  json j;
  put(j, r.run);
  j["variant"] = r.variant;
  j["pole_distance"] = r.pole_distance;
  j["chart_switches"] = double(r.chart_switches);
  j["failure_method"] = r.failure_method;
  j["error"] = number_or_null(r.error);
  j["reference_self_check"] = number_or_null(r.reference_self_check);
  return j;
}

json to_json(const SeparatrixRow& r) {
  json j;
  put(j, r.run);
  j["flip_time"] = number_or_null(r.flip_time);
  j["reference_flip_time"] = number_or_null(r.reference_flip_time);
  j["flip_time_error"] = number_or_null(r.flip_time_error);
  j["flips"] = double(r.flips);
  j["reference_flips"] = double(r.reference_flips);
  j["last_flip_time_error"] = number_or_null(r.last_flip_time_error);
  return j;
}

json to_json(const SleepingTopRow& r) {
  json j;
  put(j, r.run);
  j["reached"] = yes_no(r.reached);
  j["gamma_error"] = number_or_null(r.gamma_error);
  j["target_gamma_error"] = number_or_null(r.target_gamma_error);
  j["omega3"] = number_or_null(r.omega3);
  return j;
}

json to_json(const ChaosRow& r) {
  json j;
  put(j, r.run);
  j["threshold"] = number_or_null(r.threshold);
  j["separated"] = yes_no(r.separated);
  j["separation_time"] = number_or_null(r.separation_time);
  j["reference_self_check"] = number_or_null(r.reference_self_check);
  j["reference_horizon"] = number_or_null(r.reference_horizon);
  j["reference_decides"] = yes_no(r.reference_decides);
  return j;
}

}  // namespace

json number_or_null(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json row_json(const StudyRow& row) {
  json j = std::visit([](const auto& r) { return to_json(r); }, row);
  j["study"] = std::string(study_name(row));
  return j;
}

json rows_json(const std::vector<StudyRow>& rows) {
  auto a = json::array();
  for (const auto& r : rows) a.push_back(row_json(r));
  return a;
}

namespace {

json evidence_json(const Evidence& e) {
  json j;
  put(j, e.run);
  j["error"] = number_or_null(e.error);
  j["drift"] = number_or_null(e.drift);
  j["drift_invariant"] = e.drift_invariant.empty() ? json(nullptr) : json(e.drift_invariant);
  j["drift_steps"] = e.drift_samples;
  return j;
}

}  // namespace

json recommendation_json(const Recommendation& r) {
  return {{"case", r.case_name},
          {"t_end", number_or_null(r.t_end)},
          {"target_error", number_or_null(r.target_error)},
          {"reference_self_check", number_or_null(r.reference_self_check)},
          {"compared", r.compared},
          {"meeting", r.meeting},
          {"met", r.met},
          {"rule",
           "the least CPU time among epviz's runs with error <= target_error; none: the smallest "
           "error"},
          {"choice", r.choice ? evidence_json(*r.choice) : json(nullptr)},
          {"fastest_peer", r.fastest_peer ? evidence_json(*r.fastest_peer) : json(nullptr)},
          {"text", recommendation_text(r)}};
}

json bench_document(const std::vector<StudyRow>& rows, bool quick, double wall_seconds,
                    const std::optional<Recommendation>& recommendation) {
  double worst_check = 0.0, smallest = INFINITY;
  for (const auto* r : rows_of<ReferenceRow>(rows)) {
    worst_check = std::max(worst_check, r->self_check);
    if (std::isfinite(r->smallest_error)) smallest = std::min(smallest, r->smallest_error);
  }
  json doc;
  doc["metadata"] = {
      {"tool", "epviz bench"},
      {"mode", quick ? "quick" : "full"},
      {"wall_seconds", wall_seconds},
      {"machine", {{"nproc", std::thread::hardware_concurrency()}, {"compiler", compiler()}}},
      {"error_measure", "|Omega - Omega_ref|_2 + |gamma - gamma_ref|_2 at the final time"},
      {"cost_measure", "rhs_evals (+ flow_evals: exact sub-flow evaluations of splitting methods)"},
      {"cpu_time", "median of repeated runs (repeats field), integration only, no I/O"},
      {"reference",
       {{"method", "gauss6 at steps h and h/2, Richardson-extrapolated: (64 y(h/2) - y(h)) / 63"},
        {"check", "dop853 at tol 1e-14"},
        {"max_self_check", worst_check},
        {"smallest_reported_error", number_or_null(smallest)}}},
  };
  doc["rows"] = rows_json(rows);
  if (recommendation) doc["recommendation"] = recommendation_json(*recommendation);
  return doc;
}

}  // namespace epviz::study
