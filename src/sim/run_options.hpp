#pragma once
// The one place where a run's accuracy settings become a stepper's options,
// and where it is decided whether runs can share the batch integrator. The
// single runs (sim::Trajectory), the sections, the sweeps' batches and the
// render job's clouds all take them from here, so that a run means the same
// integration on every path (the batch lane is bitwise the scalar stepper).
#include "numerics/embedded_rk.hpp"
#include "sim/ensemble.hpp"
#include "sim/run_spec.hpp"

namespace epviz::sim {

// The tolerance a run's adaptive integration uses: RunSpec::tol for an
// adaptive method. A fixed-step run has none of its own; where something
// beside it must integrate adaptively (the cloud around a render's run), it
// takes the RunSpec default (1e-10).
double adaptive_tol(const RunSpec& run);

// The embedded Runge-Kutta options of a run: adaptive_tol as both the
// relative and the absolute tolerance, RunSpec::max_steps as the budget of
// step attempts; the step control is the method's own (Hairer's).
numerics::AdaptiveOptions adaptive_options(const RunSpec& run);

// Whether a run can be a lane of the batch integrator: DOP853 in the direct
// formulation, the one method and system the batch kernels have.
bool batchable(const RunSpec& run);

// The batch integrator's settings for DOP853 lanes with adaptive_options(run).
sim::DirectBatchSettings dop853_batch_settings(const RunSpec& run);

// Whether two runs can share one batch: the batch's settings are one body,
// tolerance and step budget; initial states, end times and outputs are each
// lane's own.
bool share_a_batch(const RunSpec& a, const RunSpec& b);

}  // namespace epviz::sim
