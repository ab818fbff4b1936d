#pragma once
// One epviz run timed as the studies time it, and the RunRecord describing it.
#include "sim/run_spec.hpp"
#include "sim/simulate.hpp"
#include "study/study_row.hpp"

namespace epviz::study {

// The first run's result and the median CPU time of `repeats` runs of spec
// (study/timing.hpp: long runs are timed twice at most).
struct TimedRun {
  sim::RunResult result;
  double cpu_median = 0.0;
  int repeats = 0;
  long cost = 0;  // rhs evaluations + exact sub-flow evaluations
};
TimedRun timed_run(const sim::RunSpec& spec, int repeats);

// The record of run `t` of `spec` (impl "epviz").
RunRecord run_record(const sim::RunSpec& spec, const TimedRun& t);

// Whether a sample's state is finite.
bool finite(const sim::Sample& s);

}  // namespace epviz::study
