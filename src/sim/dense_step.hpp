#pragma once
// An accepted step of a run as an observer with dense output sees it: what a
// Poincaré section needs to find its crossings as the run goes
// (sim/section.hpp, SectionObserver), instead of integrating the orbit again.
// The states are in the direct formulation's variables (Omega, gamma)
// whatever the run integrates, so that one crossing search serves all.
#include <Eigen/Core>

namespace epviz::sim {

class DenseStep {
 public:
  using State = Eigen::Matrix<double, 6, 1>;  // (Omega, gamma)

  double t0 = 0.0, t1 = 0.0;  // the step's start and end
  State x0, x1;               // the states there
  // The step's dense output at t in [t0, t1] (a fixed-step method's: the
  // cubic Hermite interpolant its samples use).
  virtual State at(double t) const = 0;

 protected:
  ~DenseStep() = default;
};

}  // namespace epviz::sim
