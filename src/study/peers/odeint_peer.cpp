// GCC flags the copy of a freshly built runge_kutta_fehlberg78 inside
// make_controlled as maybe-uninitialized (a false positive in Boost headers).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include "study/peers/odeint_peer.hpp"

#include <boost/numeric/odeint.hpp>
#include <exception>

namespace epviz::study::peers {
namespace {

namespace odeint = boost::numeric::odeint;
using OdeState = std::array<double, 6>;

// Boost.Odeint's System concept: sys(x, dxdt, t).
struct OdeintSystem {
  CountingRhs f;
  void operator()(const OdeState& x, OdeState& dxdt, double /*t*/) const {
    f(x.data(), dxdt.data());
  }
};

}  // namespace

PeerRun run_odeint(OdeintStepper which, const physics::DirectSystem& sys,
                   const physics::DirectSystem::State& x0, double tol, double t_end) {
  PeerRun r;
  std::copy(x0.data(), x0.data() + 6, r.x.begin());
  const OdeintSystem system{CountingRhs{&sys, &r.rhs}};
  const double dt0 = std::min(1e-3, t_end);
  try {
    switch (which) {
      case OdeintStepper::dopri5_controlled: {
        auto stepper = odeint::make_controlled(tol, tol, odeint::runge_kutta_dopri5<OdeState>());
        r.steps = long(odeint::integrate_adaptive(stepper, system, r.x, 0.0, t_end, dt0));
        r.t = t_end;
        break;
      }
      case OdeintStepper::dopri5_dense: {
        auto stepper = odeint::make_dense_output(tol, tol, odeint::runge_kutta_dopri5<OdeState>());
        const std::array<double, 2> times{0.0, t_end};
        OdeState out = r.x;
        r.steps = long(odeint::integrate_times(stepper, system, r.x, times.begin(), times.end(),
                                               dt0, [&](const OdeState& x, double t) {
                                                 out = x;
                                                 r.t = t;
                                               }));
        r.x = out;
        break;
      }
      case OdeintStepper::rkf78_controlled: {
        auto stepper =
            odeint::make_controlled(tol, tol, odeint::runge_kutta_fehlberg78<OdeState>());
        r.steps = long(odeint::integrate_adaptive(stepper, system, r.x, 0.0, t_end, dt0));
        r.t = t_end;
        break;
      }
    }
  } catch (const std::exception& e) {
    r.failure = e.what();
  }
  return r;
}

}  // namespace epviz::study::peers
