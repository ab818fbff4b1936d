#pragma once
// Initial states whose gamma passes close to the south pole gamma = (0, 0, -1),
// where the Riccati coordinates (a, b) go to infinity: the test case for chart
// switching and for the pole-free spinor formulation; and the stability study
// that sends each formulation through such a passage.
#include <vector>

#include "physics/body.hpp"
#include "study/options.hpp"
#include "study/study_row.hpp"

namespace epviz::study {

// The state at t = 0 from which the body reaches, at t = t_pass, angular
// velocity omega_pass and a gamma at angular distance `distance` from the south
// pole. Found by integrating the direct formulation backwards from the passage
// with DOP853 at tolerance 1e-14.
physics::InitialState pole_passage_initial_state(const physics::Body& body,
                                                 const Eigen::Vector3d& omega_pass, double t_pass,
                                                 double distance);

// DOP853 at tol 1e-10 on the generic body through a passage 1e-7 from the
// south pole, in each formulation (Riccati with and without the chart switch).
std::vector<PolePassageRow> stability_pole(const StudyOptions& o);

}  // namespace epviz::study
