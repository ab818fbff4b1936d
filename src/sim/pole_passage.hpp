#pragma once
// Initial states whose gamma passes close to the south pole gamma = (0, 0, -1),
// where the Riccati coordinates (a, b) go to infinity: the test case for chart
// switching and for the pole-free spinor formulation.
#include "physics/body.hpp"

namespace epviz::sim {

// The state at t = 0 from which the body reaches, at t = t_pass, angular
// velocity omega_pass and a gamma at angular distance `distance` from the south
// pole. Found by integrating the direct formulation backwards from the passage
// with DOP853 at tolerance 1e-14.
physics::InitialState pole_passage_initial_state(const physics::Body& body,
                                                 const Eigen::Vector3d& omega_pass,
                                                 double t_pass, double distance);

}  // namespace epviz::sim
