#pragma once
// The simulation fields, as a job file or the command line gave them, checked
// against each other and against physics: the run they describe.
#include "job/document.hpp"
#include "sim/run_spec.hpp"

namespace epviz::job {

// Checks the fields against each other and against physics and fills in the
// defaults: a case preset's body and state for fields not given (the generic
// body, labelled custom, without a case or with case "custom"). Throws
// io::BadInput naming the origin.
sim::RunSpec resolve(const SimulationFields& fields);

}  // namespace epviz::job
