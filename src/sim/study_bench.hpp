#pragma once
// The studies behind `epviz bench` (no I/O, no GL): work-precision sweeps,
// long-time invariant drift at a fixed cost, and measured stability limits.
// Every result is a StudyRow: a "study" name plus named text fields, numbers
// (NaN = not applicable, written as null) and series, so that rows from other
// implementations (peers) can be added with the same schema.
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "physics/cases.hpp"
#include "sim/run_spec.hpp"
#include "sim/simulate.hpp"

namespace epviz::sim {

struct StudyRow {
  std::string study;
  std::vector<std::pair<std::string, std::string>> text;
  std::vector<std::pair<std::string, double>> numbers;
  std::vector<std::pair<std::string, std::vector<double>>> series;

  void set(const std::string& key, const std::string& value);
  void set(const std::string& key, const char* value) { set(key, std::string(value)); }
  void set(const std::string& key, double value);
  std::optional<std::string> text_of(const std::string& key) const;
  std::optional<double> number(const std::string& key) const;
};

struct StudyOptions {
  bool quick = false;
  std::vector<physics::Case> cases;           // work-precision cases; empty = all six presets
  std::vector<Method> methods;                // empty = all_methods()
  std::vector<Formulation> formulations;      // empty = all_formulations()
  int repeats = 0;                            // CPU-time repeats; 0 = 3 (quick) or 5 (full)
  std::function<void(const std::string&)> progress;  // optional: told what runs next
};


// Median CPU time of `repeats` runs of spec (the first run's result is returned).
struct TimedRun {
  RunResult result;
  double cpu_median = 0.0;
  int repeats = 0;
  long cost = 0;  // rhs evaluations + exact sub-flow evaluations
};
TimedRun timed_run(const RunSpec& spec, int repeats);

// The final time of the work-precision runs of case c.
double wp_t_end(physics::Case c);
// Work-precision: rows of study "work_precision" plus one "reference" row per case.
std::vector<StudyRow> work_precision_study(const StudyOptions& o);
// Invariant drift over 1e5 (full) / 1e3 (quick) time units on Kovalevskaya and
// Goryachev-Chaplygin, direct formulation, a fixed budget of evaluations per time unit.
std::vector<StudyRow> drift_study(const StudyOptions& o);

// Invariant cost: on Kovalevskaya (direct formulation), for each method the
// cheapest accuracy setting on a ladder (coarse to fine; tolerances for
// adaptive methods, steps for fixed-step ones) whose largest relative drift of
// C1 and of the fourth integral over t_end stays below `target`. Study
// "invariant_cost"; reached = "no" when the finest setting within the ladder's
// cost cap still misses. t_end <= 0: 1e4 (full) / 1e3 (quick).
inline constexpr double kInvariantCostTarget = 1e-8;
std::vector<StudyRow> invariant_cost_study(const StudyOptions& o, double t_end = 0.0,
                                           double target = kInvariantCostTarget);
// The initial state of the generic body used by the chaos study: one with a
// short Lyapunov time, so that the study's runs separate within its time span.
physics::InitialState chaos_initial_state();

// --- Stability -------------------------------------------------------------
// Whether one fixed-step run of `c`'s preset over t_end keeps the motion:
// no failure, finite, global error <= 0.1 and relative energy drift <= 0.1 at t_end.
struct StepVerdict {
  bool ok = true;
  std::string reason;  // "" when ok: "blew up: ...", "lost the motion: error ...", or the failure
  double error = 0.0, energy_drift = 0.0, failure_t = 0.0;
};
StepVerdict check_fixed_step(physics::Case c, Method m, double step, double t_end,
                             const Sample& reference_end);

std::vector<StudyRow> stability_max_step(const StudyOptions& o);   // study "stability_max_step"
std::vector<StudyRow> stability_pole(const StudyOptions& o);       // study "stability_pole"
std::vector<StudyRow> stability_separatrix(const StudyOptions& o); // study "stability_separatrix"
std::vector<StudyRow> stability_sleeping(const StudyOptions& o);   // study "stability_sleeping_top"
std::vector<StudyRow> stability_chaos(const StudyOptions& o);      // study "stability_chaos"

}  // namespace epviz::sim
