#pragma once
// GSL's rk8pd through gsl_odeiv2_driver on the direct system. Built only when
// CMake finds GSL (EPVIZ_HAVE_GSL); without it the peer is not offered.
#include "study/peers/peer_run.hpp"

namespace epviz::study::peers {

// abs = rel = tol from 0 to t_end, no step limit; a GSL error is returned in failure.
PeerRun run_gsl_rk8pd(const physics::DirectSystem& sys, const physics::DirectSystem::State& x0,
                      double tol, double t_end);

}  // namespace epviz::study::peers
