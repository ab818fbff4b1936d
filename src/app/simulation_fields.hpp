#pragma once
// The fields that describe a simulation, as given on the command line or in a
// job file, before they are checked against each other and against physics.
// Each field remembers where it came from ("--inertia", "job.json: key 'inertia'")
// so that an error names what the user wrote.
#include <string>
#include <vector>

#include "job/document.hpp"
#include "job/fields.hpp"
#include "job/schema.hpp"

namespace CLI {
class App;  // CLI11: included only where options are defined
}

namespace epviz::app {

// The fields and their reading from a job belong to the job format (job/schema.hpp).
using job::Given;
using job::read_simulation_fields;
using job::SimulationFields;

// The options of `epviz simulate` that describe the simulation, as typed,
// one per field of job::simulation_field_table() in its order; text empty:
// not given (an empty value is refused while parsing, see reject_empty_values).
struct SimulationOptions {
  struct Value {
    std::string text;  // options that take a value
    bool set = false;  // flags
  };
  std::vector<Value> values = std::vector<Value>(job::simulation_field_table().size());
};

// Adds an option per field (--case, --inertia, ... --no-chart-switch) to
// `cmd`, read into `options`, with the field's help, choices and default.
void add_simulation_options(CLI::App& cmd, SimulationOptions& options);

// The fields the options give, each converted and named by its option; throws
// io::BadInput for a value that is not a number, a vector, ...
SimulationFields fields_from_options(const SimulationOptions& options);

}  // namespace epviz::app
