// The steppers of the direct formulation, the exact splittings among them
// (see trajectory_steppers.hpp).
#include "physics/direct.hpp"
#include "sim/trajectory_steppers.hpp"

namespace epviz::sim::detail {

std::unique_ptr<Trajectory> start_direct(const RunSpec& spec) {
  return start_with(physics::DirectSystem(spec.body), spec);
}

}  // namespace epviz::sim::detail
