#include "sim/section.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "numerics/composition.hpp"
#include "numerics/embedded_rk.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/rk4.hpp"
#include "numerics/splitting.hpp"
#include "physics/direct.hpp"
#include "physics/free_rigid_body_flow.hpp"
#include "sim/drift.hpp"

namespace epviz::sim {
namespace {

constexpr std::array<std::pair<StateComponent, std::string_view>, 6> kComponents{{
    {StateComponent::omega1, "omega1"},
    {StateComponent::omega2, "omega2"},
    {StateComponent::omega3, "omega3"},
    {StateComponent::gamma1, "gamma1"},
    {StateComponent::gamma2, "gamma2"},
    {StateComponent::gamma3, "gamma3"},
}};

constexpr std::array<std::string_view, 6> kSymbols{"Ω₁", "Ω₂", "Ω₃", "γ₁", "γ₂", "γ₃"};

constexpr std::array<std::pair<CrossingDirection, std::string_view>, 3> kDirections{{
    {CrossingDirection::upward, "upward"},
    {CrossingDirection::downward, "downward"},
    {CrossingDirection::both, "both"},
}};

using State = physics::DirectSystem::State;

double level_of(const SectionSurface& s, const State& x) { return x[int(s.function)] - s.value; }

bool crosses(CrossingDirection d, double before, double after) {
  const bool up = before < 0.0 && after >= 0.0;
  const bool down = before > 0.0 && after <= 0.0;
  switch (d) {
    case CrossingDirection::upward: return up;
    case CrossingDirection::downward: return down;
    case CrossingDirection::both: return up || down;
  }
  return false;
}

// A fixed-step method as section_crossings drives a stepper: steps of exactly
// `h`, and between two step ends the cubic Hermite interpolant of the states
// and their derivatives (error O(h^4) per step, as for the trajectories of
// sim/trajectory_steppers.hpp). The derivatives are those of the direct
// equations, evaluated only for steps that hold a crossing.
template <class Stepper>
class FixedSteps {
 public:
  FixedSteps(Stepper stepper, double h, const physics::Body& body)
      : stepper_(std::move(stepper)), equations_(body), h_(h) {}
  void init(double t0, const State& x) {
    n_ = 0;
    t0_ = t0;
    x1_ = x;
  }
  void step() {
    x0_ = x1_;
    stepper_.step(x1_, t(), h_);
    ++n_;
    have_derivatives_ = false;
  }
  double t() const { return t0_ + double(n_) * h_; }
  const State& state() const { return x1_; }
  State dense(double t_at) const {
    if (!have_derivatives_) {
      equations_.rhs(t() - h_, x0_, d0_);
      equations_.rhs(t(), x1_, d1_);
      have_derivatives_ = true;
    }
    const double s = (t_at - (t() - h_)) / h_, r = 1.0 - s;
    const double h00 = (1.0 + 2.0 * s) * r * r, h10 = s * r * r;
    const double h01 = s * s * (3.0 - 2.0 * s), h11 = -s * s * r;
    return State(h00 * x0_ + (h10 * h_) * d0_ + h01 * x1_ + (h11 * h_) * d1_);
  }

 private:
  Stepper stepper_;
  physics::DirectSystem equations_;
  double h_;
  double t0_ = 0.0;
  long n_ = 0;
  State x0_, x1_;
  mutable State d0_, d1_;
  mutable bool have_derivatives_ = false;
};

// The root of the section function on [t0, t1] (g0 = g(t0) and g1 = g(t1) of
// opposite signs, or g1 = 0) along the stepper's dense output: regula falsi
// with the Illinois modification, which keeps the bracket and converges
// superlinearly where plain regula falsi stalls on one end.
template <class Stepper>
std::pair<double, State> locate(const Stepper& stepper, const SectionSurface& s, double t0,
                                double g0, double t1, double g1) {
  State x = stepper.state();
  double t = t1;
  if (g1 == 0.0) return {t, x};
  int kept_side = 0;  // which end the last iteration kept: +1 t1, -1 t0
  for (int i = 0; i < 200; ++i) {
    t = (t0 * g1 - t1 * g0) / (g1 - g0);
    if (!(t > t0 && t < t1)) t = 0.5 * (t0 + t1);
    x = stepper.dense(t);
    const double g = level_of(s, x);
    if (std::abs(g) <= 0.25 * kSectionResidual || std::nextafter(t0, t1) >= t1) break;
    if ((g < 0.0) == (g0 < 0.0)) {
      t0 = t;
      g0 = g;
      if (kept_side == 1) g1 *= 0.5;
      kept_side = 1;
    } else {
      t1 = t;
      g1 = g;
      if (kept_side == -1) g0 *= 0.5;
      kept_side = -1;
    }
  }
  return {t, x};
}

template <class Stepper>
std::vector<Crossing> run_section(Stepper stepper, const RunSpec& run,
                                  const SectionSurface& surface, int max_crossings) {
  // The stepper refuses non-finite states itself; the drift limit is checked
  // on what the section keeps, every crossing, and on the last step's end
  // (a check at every step end made sections about 15 % slower).
  const MotionCheck check(run.body, run.initial, run.max_drift);
  const std::string method(name(run.method));
  auto keep_motion = [&](double t, const State& x) {
    Sample s;
    s.t = t;
    s.omega = x.head<3>();
    s.gamma = x.tail<3>();
    if (auto failure = check.failure(s, method)) throw numerics::IntegrationError(*failure);
  };
  std::vector<Crossing> found;
  stepper.init(0.0, physics::DirectSystem::pack(run.initial));
  double g_prev = level_of(surface, stepper.state());
  while (int(found.size()) < max_crossings && stepper.t() < run.t_end) {
    const double t0 = stepper.t();
    stepper.step();
    const double g1 = level_of(surface, stepper.state());
    if (crosses(surface.direction, g_prev, g1)) {
      const auto [t, x] = locate(stepper, surface, t0, g_prev, stepper.t(), g1);
      if (t > run.t_end) break;
      keep_motion(t, x);
      found.push_back({int(found.size()) + 1, t, x.template head<3>(), x.template tail<3>()});
    }
    g_prev = g1;
  }
  keep_motion(stepper.t(), stepper.state());
  return found;
}

}  // namespace

const std::vector<StateComponent>& all_state_components() {
  static const std::vector<StateComponent> all = [] {
    std::vector<StateComponent> v;
    for (const auto& [c, n] : kComponents) v.push_back(c);
    return v;
  }();
  return all;
}

std::string_view name(StateComponent c) { return kComponents[std::size_t(c)].second; }

std::string_view symbol(StateComponent c) { return kSymbols[std::size_t(c)]; }

std::optional<StateComponent> state_component_from_name(std::string_view s) {
  for (const auto& [c, n] : kComponents)
    if (n == s) return c;
  return std::nullopt;
}

double value_of(StateComponent c, const physics::Vector3d& omega, const physics::Vector3d& gamma) {
  const int i = int(c);
  return i < 3 ? omega[i] : gamma[i - 3];
}

std::string_view name(CrossingDirection d) { return kDirections[std::size_t(d)].second; }

std::optional<CrossingDirection> crossing_direction_from_name(std::string_view s) {
  for (const auto& [d, n] : kDirections)
    if (n == s) return d;
  return std::nullopt;
}

std::vector<Crossing> section_crossings(const RunSpec& run, const SectionSurface& surface,
                                        int max_crossings) {
  using physics::DirectSystem;
  using physics::ExactSplitSystem;
  numerics::AdaptiveOptions opts;
  opts.rtol = run.tol;
  opts.atol = run.tol;
  opts.max_steps = run.max_steps;
  const DirectSystem sys(run.body);
  auto fixed = [&](auto stepper) {
    return run_section(FixedSteps<decltype(stepper)>(std::move(stepper), run.step, run.body), run,
                       surface, max_crossings);
  };
  switch (run.method) {
    case Method::dopri5:
      return run_section(numerics::Dopri5<DirectSystem>(sys, opts), run, surface, max_crossings);
    case Method::dop853:
      return run_section(numerics::Dop853<DirectSystem>(sys, opts), run, surface, max_crossings);
    case Method::rk4: return fixed(numerics::Rk4<DirectSystem>(sys));
    case Method::midpoint: return fixed(numerics::ImplicitMidpoint<DirectSystem>(sys));
    case Method::gauss4: return fixed(numerics::Gauss4<DirectSystem>(sys));
    case Method::gauss6: return fixed(numerics::Gauss6<DirectSystem>(sys));
    case Method::splitting: return fixed(numerics::StrangSplitting<DirectSystem>(sys));
    case Method::exact_split2:
      return fixed(
          numerics::Composition2<ExactSplitSystem>(ExactSplitSystem(run.body), "exact-split2"));
    case Method::exact_split4:
      return fixed(
          numerics::Composition4<ExactSplitSystem>(ExactSplitSystem(run.body), "exact-split4"));
  }
  throw std::invalid_argument("unknown method");
}

}  // namespace epviz::sim
