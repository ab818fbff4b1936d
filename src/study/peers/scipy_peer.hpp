#pragma once
// SciPy's DOP853 (solve_ivp and ode('dop853')) run by bench/peers/scipy_driver.py
// under /usr/bin/python3 (Debian's python3-scipy), talking JSON over pipes.
#include <string>
#include <vector>

#include "physics/body.hpp"
#include "study/peers/peers.hpp"

namespace epviz::study::peers {

// Path of the driver script: $EPVIZ_SCIPY_DRIVER if set, else
// bench/peers/scipy_driver.py in the data directories (io/data_dir.hpp); empty
// when none has it.
std::string scipy_driver_path();

// Both SciPy methods at every tolerance: results[i] for tolerances[i] of
// solve_ivp (first) and ode (second). When python3, scipy or the script is
// missing, every result is skipped, with the reason.
struct ScipyResults {
  std::vector<PeerResult> solve_ivp;
  std::vector<PeerResult> ode;
};
ScipyResults run_scipy_peers(const physics::Body& body, const physics::InitialState& initial,
                             double t_end, const std::vector<double>& tolerances, int repeats);

}  // namespace epviz::study::peers
