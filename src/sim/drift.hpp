#pragma once
// Invariant bookkeeping over a run: each sample's invariants and the largest
// relative drift from their initial values (physics/invariants.hpp defines the scales).
#include <optional>
#include <vector>

#include "physics/invariants.hpp"
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

}  // namespace epviz::sim
