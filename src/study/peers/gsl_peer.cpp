#include "study/peers/gsl_peer.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

namespace epviz::study::peers {
namespace {

int gsl_rhs(double /*t*/, const double y[], double dydt[], void* params) {
  (*static_cast<const CountingRhs*>(params))(y, dydt);
  return GSL_SUCCESS;
}

}  // namespace

PeerRun run_gsl_rk8pd(const physics::DirectSystem& sys, const physics::DirectSystem::State& x0,
                      double tol, double t_end) {
  PeerRun r;
  std::copy(x0.data(), x0.data() + 6, r.x.begin());
  CountingRhs f{&sys, &r.rhs};
  const double dt0 = std::min(1e-3, t_end);
  gsl_odeiv2_system s{gsl_rhs, nullptr, 6, &f};
  gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&s, gsl_odeiv2_step_rk8pd, dt0, tol, tol);
  if (!d) {
    r.failure = "gsl_odeiv2_driver_alloc_y_new failed";
    return r;
  }
  gsl_odeiv2_driver_set_nmax(d, 0);  // no step limit
  double t = 0.0;
  const int status = gsl_odeiv2_driver_apply(d, &t, t_end, r.x.data());
  r.steps = long(d->e->count - d->e->failed_steps);
  gsl_odeiv2_driver_free(d);
  r.t = t;
  if (status != GSL_SUCCESS)
    r.failure = std::string("gsl_odeiv2_driver_apply: ") + gsl_strerror(status);
  return r;
}

}  // namespace epviz::study::peers
