// GCC flags the copy of a freshly built runge_kutta_fehlberg78 inside
// make_controlled as maybe-uninitialized (a false positive in Boost headers).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include "peers/peers.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <boost/numeric/odeint.hpp>
#include <ctime>
#include <stdexcept>

#include "peers/scipy_peer.hpp"
#include "physics/direct.hpp"
#include "sim/study_bench.hpp"

namespace epviz::peers {
namespace {

namespace odeint = boost::numeric::odeint;
using OdeState = std::array<double, 6>;
using physics::DirectSystem;

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// DirectSystem::rhs on plain arrays (the libraries' state types), counting calls.
struct CountingRhs {
  const DirectSystem* sys;
  long* count;
  void operator()(const double* x, double* dxdt) const {
    ++*count;
    const DirectSystem::State xs = Eigen::Map<const DirectSystem::State>(x);
    DirectSystem::State d;
    sys->rhs(0.0, xs, d);
    std::copy(d.data(), d.data() + 6, dxdt);
  }
};

// Boost.Odeint's System concept: sys(x, dxdt, t).
struct OdeintSystem {
  CountingRhs f;
  void operator()(const OdeState& x, OdeState& dxdt, double /*t*/) const { f(x.data(), dxdt.data()); }
};

int gsl_rhs(double /*t*/, const double y[], double dydt[], void* params) {
  (*static_cast<const CountingRhs*>(params))(y, dydt);
  return GSL_SUCCESS;
}

struct OneRun {
  std::array<double, 6> x{};
  double t = 0.0;
  long rhs = 0, steps = 0;
  std::string failure;  // "" = ok
};

OneRun run_once(PeerId id, const DirectSystem& sys, const DirectSystem::State& x0, double tol,
                double t_end) {
  OneRun r;
  std::copy(x0.data(), x0.data() + 6, r.x.begin());
  CountingRhs f{&sys, &r.rhs};
  const double dt0 = std::min(1e-3, t_end);
  try {
    switch (id) {
      case PeerId::odeint_dopri5_controlled: {
        auto stepper = odeint::make_controlled(tol, tol, odeint::runge_kutta_dopri5<OdeState>());
        r.steps = long(odeint::integrate_adaptive(stepper, OdeintSystem{f}, r.x, 0.0, t_end, dt0));
        r.t = t_end;
        break;
      }
      case PeerId::odeint_dopri5_dense: {
        auto stepper = odeint::make_dense_output(tol, tol, odeint::runge_kutta_dopri5<OdeState>());
        const std::array<double, 2> times{0.0, t_end};
        OdeState out = r.x;
        r.steps = long(odeint::integrate_times(stepper, OdeintSystem{f}, r.x, times.begin(),
                                               times.end(), dt0,
                                               [&](const OdeState& x, double t) {
                                                 out = x;
                                                 r.t = t;
                                               }));
        r.x = out;
        break;
      }
      case PeerId::odeint_rkf78_controlled: {
        auto stepper = odeint::make_controlled(tol, tol, odeint::runge_kutta_fehlberg78<OdeState>());
        r.steps = long(odeint::integrate_adaptive(stepper, OdeintSystem{f}, r.x, 0.0, t_end, dt0));
        r.t = t_end;
        break;
      }
      case PeerId::gsl_rk8pd: {
        gsl_odeiv2_system s{gsl_rhs, nullptr, 6, &f};
        gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&s, gsl_odeiv2_step_rk8pd, dt0, tol, tol);
        if (!d) throw std::runtime_error("gsl_odeiv2_driver_alloc_y_new failed");
        gsl_odeiv2_driver_set_nmax(d, 0);  // no step limit
        double t = 0.0;
        const int status = gsl_odeiv2_driver_apply(d, &t, t_end, r.x.data());
        r.steps = long(d->e->count - d->e->failed_steps);
        gsl_odeiv2_driver_free(d);
        r.t = t;
        if (status != GSL_SUCCESS)
          r.failure = std::string("gsl_odeiv2_driver_apply: ") + gsl_strerror(status);
        break;
      }
      default:
        throw std::invalid_argument("run_once: not a C++ peer");
    }
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::exception& e) {
    r.failure = e.what();  // odeint throws on step-size underflow / too many steps
  }
  for (double v : r.x)
    if (!std::isfinite(v) && r.failure.empty()) r.failure = "non-finite state";
  return r;
}

bool is_scipy(PeerId id) {
  return id == PeerId::scipy_dop853_solve_ivp || id == PeerId::scipy_dop853_ode;
}

}  // namespace

const std::vector<PeerId>& all_peers() {
  static const std::vector<PeerId> ids{PeerId::odeint_dopri5_controlled, PeerId::odeint_dopri5_dense,
                                       PeerId::odeint_rkf78_controlled,  PeerId::gsl_rk8pd,
                                       PeerId::scipy_dop853_solve_ivp,   PeerId::scipy_dop853_ode};
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
  PeerResult out;
  std::vector<double> cpu;
  OneRun first;
  for (int k = 0; k < repeats; ++k) {
    const double start = cpu_now();
    OneRun r = run_once(id, sys, x0, spec.tol, spec.t_end);
    cpu.push_back(cpu_now() - start);
    if (k == 0) first = r;
    if (!r.failure.empty()) break;  // a failed run is not timed again
    // Long runs are timed once more at most (as sim::timed_run).
    if (k == 0 && cpu.back() > 0.5) repeats = std::min(repeats, 2);
  }
  out.t = first.t;
  out.omega = Eigen::Vector3d(first.x[0], first.x[1], first.x[2]);
  out.gamma = Eigen::Vector3d(first.x[3], first.x[4], first.x[5]);
  out.rhs_evals = first.rhs;
  out.steps = first.steps;
  out.cpu_seconds = median(cpu);
  out.repeats = int(cpu.size());
  if (!first.failure.empty()) {
    out.status = "failed";
    out.reason = first.failure;
  }
  return out;
}

std::vector<PeerRow> peer_work_precision(physics::Case c, const std::vector<double>& tolerances,
                                         double t_end, int repeats) {
  const auto& p = physics::preset(c);
  sim::RunSpec spec = sim::preset_run(c, sim::Method::dop853, sim::Formulation::direct, t_end, 1);
  std::vector<PeerRow> rows;
  auto add = [&](PeerId id, double tol, const PeerResult& r) {
    PeerRow row;
    row.impl = impl_name(id);
    row.method = method_name(id);
    row.id = id;
    row.tol = tol;
    row.t_end = t_end;
    row.omega = r.omega;
    row.gamma = r.gamma;
    row.rhs_evals = r.rhs_evals;
    row.steps = r.steps;
    row.cpu_ms = 1e3 * r.cpu_seconds;
    row.repeats = r.repeats;
    row.status = r.status;
    row.reason = r.reason;
    rows.push_back(row);
  };
  for (const PeerId id : all_peers()) {
    if (is_scipy(id)) continue;
    for (const double tol : tolerances) {
      spec.tol = tol;
      add(id, tol, run_peer(id, spec, repeats));
    }
  }
  const auto s = run_scipy_peers(p.body, p.initial, t_end, tolerances, repeats);
  for (std::size_t i = 0; i < tolerances.size(); ++i) add(PeerId::scipy_dop853_solve_ivp, tolerances[i], s.solve_ivp[i]);
  for (std::size_t i = 0; i < tolerances.size(); ++i) add(PeerId::scipy_dop853_ode, tolerances[i], s.ode[i]);
  return rows;
}

}  // namespace epviz::peers
