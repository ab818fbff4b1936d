#include "study/peers/peers.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "study/peers/odeint_peer.hpp"
#include "study/peers/scipy_peer.hpp"
#include "study/timing.hpp"
#ifdef EPVIZ_HAVE_GSL
#include "study/peers/gsl_peer.hpp"
#endif

namespace epviz::study::peers {
namespace {

using physics::DirectSystem;

bool is_scipy(PeerId id) {
  return id == PeerId::scipy_dop853_solve_ivp || id == PeerId::scipy_dop853_ode;
}

PeerRun run_cpp_peer(PeerId id, const DirectSystem& sys, const DirectSystem::State& x0, double tol,
                     double t_end) {
  PeerRun r;
  switch (id) {
    case PeerId::odeint_dopri5_controlled:
      r = run_odeint(OdeintStepper::dopri5_controlled, sys, x0, tol, t_end);
      break;
    case PeerId::odeint_dopri5_dense:
      r = run_odeint(OdeintStepper::dopri5_dense, sys, x0, tol, t_end);
      break;
    case PeerId::odeint_rkf78_controlled:
      r = run_odeint(OdeintStepper::rkf78_controlled, sys, x0, tol, t_end);
      break;
    case PeerId::gsl_rk8pd:
#ifdef EPVIZ_HAVE_GSL
      r = run_gsl_rk8pd(sys, x0, tol, t_end);
      break;
#else
      throw std::invalid_argument("run_peer: this build has no GSL");
#endif
    case PeerId::scipy_dop853_solve_ivp:
    case PeerId::scipy_dop853_ode: throw std::invalid_argument("run_peer: not a C++ peer");
  }
  for (double v : r.x)
    if (!std::isfinite(v) && r.failure.empty()) r.failure = "non-finite state";
  return r;
}

}  // namespace

const std::vector<PeerId>& all_peers() {
  static const std::vector<PeerId> ids{PeerId::odeint_dopri5_controlled,
                                       PeerId::odeint_dopri5_dense,
                                       PeerId::odeint_rkf78_controlled,
#ifdef EPVIZ_HAVE_GSL
                                       PeerId::gsl_rk8pd,
#endif
                                       PeerId::scipy_dop853_solve_ivp,
                                       PeerId::scipy_dop853_ode};
  return ids;
}

std::string impl_name(PeerId id) {
  switch (id) {
    case PeerId::odeint_dopri5_controlled:
    case PeerId::odeint_dopri5_dense:
    case PeerId::odeint_rkf78_controlled: return "boost-odeint";
    case PeerId::gsl_rk8pd: return "gsl";
    case PeerId::scipy_dop853_solve_ivp:
    case PeerId::scipy_dop853_ode: return "scipy";
  }
  return "?";
}

std::string method_name(PeerId id) {
  switch (id) {
    case PeerId::odeint_dopri5_controlled: return "dopri5-controlled";
    case PeerId::odeint_dopri5_dense: return "dopri5-dense";
    case PeerId::odeint_rkf78_controlled: return "rkf78-controlled";
    case PeerId::gsl_rk8pd: return "rk8pd";
    case PeerId::scipy_dop853_solve_ivp: return "dop853-solve_ivp";
    case PeerId::scipy_dop853_ode: return "dop853-ode";
  }
  return "?";
}

PeerResult run_peer(PeerId id, const sim::RunSpec& spec, int repeats) {
  repeats = std::max(repeats, 1);
  if (is_scipy(id)) {
    auto s = run_scipy_peers(spec.body, spec.initial, spec.t_end, {spec.tol}, repeats);
    return id == PeerId::scipy_dop853_solve_ivp ? s.solve_ivp.at(0) : s.ode.at(0);
  }
  const DirectSystem sys(spec.body);
  const DirectSystem::State x0 = DirectSystem::pack(spec.initial);
  std::vector<double> cpu;
  PeerRun first;
  for (int k = 0; k < repeats; ++k) {
    const double start = cpu_seconds_now();
    PeerRun r = run_cpp_peer(id, sys, x0, spec.tol, spec.t_end);
    cpu.push_back(cpu_seconds_now() - start);
    if (k == 0) {
      first = r;
      repeats = repeats_after_first(cpu.back(), repeats);
    }
    if (!r.failure.empty()) break;  // a failed run is not timed again
  }
  PeerResult out;
  out.t = first.t;
  out.omega = Eigen::Vector3d(first.x[0], first.x[1], first.x[2]);
  out.gamma = Eigen::Vector3d(first.x[3], first.x[4], first.x[5]);
  out.rhs_evals = first.rhs;
  out.steps = first.steps;
  out.cpu_seconds = median(cpu);
  out.repeats = int(cpu.size());
  if (!first.failure.empty()) {
    out.status = PeerStatus::failed;
    out.reason = first.failure;
  }
  return out;
}

std::vector<PeerRow> peer_work_precision(const physics::Body& body,
                                         const physics::InitialState& initial,
                                         const std::vector<double>& tolerances, double t_end,
                                         int repeats) {
  sim::RunSpec spec = sim::body_run(physics::Case::custom, body, initial, sim::Method::dop853,
                                    sim::Formulation::direct, t_end, 1);
  std::vector<PeerRow> rows;
  for (const PeerId id : all_peers()) {
    if (is_scipy(id)) continue;
    for (const double tol : tolerances) {
      spec.tol = tol;
      rows.push_back({id, tol, t_end, run_peer(id, spec, repeats)});
    }
  }
  const auto s = run_scipy_peers(body, initial, t_end, tolerances, repeats);
  for (std::size_t i = 0; i < tolerances.size(); ++i)
    rows.push_back({PeerId::scipy_dop853_solve_ivp, tolerances[i], t_end, s.solve_ivp[i]});
  for (std::size_t i = 0; i < tolerances.size(); ++i)
    rows.push_back({PeerId::scipy_dop853_ode, tolerances[i], t_end, s.ode[i]});
  return rows;
}

}  // namespace epviz::study::peers
