#pragma once
// The fields that describe a simulation, as given on the command line or in a
// job file, before they are checked against each other and against physics.
// Each field remembers where it came from ("--inertia", "job.json: key 'inertia'")
// so that an error names what the user wrote.
#include "app/cli.hpp"
#include "job/document.hpp"
#include "job/field_options.hpp"
#include "job/fields.hpp"
#include "job/schema.hpp"

namespace epviz::app {

// The fields and their reading from a job belong to the job format (job/schema.hpp).
using job::Given;
using job::read_simulation_fields;
using job::SimulationFields;

// The options' text and its conversion belong to the job too (job/field_options.hpp).
using job::fields_from_options;
using job::SimulationOptions;

// Adds an option per field (--case, --inertia, ... --no-chart-switch) to
// `cmd`, read into `options`, with the field's help, choices and default.
void add_simulation_options(cli::Command cmd, SimulationOptions& options);

}  // namespace epviz::app
