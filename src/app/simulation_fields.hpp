#pragma once
// The fields that describe a simulation, as given on the command line or in a
// job file, before they are checked against each other and against physics.
// Each field remembers where it came from ("--inertia", "job.json: key 'inertia'")
// so that an error names what the user wrote.
#include "job/document.hpp"
#include "job/schema.hpp"
#include "sim/run_spec.hpp"

namespace epviz::app {

// The fields and their reading from a job belong to the job format (job/schema.hpp).
using job::Given;
using job::read_simulation_fields;
using job::SimulationFields;

// Checks the fields against each other and against physics and fills in the
// defaults: a case preset's body and state for fields not given (the generic
// body, labelled custom, without a case). Throws UsageError naming the origin.
sim::RunSpec resolve(const SimulationFields& fields);

}  // namespace epviz::app
