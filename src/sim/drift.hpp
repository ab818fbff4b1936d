#pragma once
// Invariant bookkeeping over a run: each sample's invariants and the largest
// relative drift from their initial values (physics/invariants.hpp defines the scales).
#include <optional>
#include <string_view>
#include <vector>

#include "numerics/failure.hpp"

#include "physics/invariants.hpp"
#include "sim/run_spec.hpp"
#include "sim/simulate.hpp"

namespace epviz::sim {

struct Drifts {
  double gamma_norm2 = 0.0;
  double area = 0.0;
  double energy = 0.0;
  std::optional<double> extra;  // only for cases with a fourth integral
};

class InvariantMonitor {
 public:
  // The reference values are those of the initial state of the run.
  InvariantMonitor(const physics::Body& body, physics::Case c,
                   const physics::InitialState& initial);

  physics::Invariants at(const Sample& s) const;
  Drifts relative_drift(const physics::Invariants& now) const;
  Drifts max_relative_drift(const std::vector<Sample>& samples) const;

  // A running maximum: start from no_drift() (zero, with an extra entry when
  // the case has a fourth integral) and fold each sample in with worsen(). A
  // non-finite drift wins: it is the worst there is.
  Drifts no_drift() const;
  void worsen(Drifts& worst, const Sample& s) const;

 private:
  physics::Body body_;
  physics::Case case_;
  physics::Invariants initial_;
  physics::Invariants scale_;
};

// The two figures every report gives of a run's invariants (epviz simulate's
// and render's, from one RunDriftMonitor each): the largest relative drift at
// the integrator's steps, the method's own conservation, and over the states
// handed out (written or drawn, at the output times, interpolated between
// steps or by dense output). They differ: implicit midpoint keeps a quadratic
// invariant to round-off at its steps, not on the cubic between them.
struct RunDrifts {
  Drifts steps;
  Drifts output;
};

// Folds both of one run: step() with the state at the end of every accepted
// step (sim::Trajectory::observe_steps), output() with every state handed out.
class RunDriftMonitor {
 public:
  explicit RunDriftMonitor(const RunSpec& spec);

  void step(const Sample& s) { monitor_.worsen(drifts_.steps, s); }
  void output(const Sample& s) { monitor_.worsen(drifts_.output, s); }
  const RunDrifts& drifts() const { return drifts_; }

 private:
  InvariantMonitor monitor_;
  RunDrifts drifts_;
};

// The test every run passes at each output time, whoever consumes it (epviz
// simulate, render, the live view, the stability study): the sample must be
// finite, and its relative drift of the energy and of |gamma|^2 at most a limit
// (RunSpec::max_drift). A run that fails it is no longer the motion of the
// body, however finite its numbers: it ends there, as a numerical failure.
// Cheap enough for every sample: two quadratic forms and a comparison.
class MotionCheck {
 public:
  MotionCheck(const physics::Body& body, const physics::InitialState& initial, double max_drift);

  // nullopt when `s` keeps the motion; otherwise the failure at s.t, with
  // kind non_finite (NaN or Inf in the sample, or in its energy or |gamma|^2)
  // or lost_motion (a drift above the limit, named in the detail), reported
  // for `method`.
  std::optional<numerics::Failure> failure(const Sample& s, std::string_view method) const;

  double max_drift() const { return max_drift_; }

 private:
  InvariantMonitor monitor_;  // of a custom case: the energy and |gamma|^2 need no case
  double max_drift_;
};

}  // namespace epviz::sim
