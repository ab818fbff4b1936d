#include "study/bench_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "study/invariant_cost.hpp"
#include "study/text_table.hpp"

namespace epviz::study {
namespace {

// Columns reading a field of the row, or of its RunRecord.
template <class Row>
TextColumn<Row> text(std::string header, std::string Row::*field) {
  return {std::move(header), [field](const Row& r) { return r.*field; }};
}
template <class Row, class T>
TextColumn<Row> number(std::string header, T Row::*field) {
  return {std::move(header), [field](const Row& r) { return cell_number(double(r.*field)); }};
}
template <class Row>
TextColumn<Row> flag(std::string header, bool Row::*field) {
  return {std::move(header),
          [field](const Row& r) { return std::string(r.*field ? "yes" : "no"); }};
}
template <class Row>
TextColumn<Row> run_text(std::string header, std::string RunRecord::*field) {
  return {std::move(header), [field](const Row& r) { return r.run.*field; }};
}
template <class Row, class T>
TextColumn<Row> run_number(std::string header, T RunRecord::*field) {
  return {std::move(header), [field](const Row& r) { return cell_number(double(r.run.*field)); }};
}
template <class Row>
TextColumn<Row> run_status(std::string header) {
  return {std::move(header), [](const Row& r) { return std::string(r.run.ok ? "ok" : "failed"); }};
}

std::string work_precision_tables(const std::vector<StudyRow>& rows) {
  std::string out;
  using R = WorkPrecisionRow;
  TextTable<R> table{
      "",
      {run_text<R>("impl", &RunRecord::impl), run_text<R>("method", &RunRecord::method),
       run_text<R>("formulation", &RunRecord::formulation), run_number<R>("tol", &RunRecord::tol),
       run_number<R>("step", &RunRecord::step), number("error", &R::error),
       run_number<R>("rhs_evals", &RunRecord::rhs_evals),
       run_number<R>("flow_evals", &RunRecord::flow_evals),
       run_number<R>("cpu_ms", &RunRecord::cpu_ms), run_status<R>("status")}};
  const auto runs = rows_of<R>(rows);
  for (const auto* ref : rows_of<ReferenceRow>(rows)) {
    table.title =
        "work-precision: " + ref->case_name + " (t_end " + cell_number(ref->t_end) +
        "; error = |dOmega|_2 + |dgamma|_2 vs Gauss6 Richardson, self-check vs DOP853 1e-14: " +
        cell_number(ref->self_check) + ")";
    std::vector<const R*> of_case;
    std::copy_if(runs.begin(), runs.end(), std::back_inserter(of_case),
                 [&](const R* r) { return r->run.case_name == ref->case_name; });
    out += text_table(table, of_case);
  }
  return out;
}

std::string peer_table(const std::vector<StudyRow>& rows) {
  using R = PeerRatioRow;
  return text_table(
      TextTable<R>{
          "peers: CPU time against epviz dop853 at equal achieved error (log-log interpolation; "
          "ratio > 1: epviz is faster)",
          {text("case", &R::case_name), text("impl", &R::impl), text("method", &R::method),
           number("error", &R::error), number("peer_ms", &R::peer_cpu_ms),
           number("epviz_ms", &R::epviz_dop853_cpu_ms), number("ratio", &R::ratio)}},
      rows_of<R>(rows));
}

std::string invariant_tables(const std::vector<StudyRow>& rows) {
  std::string out;
  {
    using R = DriftRow;
    out += text_table(
        TextTable<R>{
            "invariant drift (max relative, direct formulation, equal evaluations per time unit)",
            {run_text<R>("case", &RunRecord::case_name), run_text<R>("method", &RunRecord::method),
             run_number<R>("tol", &RunRecord::tol), run_number<R>("step", &RunRecord::step),
             run_number<R>("t_end", &RunRecord::t_end),
             run_number<R>("rhs_evals", &RunRecord::rhs_evals),
             run_number<R>("cpu_ms", &RunRecord::cpu_ms),
             number("|gamma|^2", &R::drift_gamma_norm2), number("C0", &R::drift_C0),
             number("C1", &R::drift_C1), number("extra", &R::drift_extra)}},
        rows_of<R>(rows));
  }
  using R = InvariantCostRow;
  const auto cost = rows_of<R>(rows);
  char title[160];
  std::snprintf(
      title, sizeof title,
      "invariant cost: cheapest run keeping C1 and the 4th integral within %g over T = %g "
      "(kovalevskaya, direct)",
      kInvariantCostTarget, cost.empty() ? 0.0 : cost[0]->run.t_end);
  out += text_table(
      TextTable<R>{title,
                   {run_text<R>("method", &RunRecord::method),
                    run_number<R>("tol", &RunRecord::tol),
                    run_number<R>("step", &RunRecord::step),
                    flag("reached", &R::reached),
                    {"cost", [](const R& r) { return cell_number(double(r.run.cost())); }},
                    run_number<R>("cpu_ms", &RunRecord::cpu_ms),
                    number("C1", &R::drift_C1),
                    number("extra", &R::drift_extra)}},
      cost);
  return out;
}

std::string stability_tables(const std::vector<StudyRow>& rows) {
  std::string out;
  {
    using R = MaxStepRow;
    out += text_table(TextTable<R>{"stability 1: largest fixed step before blow-up, lost motion "
                                   "(energy or |gamma|^2 drift > 1) or loss of shape (error > 0.1)",
                                   {text("case", &R::case_name), text("method", &R::method),
                                    number("max_step", &R::max_step),
                                    number("h/period", &R::max_step_over_period),
                                    number("failing", &R::failing_step),
                                    text("failure at the failing step", &R::failure_reason)}},
                      rows_of<R>(rows));
  }
  {
    using R = PolePassageRow;
    out += text_table(
        TextTable<R>{
            "stability 2: south-pole passage, dop853 at equal tolerance",
            {text("variant", &R::variant),
             run_status<R>("status"),
             run_number<R>("fail_t", &RunRecord::failure_t),
             {"steps",
              [](const R& r) { return cell_number(r.run.steps ? double(*r.run.steps) : NAN); }},
             number("switches", &R::chart_switches),
             number("error", &R::error),
             run_text<R>("reason", &RunRecord::failure_reason)}},
        rows_of<R>(rows));
  }
  {
    using R = SeparatrixRow;
    out += text_table(
        TextTable<R>{
            "stability 3: Euler case near the separatrix, first flip of Omega_2",
            {run_text<R>("method", &RunRecord::method), run_number<R>("tol", &RunRecord::tol),
             run_number<R>("step", &RunRecord::step), number("flip_t", &R::flip_time),
             number("ref_flip_t", &R::reference_flip_time), number("|dt|", &R::flip_time_error),
             number("flips", &R::flips), number("ref", &R::reference_flips),
             number("|dt| last", &R::last_flip_time_error)}},
        rows_of<R>(rows));
  }
  {
    using R = SleepingTopRow;
    out += text_table(
        TextTable<R>{
            "stability 4: fast sleeping top (Omega3 = 50): cheapest run with gamma error < 1e-3",
            {run_text<R>("method", &RunRecord::method),
             run_text<R>("formulation", &RunRecord::formulation),
             run_number<R>("tol", &RunRecord::tol), run_number<R>("step", &RunRecord::step),
             flag("reached", &R::reached), number("gamma_err", &R::gamma_error),
             run_number<R>("rhs_evals", &RunRecord::rhs_evals),
             run_number<R>("cpu_ms", &RunRecord::cpu_ms)}},
        rows_of<R>(rows));
  }
  using R = ChaosRow;
  out += text_table(
      TextTable<R>{
          "stability 5: generic body from a strongly chaotic state (Lyapunov time ~2), time of "
          "separation > 1e-3 from the reference",
          {run_text<R>("method", &RunRecord::method), run_number<R>("tol", &RunRecord::tol),
           run_number<R>("step", &RunRecord::step), flag("separated", &R::separated),
           number("sep_time", &R::separation_time), run_number<R>("t_end", &RunRecord::t_end),
           run_number<R>("cpu_ms", &RunRecord::cpu_ms)}},
      rows_of<R>(rows));
  return out;
}

}  // namespace

std::string bench_tables(const std::vector<StudyRow>& rows) {
  return work_precision_tables(rows) + peer_table(rows) + invariant_tables(rows) +
         stability_tables(rows);
}

}  // namespace epviz::study
