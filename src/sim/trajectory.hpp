#pragma once
// A simulation that runs ahead one output time at a time, so that a renderer
// can consume it frame by frame with flat memory, and a batch run is just a
// loop over it.
#include <functional>
#include <memory>

#include "numerics/system.hpp"
#include "sim/dense_step.hpp"
#include "sim/run_spec.hpp"
#include "sim/simulate.hpp"

namespace epviz::sim {

class Trajectory {
 public:
  virtual ~Trajectory() = default;

  // The state at t = 0.
  virtual Sample initial() const = 0;
  // Advances to the next output time t_k = k * spacing (k = 1, 2, ...) and
  // returns its sample. Adaptive methods sample by dense output; fixed-step
  // methods take steps of exactly spec.step and interpolate between them
  // (cubic Hermite), so that the output spacing never changes the integration. Throws numerics::IntegrationError,
  // also for a sample that is not finite or lost the motion (sim::MotionCheck
  // with spec.max_drift): a trajectory hands out only samples that keep it.
  virtual Sample next() = 0;

  virtual numerics::Stats stats() const = 0;
  virtual long chart_switches() const = 0;
  virtual double effective_step() const = 0;  // 0 for adaptive methods
  // Right-hand side evaluations spent on interpolating between fixed steps
  // (not in stats(): they are no part of the method).
  virtual long interpolation_evals() const { return 0; }

  // Called with the state at the end of every accepted step, before the
  // output time that needed it is handed out: the drift at the steps, which
  // does not depend on the output spacing (sim::RunDriftMonitor).
  using StepObserver = std::function<void(const Sample&)>;
  virtual void observe_steps(StepObserver observer) { step_observer_ = std::move(observer); }
  // Called after every accepted step with the step and its dense output
  // (sim/dense_step.hpp), before the output time that needed it is handed
  // out: a Poincaré section found from the run itself. The first step shown
  // is the next one taken; an empty observer stops the showing.
  using DenseStepObserver = std::function<void(const DenseStep&)>;
  virtual void observe_dense_steps(DenseStepObserver observer) = 0;
  double spacing() const { return spacing_; }

  // Output spacing spec.t_end / spec.samples. Throws std::invalid_argument for
  // a spec that cannot run.
  static std::unique_ptr<Trajectory> start(const RunSpec& spec);

 protected:
  explicit Trajectory(double spacing) : spacing_(spacing) {}
  // Whether anyone observes the steps: a step's sample is made only then
  // (for the spinor formulation it costs an attitude).
  bool observing_steps() const { return bool(step_observer_); }
  void notify_step(const Sample& s) const { step_observer_(s); }
  double spacing_;
  StepObserver step_observer_;
};

}  // namespace epviz::sim
