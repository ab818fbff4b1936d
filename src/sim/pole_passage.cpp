#include "sim/pole_passage.hpp"

#include <cmath>

#include "numerics/embedded_rk.hpp"
#include "physics/direct.hpp"

namespace epviz::sim {
namespace {

// The direct system with time reversed: x(t_pass - s) solves dx/ds = -f(x).
struct Reversed {
  static constexpr int dim = physics::DirectSystem::dim;
  using State = physics::DirectSystem::State;
  physics::DirectSystem forward;
  void rhs(double t, const State& x, State& dx) const {
    forward.rhs(-t, x, dx);
    dx = -dx;
  }
};

}  // namespace

physics::InitialState pole_passage_initial_state(const physics::Body& body,
                                                 const Eigen::Vector3d& omega_pass,
                                                 double t_pass, double distance) {
  physics::DirectSystem direct(body);
  physics::InitialState at_pass;
  at_pass.omega = omega_pass;
  // Off the pole towards the diagonal of the (1, 2) plane, so that both a and b blow up.
  at_pass.gamma = {std::sin(distance) / std::sqrt(2.0), std::sin(distance) / std::sqrt(2.0),
                   -std::cos(distance)};

  numerics::AdaptiveOptions opts;
  opts.rtol = opts.atol = 1e-14;
  numerics::Dop853<Reversed> back(Reversed{direct}, opts);
  back.init(0.0, direct.pack(at_pass));
  while (back.t() < t_pass) back.step();
  const auto x0 = back.dense(t_pass);

  physics::InitialState start;
  start.omega = direct.omega(x0);
  start.gamma = direct.gamma(x0).normalized();
  return start;
}

}  // namespace epviz::sim
