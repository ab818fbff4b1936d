#include "study/pole_passage.hpp"

#include <cmath>

#include "numerics/embedded_rk.hpp"
#include "physics/direct.hpp"
#include "study/reference.hpp"
#include "study/timed_run.hpp"

namespace epviz::study {
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
                                                 const Eigen::Vector3d& omega_pass, double t_pass,
                                                 double distance) {
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

std::vector<PolePassageRow> stability_pole(const StudyOptions& o) {
  std::vector<PolePassageRow> rows;
  const auto& g = physics::preset(physics::Case::generic);
  const double t_end = 6.0, distance = 1e-7, tol = 1e-10;
  const int samples = 60;
  const auto initial = pole_passage_initial_state(g.body, {0.3, 1.2, -0.4}, 2.0, distance);
  const auto ref = compute_reference(g.body, initial, t_end, samples, reference_step(initial));
  struct Variant {
    sim::Formulation f;
    bool chart_switch;
    const char* label;
  };
  const Variant variants[] = {{sim::Formulation::riccati, true, "riccati+chart-switch"},
                              {sim::Formulation::riccati, false, "riccati-no-switch"},
                              {sim::Formulation::spinor, true, "spinor"},
                              {sim::Formulation::direct, true, "direct"}};
  for (const auto& v : variants) {
    tell(o, std::string("stability (pole passage): ") + v.label);
    sim::RunSpec spec;
    spec.body = g.body;
    spec.initial = initial;
    spec.formulation = v.f;
    spec.method = sim::Method::dop853;
    spec.tol = tol;
    spec.t_end = t_end;
    spec.samples = samples;
    spec.chart_switch = v.chart_switch;
    const auto t = timed_run(spec, repeats_of(o));
    PolePassageRow row{run_record(spec, t)};
    row.variant = v.label;
    row.pole_distance = distance;
    row.chart_switches = t.result.chart_switches;
    row.failure_method = t.result.failure ? t.result.failure->method : std::string();
    if (!t.result.failure && finite(t.result.samples.back()))
      row.error = state_error(t.result.samples.back(), ref.samples.back());
    row.reference_self_check = ref.self_check;
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace epviz::study
