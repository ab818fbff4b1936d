#pragma once
// The keys a sweep's row and `epviz simulate`'s report share, written in one
// place so that both say the same of the same run: case, formulation, method
// and its accuracy (tol, or the step asked for and the effective step),
// initial state, end time, failure kind, the largest relative drift of every
// invariant, and the work (samples written, steps, evaluations, rejected
// steps, CPU seconds of the integration).
#include "io/json_line.hpp"
#include "sim/drift.hpp"
#include "sim/run_spec.hpp"
#include "sim/simulate.hpp"

namespace epviz::sweep {

// Writes the shared members into the object `j` has open.
void write_run_record(io::JsonLine& j, const sim::RunSpec& spec, const sim::RunResult& result,
                      const sim::Drifts& drift);

}  // namespace epviz::sweep
