#pragma once
// The fields that describe a simulation, as given on the command line or in a
// job file, before they are checked against each other and against physics.
// Each field remembers where it came from ("--inertia", "job.json: key 'inertia'")
// so that an error names what the user wrote.
#include <string>

#include "job/document.hpp"
#include "job/schema.hpp"
#include "sim/run_spec.hpp"

namespace CLI {
class App;  // CLI11: included only where options are defined
}

namespace epviz::app {

// The fields and their reading from a job belong to the job format (job/schema.hpp).
using job::Given;
using job::read_simulation_fields;
using job::SimulationFields;

// The options of `epviz simulate` that describe the simulation, as typed;
// empty: not given (an empty value is refused while parsing, see
// reject_empty_values).
struct SimulationOptions {
  std::string case_name, inertia, com, weight, omega, gamma, formulation, method, tol, step, t_end,
      samples, max_drift;
  bool allow_nonphysical = false, normalize_gamma = false, no_chart_switch = false;
};

// Adds --case, --inertia, ... --no-chart-switch to `cmd`, read into `options`.
void add_simulation_options(CLI::App& cmd, SimulationOptions& options);

// The fields the options give, each converted and named by its option; throws
// UsageError for a value that is not a number, a vector, ...
SimulationFields fields_from_options(const SimulationOptions& options);

// Checks the fields against each other and against physics and fills in the
// defaults: a case preset's body and state for fields not given (the generic
// body, labelled custom, without a case or with case "custom"). Throws
// UsageError naming the origin.
sim::RunSpec resolve(const SimulationFields& fields);

}  // namespace epviz::app
