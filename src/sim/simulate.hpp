#pragma once
// Runs one model with one stepper to a list of output times.
#include <Eigen/Geometry>
#include <functional>
#include <optional>
#include <vector>

#include "numerics/failure.hpp"
#include "numerics/system.hpp"
#include "sim/run_spec.hpp"

namespace epviz::sim {

struct Sample {
  double t = 0.0;
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  Eigen::Vector3d gamma = Eigen::Vector3d::UnitZ();
  // Body-to-space rotation; only the spinor formulation integrates it.
  std::optional<Eigen::Quaterniond> attitude;
};

struct RunResult {
  std::vector<Sample> samples;  // up to the failure, if any (empty when streamed to a sink)
  long samples_written = 0;     // samples produced, kept or streamed
  numerics::Stats stats;
  double cpu_seconds = 0.0;     // integration only: no I/O, no invariant bookkeeping
  double effective_step = 0.0;  // fixed-step methods: the step actually used
  long chart_switches = 0;      // Riccati formulation only
  std::optional<numerics::Failure> failure;
};

// Integrates spec and samples the state at spec.samples + 1 equally spaced
// instants from 0 to spec.t_end (a loop over sim::Trajectory).
// Adaptive methods sample by dense output, so output times never force steps;
// fixed-step methods take steps of exactly spec.step and interpolate the
// output times between steps (cubic Hermite, sim/trajectory_steppers.hpp).
// Numerical failure is not thrown: it ends the run and is returned in `failure`
// (a sample that lost the motion, sim/drift.hpp, is one; samples hold only
// those before it).
// Throws std::invalid_argument for a spec that cannot run (incompatible method).
RunResult simulate(const RunSpec& spec);

// The same run, handing each sample to `sink` instead of keeping it, so that
// memory does not grow with spec.samples (result.samples stays empty).
// `on_step`, when given, receives the state at the end of every accepted step
// (Trajectory::observe_steps), those before an output time ahead of that
// sample. Both are called in order, in bursts of at most a few thousand
// events or a tenth of a second, with the clock stopped: memory does not grow
// with the steps between two samples either, and cpu_seconds counts the
// integration only. Exceptions from either propagate.
using SampleSink = std::function<void(const Sample&)>;
RunResult simulate(const RunSpec& spec, const SampleSink& sink, const SampleSink& on_step = {});

// The calling thread's CPU time in seconds, the clock of cpu_seconds: a run
// integrates on one thread, and in a sweep other threads run other points
// meanwhile (the process's CPU time would count theirs too, and costs a walk
// over all threads to read).
double thread_cpu_seconds();

}  // namespace epviz::sim
