// The steppers of the spinor formulation (see trajectory_steppers.hpp).
#include "physics/spinor.hpp"
#include "sim/trajectory_steppers.hpp"

// The one copy of its out-of-line steppers (sim/steppers.hpp).
EPVIZ_SIM_INSTANTIATE_STEPPERS(::epviz::physics::SpinorSystem)

namespace epviz::sim::detail {

std::unique_ptr<Trajectory> start_spinor(const RunSpec& spec) {
  return start_with(physics::SpinorSystem(spec.body), spec);
}

}  // namespace epviz::sim::detail
