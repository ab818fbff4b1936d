#include "sim/trajectory.hpp"

#include <stdexcept>

#include "sim/trajectory_start.hpp"

namespace epviz::sim {

std::unique_ptr<Trajectory> Trajectory::start(const RunSpec& spec) {
  if (auto why = incompatibility(spec.method, spec.formulation)) throw std::invalid_argument(*why);
  if (!(spec.t_end > 0.0) || spec.samples < 1)
    throw std::invalid_argument("t_end must be positive and samples at least 1");
  switch (spec.formulation) {
    case Formulation::direct: return detail::start_direct(spec);
    case Formulation::riccati: return detail::start_riccati(spec);
    case Formulation::spinor: return detail::start_spinor(spec);
  }
  throw std::invalid_argument("unknown formulation");
}

}  // namespace epviz::sim
