#pragma once
// The rows of `epviz bench`, one record type per study, shared by epviz's own
// runs and the peers' (impl names the implementation). NaN means "not
// applicable" and is written as null (study/bench_json.hpp writes the rows).
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace epviz::study {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// What every row that describes one integration run says about it.
struct RunRecord {
  std::string impl = "epviz";  // or the peer library: "boost-odeint", "gsl", "scipy"
  std::string case_name;       // a preset's name, or "custom"
  std::string formulation;     // "direct", "riccati", "spinor"
  std::string method;          // sim's method name, or the peer's ("rk8pd", ...)
  bool adaptive = true;        // accuracy set by tol (adaptive) or by step (fixed)
  double tol = kNaN;           // adaptive only
  double step = kNaN;          // fixed-step only: the step actually used
  double t_end = 0.0;
  std::optional<long> steps;  // accepted steps; empty where a library does not say
  long rhs_evals = 0;
  long flow_evals = 0;  // exact sub-flow evaluations (splitting methods)
  double cpu_ms = 0.0;  // median CPU time per run, integration only
  int repeats = 0;
  bool ok = true;  // false: the run failed (then failure_t and failure_reason say how)
  double failure_t = kNaN;
  std::string failure_reason;
  long cost() const { return rhs_evals + flow_evals; }
};

// Global error at t_end of one run against the case's reference.
struct WorkPrecisionRow {
  static constexpr std::string_view study = "work_precision";
  RunRecord run;
  double error = kNaN;          // NaN when the run failed
  bool error_resolved = false;  // above 10x the reference's self-check
};

// The reference of one case's work-precision runs (study/reference.hpp).
struct ReferenceRow {
  static constexpr std::string_view study = "reference";
  std::string case_name;
  double t_end = 0.0;
  double step = 0.0;         // coarse Gauss6 step of the Richardson pair
  double check_tol = 1e-14;  // DOP853's tolerance for the check
  double self_check = 0.0;
  double smallest_error = kNaN;      // smallest resolved error of the case's runs
  double smallest_error_any = kNaN;  // smallest error, resolved or not
  double cpu_ms = 0.0;
};

// A peer's CPU time against epviz's DOP853 at equal achieved error.
struct PeerRatioRow {
  static constexpr std::string_view study = "peer_ratio";
  std::string case_name, impl, method;
  double error = kNaN;
  double peer_cpu_ms = kNaN;
  double epviz_dop853_cpu_ms = kNaN;
  double ratio = kNaN;  // peer / epviz: > 1 means epviz is faster
};

// Largest relative drift of the integrals over a long run at a fixed budget.
struct DriftRow {
  static constexpr std::string_view study = "drift";
  RunRecord run;
  double budget_evals_per_time = 0.0;
  double drift_gamma_norm2 = kNaN, drift_C0 = kNaN, drift_C1 = kNaN, drift_extra = kNaN;
  std::vector<double> series_t{}, series_drift_C1{}, series_drift_extra{},
      series_drift_gamma_norm2{};  // relative drift at sample times
};

// The cheapest accuracy setting keeping C1 and the fourth integral within target.
struct InvariantCostRow {
  static constexpr std::string_view study = "invariant_cost";
  RunRecord run;  // the chosen rung, or the finest tried when none reached the target
  double target = kNaN;
  double drift_C1 = kNaN, drift_extra = kNaN;
  bool reached = false;
};

// Largest fixed step that keeps the motion (bisected on the number of steps).
struct MaxStepRow {
  static constexpr std::string_view study = "stability_max_step";
  std::string impl = "epviz";
  std::string case_name, method;
  std::string formulation = "direct";
  double t_end = 0.0, fastest_period = 0.0;
  double max_step = kNaN, max_step_over_period = kNaN;
  double error_at_max_step = kNaN;
  double failing_step = kNaN;  // NaN when even the largest step tried keeps the motion
  std::string failure_reason;  // at the failing step
};

// DOP853 through a south-pole passage, per formulation (and chart switch).
struct PolePassageRow {
  static constexpr std::string_view study = "stability_pole";
  RunRecord run;
  std::string variant{};  // "riccati+chart-switch", "riccati-no-switch", "spinor", "direct"
  double pole_distance = 0.0;
  long chart_switches = 0;
  std::string failure_method{};  // the stepper that reported the failure ("" when ok)
  double error = kNaN;
  double reference_self_check = kNaN;
};

// Euler case near the separatrix: when Omega_2 changes sign, against the reference.
struct SeparatrixRow {
  static constexpr std::string_view study = "stability_separatrix";
  RunRecord run;
  double flip_time = kNaN, reference_flip_time = kNaN, flip_time_error = kNaN;
  long flips = 0, reference_flips = 0;
  double last_flip_time_error = kNaN;  // NaN when the numbers of flips differ
};

// Fast sleeping top: the cheapest run whose gamma error stays below target.
struct SleepingTopRow {
  static constexpr std::string_view study = "stability_sleeping_top";
  RunRecord run;
  bool reached = false;
  double gamma_error = kNaN;
  double target_gamma_error = kNaN;
  double omega3 = kNaN;
};

// Strongly chaotic generic body: when the run separates from the reference.
struct ChaosRow {
  static constexpr std::string_view study = "stability_chaos";
  RunRecord run;
  double threshold = kNaN;
  bool separated = false;
  double separation_time = kNaN;
  double reference_self_check = kNaN;  // the largest disagreement of the reference's two runs
  // The time up to which the reference's two runs agree to a tenth of the
  // threshold; a run not separated by then, when it is short of t_end, is
  // undecided (reference_decides false): "reference not converged".
  double reference_horizon = kNaN;
  bool reference_decides = true;
};

using StudyRow =
    std::variant<WorkPrecisionRow, ReferenceRow, PeerRatioRow, DriftRow, InvariantCostRow,
                 MaxStepRow, PolePassageRow, SeparatrixRow, SleepingTopRow, ChaosRow>;

// The row's study name, as written in the JSON "study" field.
inline std::string_view study_name(const StudyRow& row) {
  return std::visit([](const auto& r) { return std::decay_t<decltype(r)>::study; }, row);
}

// The rows of one kind, in order.
template <class Row>
std::vector<const Row*> rows_of(const std::vector<StudyRow>& rows) {
  std::vector<const Row*> out;
  for (const auto& r : rows)
    if (const auto* p = std::get_if<Row>(&r)) out.push_back(p);
  return out;
}

// Appends `more` (rows of one kind or already StudyRows) to `rows`.
template <class Row>
void append(std::vector<StudyRow>& rows, std::vector<Row> more) {
  for (auto& r : more) rows.emplace_back(std::move(r));
}

}  // namespace epviz::study
