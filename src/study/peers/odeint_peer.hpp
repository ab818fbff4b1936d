#pragma once
// Boost.Odeint's runge_kutta_dopri5 (controlled and dense output) and
// runge_kutta_fehlberg78 (controlled) on the direct system.
#include "study/peers/peer_run.hpp"

namespace epviz::study::peers {

enum class OdeintStepper { dopri5_controlled, dopri5_dense, rkf78_controlled };

// abs = rel = tol from 0 to t_end; a library error (odeint throws on step-size
// underflow or too many steps) is returned in failure.
PeerRun run_odeint(OdeintStepper stepper, const physics::DirectSystem& sys,
                   const physics::DirectSystem::State& x0, double tol, double t_end);

}  // namespace epviz::study::peers
