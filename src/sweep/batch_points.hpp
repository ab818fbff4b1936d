#pragma once
// Sweep points integrated side by side by the batch integrator
// (sim/ensemble.hpp, docs/ensembles.md), several to the vector
// registers of one core, with the very rows run_point gives them: the batch
// lane is the scalar DOP853 of sim::simulate, bit for bit, and the row is
// made by the same code (point_row) from the same numbers.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sweep/point_run.hpp"

namespace epviz::sweep {

// Whether run_batched gives `run` the row run_point gives it: the direct
// formulation integrated by dop853, its samples kept in memory (at most
// kKeptSamples). Other points keep the scalar path.
bool runs_batched(const sim::RunSpec& run);

// Points that may share a batch: the same body, tolerance and step budget
// (the batch's settings); the initial states, end times, sample counts and
// drift limits are each trajectory's own.
std::string batch_key(const sim::RunSpec& run);

// Hands `emit` the row of each of `points` (each runs_batched, all of one
// batch_key; throws std::logic_error otherwise), integrated on this thread
// as one batch: the runs, each row as soon as its run ends; with an FTLE,
// then the windows of every point side by side (each window's base and
// neighbour state two lanes), and the rows in order when the last window
// ends. A trajectory that fails (lost motion, not finite, the step budget)
// fails alone; its row says so as run_point's would. The CPU time of a row is
// the thread's from its run's start to its end, divided among the lanes.
void run_batched(const std::vector<const PreparedPoint*>& points, const std::string& sweep_hash,
                 bool reference, const std::optional<FtleSettings>& ftle, ReferenceCache* cache,
                 const std::function<void(const PointRow&)>& emit);

}  // namespace epviz::sweep
