#pragma once
// Peer integrators run on epviz's own problem, for `epviz bench` to compare
// with: Boost.Odeint (runge_kutta_dopri5 controlled and dense-output,
// runge_kutta_fehlberg78 controlled), GSL's rk8pd (gsl_odeiv2_driver; only
// when CMake found GSL) and SciPy's DOP853 (solve_ivp and ode('dop853'),
// through bench/peers/scipy_driver.py). The C++ peers integrate
// physics::DirectSystem's rhs (math.md eqs. 1.1-1.2) wrapped for each
// library's callback type; the SciPy driver writes the same equations in plain
// Python. Every peer uses abs = rel = tol, runs from t = 0 to t_end with no
// intermediate output and is timed like epviz's runs (study/timing.hpp:
// process CPU time, integration only, median of repeats).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "physics/cases.hpp"
#include "sim/run_spec.hpp"

namespace epviz::study::peers {

enum class PeerId {
  odeint_dopri5_controlled,  // make_controlled(tol, tol, runge_kutta_dopri5) + integrate_adaptive
  odeint_dopri5_dense,  // make_dense_output(tol, tol, runge_kutta_dopri5) + integrate_times {0, t_end}
  odeint_rkf78_controlled,  // make_controlled(tol, tol, runge_kutta_fehlberg78) + integrate_adaptive
  gsl_rk8pd,                // gsl_odeiv2_driver_alloc_y_new(rk8pd, tol, tol) + driver_apply
  scipy_dop853_solve_ivp,   // scipy.integrate.solve_ivp(method='DOP853', rtol=atol=tol)
  scipy_dop853_ode,         // scipy.integrate.ode('dop853', rtol=atol=tol) (Hairer's Fortran)
};

// The peers this build offers (GSL's only when it was found at configure time).
const std::vector<PeerId>& all_peers();
std::string impl_name(PeerId id);    // "boost-odeint", "gsl", "scipy"
std::string method_name(PeerId id);  // "dopri5-controlled", "dopri5-dense", "rkf78-controlled",
                                     // "rk8pd", "dop853-solve_ivp", "dop853-ode"

enum class PeerStatus {
  ok,
  failed,   // the library reported an error
  skipped,  // the peer could not run here (no python3 or scipy, no driver script)
};

struct PeerResult {
  PeerStatus status = PeerStatus::ok;
  std::string reason;  // why failed/skipped, "" when ok
  double t = 0.0;      // time reached (t_end when ok)
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  Eigen::Vector3d gamma = Eigen::Vector3d::UnitZ();
  long rhs_evals = 0;        // of the first run
  long steps = -1;           // accepted steps; -1 where the library does not say (scipy ode)
  double cpu_seconds = 0.0;  // median over repeats, integration only
  int repeats = 0;
  bool ok() const { return status == PeerStatus::ok; }
};

// One peer on spec's body and initial state (direct formulation), abs = rel =
// spec.tol, from 0 to spec.t_end; spec.method, formulation, step and samples are
// ignored. The SciPy peers start one Python process per call (prefer
// run_scipy_peers for sweeps). Never throws for a library failure: see status.
PeerResult run_peer(PeerId id, const sim::RunSpec& spec, int repeats = 1);

// One peer at one tolerance: what the peer study turns into a work-precision row.
struct PeerRow {
  PeerId id{};
  double tol = 0.0;
  double t_end = 0.0;
  PeerResult result;
};

// Every peer at every tolerance on a body from an initial state (a preset's,
// or a job's) over [0, t_end]. The SciPy rows come from one Python process for
// all tolerances; without /usr/bin/python3 or scipy they are skipped, with the
// reason.
std::vector<PeerRow> peer_work_precision(const physics::Body& body,
                                         const physics::InitialState& initial,
                                         const std::vector<double>& tolerances, double t_end,
                                         int repeats);

}  // namespace epviz::study::peers
