// The steppers of the Riccati formulation (see trajectory_steppers.hpp).
#include "physics/riccati.hpp"
#include "sim/trajectory_steppers.hpp"

namespace epviz::sim::detail {

std::unique_ptr<Trajectory> start_riccati(const RunSpec& spec) {
  return start_with(physics::RiccatiSystem(spec.body, spec.chart_switch), spec);
}

}  // namespace epviz::sim::detail
