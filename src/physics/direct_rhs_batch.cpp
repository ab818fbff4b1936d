#include "physics/direct_rhs_batch.hpp"

#include "physics/body.hpp"

namespace epviz::physics {

DirectBatchSystem DirectBatchSystem::of(const Body& body) {
  // As DirectSystem's constructor: 1 / I_i and P r component by component.
  DirectBatchSystem s{};
  for (int i = 0; i < 3; ++i) {
    s.inertia[i] = body.inertia[i];
    s.inv_inertia[i] = 1.0 / body.inertia[i];
    s.pr[i] = body.weight * body.com[i];
  }
  return s;
}

}  // namespace epviz::physics
