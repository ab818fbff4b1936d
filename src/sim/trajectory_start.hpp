#pragma once
// Inside sim/: Trajectory::start for each formulation, one file each
// (trajectory_direct.cpp, trajectory_riccati.cpp, trajectory_spinor.cpp), so
// that their stepper instantiations compile in parallel. `spec` has been
// checked by Trajectory::start.
#include <memory>

#include "sim/trajectory.hpp"

namespace epviz::sim::detail {

std::unique_ptr<Trajectory> start_direct(const RunSpec& spec);
std::unique_ptr<Trajectory> start_riccati(const RunSpec& spec);
std::unique_ptr<Trajectory> start_spinor(const RunSpec& spec);

}  // namespace epviz::sim::detail
