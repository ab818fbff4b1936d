#pragma once
// The runs `epviz simulate` makes of its fields, all checked before any is
// integrated so that bad input leaves nothing behind, and the summary it
// prints of each (the CSV and report are simulation_output.hpp).
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "job/document.hpp"
#include "sim/drift.hpp"
#include "sim/run_spec.hpp"
#include "sim/simulate.hpp"

namespace epviz::sweep {

// Whether the fields ask for every preset (case "all") rather than one run.
bool runs_every_case(const job::SimulationFields& fields);

// One run, or one per preset for case "all", each resolved (job/resolve.hpp);
// `max_steps` (--max-steps) replaces the default step budget. Throws
// io::BadInput as resolving does, and for a run check_step_budget refuses.
std::vector<sim::RunSpec> simulate_runs(const job::SimulationFields& fields,
                                        std::optional<long> max_steps);

// The step budget bounds adaptive runs while they run (a step_budget
// failure). A fixed-step run's number of steps is known before it starts:
// beyond the budget it would take hours, which is almost always a typo in
// --t-end or --step, so it is refused (io::BadInput naming them).
void check_step_budget(const sim::RunSpec& spec);

// Three lines (four when the run failed): the case, formulation, method and
// accuracy with the step counts and CPU time; the largest relative drifts
// over the samples ("max relative drift") and at the integrator's steps
// ("step drift"), the names of the report's keys.
std::string run_summary(const sim::RunSpec& spec, const sim::RunResult& result,
                        const sim::RunDrifts& drifts);

// simulate's report of a run (sweep::run_report, whose "max_relative_drift"
// is over the samples written, as in a sweep's rows and render's report) with
// render's "step_drift" added: the drift at the integrator's steps.
nlohmann::json simulate_report(const sim::RunSpec& spec, const sim::RunResult& result,
                               const sim::RunDrifts& drifts);

}  // namespace epviz::sweep
