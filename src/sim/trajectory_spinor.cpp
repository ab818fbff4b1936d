// The steppers of the spinor formulation (see trajectory_steppers.hpp).
#include "physics/spinor.hpp"
#include "sim/trajectory_steppers.hpp"

namespace epviz::sim::detail {

std::unique_ptr<Trajectory> start_spinor(const RunSpec& spec) {
  return start_with(physics::SpinorSystem(spec.body), spec);
}

}  // namespace epviz::sim::detail
