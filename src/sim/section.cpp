#include "sim/section.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "physics/direct.hpp"
#include "physics/notation.hpp"
#include "sim/drift.hpp"
#include "sim/ensemble.hpp"
#include "sim/rhs_tally.hpp"
#include "sim/steppers.hpp"

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

constexpr std::array<std::pair<CrossingDirection, std::string_view>, 3> kDirections{{
    {CrossingDirection::upward, "upward"},
    {CrossingDirection::downward, "downward"},
    {CrossingDirection::both, "both"},
}};

using State = physics::DirectSystem::State;

// The section function of a state (State, or a batch lane's std::array).
template <class X>
double level_of(const SectionSurface& s, const X& x) {
  return x[std::size_t(s.function)] - s.value;
}

// The section function of a whole state for any surface: a component's
// level_of, or for an Andoyer angle r sin(angle − value) with its half
// cos(angle − value) > 0 (SectionSurface::angle).
class SurfaceFunction {
 public:
  SurfaceFunction(const SectionSurface& s, const physics::Body& body)
      : surface_(s), body_(body), cos_c_(std::cos(s.value)), sin_c_(std::sin(s.value)) {}
  bool is_angle() const { return surface_.angle.has_value(); }
  double level(const State& x) const {
    if (!is_angle()) return level_of(surface_, x);
    const auto a = physics::andoyer_angle_sides(*surface_.angle, body_, x.head<3>(), x.tail<3>());
    return a.sine * cos_c_ - a.cosine * sin_c_;
  }
  // d level / dt at x moving at dx.
  double rate(const State& x, const State& dx) const {
    if (!is_angle()) return dx[Eigen::Index(surface_.function)];
    const auto a = physics::andoyer_angle_sides_rate(*surface_.angle, body_, x.head<3>(),
                                                     x.tail<3>(), dx.head<3>(), dx.tail<3>());
    return a.sine * cos_c_ - a.cosine * sin_c_;
  }
  // Whether a zero of level() at x is on the surface: for an angle, not the
  // opposite one (angle = value + π) where r sin(angle − value) vanishes too.
  bool on_surface(const State& x) const {
    if (!is_angle()) return true;
    const auto a = physics::andoyer_angle_sides(*surface_.angle, body_, x.head<3>(), x.tail<3>());
    return a.sine * sin_c_ + a.cosine * cos_c_ > 0.0;
  }

 private:
  SectionSurface surface_;
  physics::Body body_;
  double cos_c_, sin_c_;
};

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
  // The method's evaluations and the interpolant's.
  long rhs_evals() const { return stepper_.stats().rhs_evals + interpolation_evals_; }
  State dense(double t_at) const {
    if (!have_derivatives_) {
      equations_.rhs(t() - h_, x0_, d0_);
      equations_.rhs(t(), x1_, d1_);
      interpolation_evals_ += 2;
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
  mutable long interpolation_evals_ = 0;
};

template <class Stepper>
long rhs_evals_of(const Stepper& stepper) {
  if constexpr (requires { stepper.rhs_evals(); })
    return stepper.rhs_evals();
  else
    return stepper.stats().rhs_evals;
}

// A step's dense output as the crossing search reads it, at times within the
// step: the section function (all the search needs while it iterates) and
// the state.
class DenseOutput {
 public:
  virtual double level(double t) = 0;
  virtual State state(double t) = 0;

 protected:
  ~DenseOutput() = default;
};

// A dense output that gives the whole state (a scalar stepper's, or a step
// shown to a SectionObserver): `state_at(t)`, the state found for the
// section function kept for the state asked at the same time.
template <class StateAt>
class WholeStateDense final : public DenseOutput {
 public:
  WholeStateDense(StateAt state_at, const SurfaceFunction& surface)
      : state_at_(std::move(state_at)), surface_(surface) {}
  double level(double t) override {
    t_ = t;
    x_ = state_at_(t);
    return surface_.level(x_);
  }
  State state(double t) override { return t == t_ ? x_ : State(state_at_(t)); }

 private:
  StateAt state_at_;
  const SurfaceFunction& surface_;
  double t_ = std::numeric_limits<double>::quiet_NaN();
  State x_;
};

// The root of the section function on [t0, t1] (g0 = g(t0) and g1 = g(t1) of
// opposite signs, or g1 = 0; x1 the state at t1) along the step's dense
// output: regula falsi with the Illinois modification, which keeps the
// bracket and converges superlinearly where plain regula falsi stalls on one
// end.
std::pair<double, State> locate(DenseOutput& dense, double t0, double g0, double t1, double g1,
                                const State& x1) {
  double t = t1;
  if (g1 == 0.0) return {t, x1};
  int kept_side = 0;  // which end the last iteration kept: +1 t1, -1 t0
  for (int i = 0; i < 200; ++i) {
    t = (t0 * g1 - t1 * g0) / (g1 - g0);
    if (!(t > t0 && t < t1)) t = 0.5 * (t0 + t1);
    const double g = dense.level(t);
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
  return {t, dense.state(t)};
}

// The turning point of the section function inside a step whose ends see it
// move towards the surface and then away from it (r0 = g'(t0) and r1 =
// g'(t1) of opposite signs): the root of g' along the step's dense output, by
// the same Illinois iteration on the rate g' = f(x)_c of the dense state.
template <class Rate>
double turning_point(DenseOutput& dense, const Rate& rate, double t0, double r0, double t1,
                     double r1) {
  double t = 0.5 * (t0 + t1);
  int kept_side = 0;
  for (int i = 0; i < 100; ++i) {
    t = (t0 * r1 - t1 * r0) / (r1 - r0);
    if (!(t > t0 && t < t1)) t = 0.5 * (t0 + t1);
    const double r = rate(dense.state(t));
    if (r == 0.0 || std::nextafter(t0, t1) >= t1 || (t1 - t0) <= 1e-14 * std::abs(t1)) break;
    if ((r < 0.0) == (r0 < 0.0)) {
      t0 = t;
      r0 = r;
      if (kept_side == 1) r1 *= 0.5;
      kept_side = 1;
    } else {
      t1 = t;
      r1 = r;
      if (kept_side == -1) r0 *= 0.5;
      kept_side = -1;
    }
  }
  return t;
}

// One orbit's section, shown its steps in turn by either integration path
// (the scalar stepper here, the batch's step hook below), so that both find
// the same crossings from the same steps. The drift limit is checked on what
// the section keeps, every crossing, and on the last step's end (a check at
// every step end made sections about 15 % slower).
class OrbitSection {
 public:
  OrbitSection(const RunSpec& run, const SectionSurface& surface, int max_crossings)
      : surface_(surface, run.body),
        equations_(run.body),
        check_(run.body, run.initial, run.max_drift),
        method_(name(run.method)),
        t_end_(run.t_end),
        max_crossings_(max_crossings),
        direction_(surface.direction) {}

  double level(const State& x) const { return surface_.level(x); }
  // The rate of the section function at x along the direct equations.
  double rate(const State& x) const {
    State dx;
    equations_.rhs(0.0, x, dx);
    return surface_.rate(x, dx);
  }
  bool crosses(double g0, double g1) const { return sim::crosses(direction_, g0, g1); }
  const SurfaceFunction& function() const { return surface_; }
  // A step whose ends lie on one side of the surface, the first moving
  // towards it and the second away: the section function turns inside the
  // step and may pass through the surface and back within it (a grazing
  // passage, which a sign test of the ends alone loses).
  bool turns_towards(double g0, double g1, const State& x0, const State& x1) const {
    if (g0 == 0.0 || (g0 < 0.0) != (g1 < 0.0)) return false;
    const double r0 = rate(x0), r1 = rate(x1);
    return (r0 < 0.0) == (g0 > 0.0) && r0 != 0.0 && (r1 > 0.0) == (g1 > 0.0) && r1 != 0.0;
  }
  // Whether the step from x0 to x1 may hold a crossing: the dense output is
  // needed for it.
  bool may_cross(const State& x0, const State& x1) const {
    const double g0 = level(x0), g1 = level(x1);
    return crosses(g0, g1) || turns_towards(g0, g1, x0, x1);
  }

  // Every crossing in the step from (t0, x0) to (t1, x1), located on its
  // dense output, checked and kept in order; the first failure, if any.
  std::optional<numerics::Failure> scan(double t0, const State& x0, double t1, const State& x1,
                                        DenseOutput& dense) {
    const double g0 = level(x0), g1 = level(x1);
    if (crosses(g0, g1)) return take(t0, g0, t1, g1, x1, dense);
    if (!turns_towards(g0, g1, x0, x1)) return std::nullopt;
    const double tm = turning_point(
        dense, [this](const State& x) { return rate(x); }, t0, rate(x0), t1, rate(x1));
    const State xm = dense.state(tm);
    const double gm = level(xm);
    if ((gm < 0.0) == (g0 < 0.0) && gm != 0.0) return std::nullopt;  // turned short of it
    // Through the surface to the turning point, and back.
    if (crosses(g0, gm))
      if (auto failure = take(t0, g0, tm, gm, xm, dense)) return failure;
    if (!done() && gm != 0.0 && crosses(gm, g1)) return take(tm, gm, t1, g1, x1, dense);
    return std::nullopt;
  }
  // Enough crossings, or one past t_end: the orbit goes no further.
  bool done() const { return done_ || int(found_.size()) >= max_crossings_; }

  // The crossing in the step from (t0, g0) to (t1, g1) (crosses(g0, g1)),
  // located on its dense output, checked and kept; its failure, if any.
  std::optional<numerics::Failure> take(double t0, double g0, double t1, double g1, const State& x1,
                                        DenseOutput& dense) {
    const auto [t, x] = locate(dense, t0, g0, t1, g1, x1);
    if (t > t_end_) {
      done_ = true;
      return std::nullopt;
    }
    if (!surface_.on_surface(x)) return std::nullopt;  // an angle's opposite half
    if (auto failure = motion_failure(t, x)) return failure;
    found_.push_back({int(found_.size()) + 1, t, x.template head<3>(), x.template tail<3>()});
    return std::nullopt;
  }

  // The check of the last step's end.
  std::optional<numerics::Failure> motion_failure(double t, const State& x) const {
    Sample s;
    s.t = t;
    s.omega = x.head<3>();
    s.gamma = x.tail<3>();
    return check_.failure(s, method_);
  }

  std::vector<Crossing>& crossings() { return found_; }
  const std::vector<Crossing>& crossings() const { return found_; }

 private:
  SurfaceFunction surface_;
  physics::DirectSystem equations_;
  MotionCheck check_;
  std::string method_;
  double t_end_;
  int max_crossings_;
  CrossingDirection direction_;
  bool done_ = false;
  std::vector<Crossing> found_;
};

// Adds a stepper's evaluations to the process's tally (sim/rhs_tally.hpp)
// when its section ends, however it ends.
template <class Stepper>
struct TallyOnExit {
  const Stepper& stepper;
  ~TallyOnExit() { tally_rhs_evals(rhs_evals_of(stepper)); }
};

template <class Stepper>
std::vector<Crossing> run_section(Stepper stepper, const RunSpec& run,
                                  const SectionSurface& surface, int max_crossings) {
  OrbitSection section(run, surface, max_crossings);
  const auto fail_on = [](std::optional<numerics::Failure> failure) {
    if (failure) throw numerics::IntegrationError(*failure);
  };
  const TallyOnExit<Stepper> tally{stepper};
  WholeStateDense dense([&stepper](double t) { return State(stepper.dense(t)); },
                        section.function());
  stepper.init(0.0, physics::DirectSystem::pack(run.initial));
  State x_prev = stepper.state();
  while (!section.done() && stepper.t() < run.t_end) {
    const double t0 = stepper.t();
    stepper.step();
    if (section.may_cross(x_prev, stepper.state()))
      fail_on(section.scan(t0, x_prev, stepper.t(), stepper.state(), dense));
    x_prev = stepper.state();
  }
  fail_on(section.motion_failure(stepper.t(), stepper.state()));
  return std::move(section.crossings());
}

State state_of(const std::array<double, 6>& x) {
  State s;
  for (int i = 0; i < 6; ++i) s[i] = x[std::size_t(i)];
  return s;
}

// A batch lane's: the section function from the one component it is of,
// or for an angle from the whole state.
class LaneDense final : public DenseOutput {
 public:
  LaneDense(const numerics::BatchDense<6>& dense, const SectionSurface& surface,
            const SurfaceFunction& function)
      : dense_(dense), surface_(surface), function_(function) {}
  double level(double t) override {
    if (function_.is_angle()) return function_.level(state(t));
    return level_of(surface_, Component{dense_.component(int(surface_.function), t)});
  }
  State state(double t) override { return state_of(dense_(t)); }

 private:
  // One component standing for the state it is of, for level_of.
  struct Component {
    double value;
    double operator[](std::size_t) const { return value; }
  };
  const numerics::BatchDense<6>& dense_;
  const SectionSurface& surface_;
  const SurfaceFunction& function_;
};

// The step hook that shows every orbit's steps to its OrbitSection (sections
// indexed by the task's id), as run_section's loop does: the dense output is
// asked for where a step may hold a crossing (OrbitSection::may_cross on the
// lane's numbers, the scalar loop's test on the same values; it changes
// nothing of the orbit's section), and at the last step, whose end is checked.
numerics::BatchStepHook<6> section_hook(std::vector<OrbitSection>& sections,
                                        const std::vector<RunSpec>& runs,
                                        const SectionSurface& surface) {
  numerics::BatchStepHook<6> hook;
  hook.wants_dense = [&sections, t_end = runs.front().t_end](const numerics::BatchStep<6>& step) {
    return sections[std::size_t(step.id)].may_cross(state_of(step.x_prev), state_of(step.x)) ||
           step.t >= t_end;
  };
  hook.look = [&](const numerics::BatchStep<6>& step, const numerics::BatchDense<6>& dense) {
    OrbitSection& section = sections[std::size_t(step.id)];
    const State x0 = state_of(step.x_prev), x1 = state_of(step.x);
    numerics::BatchStepVerdict verdict;
    if (section.may_cross(x0, x1)) {
      LaneDense at(dense, surface, section.function());
      verdict.failure = section.scan(step.t_prev, x0, step.t, x1, at);
      if (verdict.failure) return verdict;
    }
    if (section.done() || step.t >= runs.front().t_end) {
      verdict.failure = section.motion_failure(step.t, x1);
      verdict.stop = true;
    }
    return verdict;
  };
  return hook;
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

std::string_view symbol(StateComponent c) {
  const auto i = std::size_t(c);  // Ω₁, Ω₂, Ω₃, then γ₁, γ₂, γ₃
  return i < 3 ? physics::symbol::omega_component[i] : physics::symbol::gamma_component[i - 3];
}

std::optional<StateComponent> state_component_from_name(std::string_view s) {
  for (const auto& [c, n] : kComponents)
    if (n == s) return c;
  return std::nullopt;
}

double value_of(StateComponent c, const physics::Vector3d& omega, const physics::Vector3d& gamma) {
  const int i = int(c);
  return i < 3 ? omega[i] : gamma[i - 3];
}

std::string_view name(physics::AndoyerAngle a) {
  return a == physics::AndoyerAngle::l ? "andoyer_l" : "andoyer_g";
}

std::optional<physics::AndoyerAngle> andoyer_angle_from_name(std::string_view s) {
  for (auto a : {physics::AndoyerAngle::l, physics::AndoyerAngle::g})
    if (name(a) == s) return a;
  return std::nullopt;
}

std::string_view surface_function_name(const SectionSurface& s) {
  return s.angle ? name(*s.angle) : name(s.function);
}

std::string_view surface_function_symbol(const SectionSurface& s) {
  if (s.angle) return *s.angle == physics::AndoyerAngle::l ? "l" : "g";
  return symbol(s.function);
}

std::string_view name(CrossingDirection d) { return kDirections[std::size_t(d)].second; }

std::optional<CrossingDirection> crossing_direction_from_name(std::string_view s) {
  for (const auto& [d, n] : kDirections)
    if (n == s) return d;
  return std::nullopt;
}

std::vector<Crossing> section_crossings(const RunSpec& run, const SectionSurface& surface,
                                        int max_crossings) {
  return with_stepper(physics::DirectSystem(run.body), run, [&](auto stepper) {
    if constexpr (AdaptiveStepper<decltype(stepper)>)
      return run_section(std::move(stepper), run, surface, max_crossings);
    else
      return run_section(FixedSteps<decltype(stepper)>(std::move(stepper), run.step, run.body), run,
                         surface, max_crossings);
  });
}

struct SectionObserver::Search {
  SectionSurface surface;
  OrbitSection section;
};

SectionObserver::SectionObserver(const RunSpec& run, const SectionSurface& surface)
    : search_(std::make_unique<Search>(
          Search{surface, OrbitSection(run, surface, std::numeric_limits<int>::max())})) {}

SectionObserver::~SectionObserver() = default;

void SectionObserver::step(const DenseStep& step) {
  OrbitSection& section = search_->section;
  // As run_section's loop: the dense output only for a step that may hold a crossing.
  if (section.done() || !section.may_cross(step.x0, step.x1)) return;
  WholeStateDense dense([&step](double t) { return step.at(t); }, section.function());
  if (auto failure = section.scan(step.t0, step.x0, step.t1, step.x1, dense))
    throw numerics::IntegrationError(*failure);
}

const std::vector<Crossing>& SectionObserver::crossings() const {
  return search_->section.crossings();
}

bool sections_batched(const RunSpec& run) { return batchable(run); }

std::vector<OrbitCrossings> section_crossings_batched(const std::vector<RunSpec>& runs,
                                                      const SectionSurface& surface,
                                                      int max_crossings, int threads) {
  std::vector<OrbitCrossings> out(runs.size());
  if (runs.empty()) return out;
  const RunSpec& first = runs.front();
  std::vector<OrbitSection> sections;
  std::vector<sim::DirectBatchTask> tasks;
  sections.reserve(runs.size());
  tasks.reserve(runs.size());
  for (const RunSpec& run : runs) {
    if (!sections_batched(run) || !share_a_batch(run, first) || run.t_end != first.t_end)
      throw std::invalid_argument(
          "section_crossings_batched: every run dop853 with one body, tolerance, step budget and "
          "t_end");
    sections.emplace_back(run, surface, max_crossings);
    tasks.push_back(sim::direct_batch_task(run.initial, run.t_end));
    tasks.back().id = long(tasks.size()) - 1;
  }
  sim::DirectBatchSettings settings = dop853_batch_settings(first);
  settings.step_hook = section_hook(sections, runs, surface);
  auto results = sim::integrate_direct_batch_parallel(first.body, tasks, settings, threads);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    out[i].failure = std::move(results[i].failure);
    if (!out[i].failure) out[i].crossings = std::move(sections[i].crossings());
  }
  return out;
}

}  // namespace epviz::sim
