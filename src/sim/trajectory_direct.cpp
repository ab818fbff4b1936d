// The steppers of the direct formulation, and the exact splittings, whose
// sub-flows are exact only for the direct state (see trajectory_steppers.hpp).
#include "numerics/composition.hpp"
#include "physics/direct.hpp"
#include "physics/free_rigid_body_flow.hpp"
#include "sim/trajectory_steppers.hpp"

namespace epviz::sim::detail {

std::unique_ptr<Trajectory> start_direct(const RunSpec& spec) {
  // Kick + exact free rigid body flow: the direct formulation's state, split differently.
  if (spec.method == Method::exact_split2)
    return fixed(numerics::Composition2<physics::ExactSplitSystem>(
                     physics::ExactSplitSystem(spec.body), "exact-split2"),
                 spec);
  if (spec.method == Method::exact_split4)
    return fixed(numerics::Composition4<physics::ExactSplitSystem>(
                     physics::ExactSplitSystem(spec.body), "exact-split4"),
                 spec);
  return start_with(physics::DirectSystem(spec.body), spec);
}

}  // namespace epviz::sim::detail
