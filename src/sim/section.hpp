#pragma once
// Poincaré sections of one orbit: the instants where a state function crosses
// a value in a chosen direction, each located on the dense output of the step
// that brackets it (docs/sections.md).
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "numerics/failure.hpp"
#include "physics/andoyer.hpp"
#include "physics/body.hpp"
#include "sim/dense_step.hpp"
#include "sim/run_spec.hpp"

namespace epviz::sim {

// The state functions a section surface may be a level of: the six
// components of the direct state (Omega, gamma), in that order.
enum class StateComponent { omega1, omega2, omega3, gamma1, gamma2, gamma3 };
const std::vector<StateComponent>& all_state_components();
std::string_view name(StateComponent c);  // "omega1" ... "gamma3"
// As figures write it: "Ω₁" ... "γ₃".
std::string_view symbol(StateComponent c);
std::optional<StateComponent> state_component_from_name(std::string_view s);
double value_of(StateComponent c, const physics::Vector3d& omega, const physics::Vector3d& gamma);

// Which sign change of (function - value) counts: from below to above
// (upward), from above to below (downward), or either.
enum class CrossingDirection { upward, downward, both };
std::string_view name(CrossingDirection d);
std::optional<CrossingDirection> crossing_direction_from_name(std::string_view s);

struct SectionSurface {
  StateComponent function = StateComponent::gamma3;
  double value = 0.0;
  CrossingDirection direction = CrossingDirection::upward;
  // When set, the surface is this Andoyer–Deprit angle = value (mod 2π)
  // instead of `function` = value: found as a zero of the smooth function
  // r sin(angle − value) of the state (physics::andoyer_angle_sides) on the
  // half where cos(angle − value) > 0, so the angle's jump at ±π is no
  // crossing. Its crossings are on the surface to kSectionResidual in that
  // function (r is of the size of G³ for g, G for l).
  std::optional<physics::AndoyerAngle> angle = std::nullopt;
};
// The surface's function as files name it ("gamma3", "andoyer_g") and as
// figures write it ("γ₃", "g").
std::string_view surface_function_name(const SectionSurface& s);
std::string_view surface_function_symbol(const SectionSurface& s);
// The Andoyer angles' names in files: "andoyer_l", "andoyer_g".
std::string_view name(physics::AndoyerAngle a);
std::optional<physics::AndoyerAngle> andoyer_angle_from_name(std::string_view s);

// How close to the surface a crossing lies: |function - value| at the
// recorded state is at most this (or the two bracketing times are adjacent
// doubles, which never happens for a transversal crossing).
inline constexpr double kSectionResidual = 1e-12;

struct Crossing {
  int number = 0;  // 1, 2, ... along the orbit
  double t = 0.0;
  physics::Vector3d omega = physics::Vector3d::Zero();
  physics::Vector3d gamma = physics::Vector3d::UnitZ();
};

// Integrates run.initial in the direct formulation with run.method until
// `max_crossings` crossings of `surface` are found or t reaches run.t_end,
// and returns them in order. Adaptive methods run at run.tol and locate each
// crossing on their dense output; fixed-step methods take steps of run.step
// and locate it on the cubic Hermite interpolant between two step ends.
// Every crossing and the last step's end pass sim::MotionCheck with
// run.max_drift. Throws numerics::IntegrationError for an orbit that is lost
// (a failed step, a non-finite state, drift past the limit).
std::vector<Crossing> section_crossings(const RunSpec& run, const SectionSurface& surface,
                                        int max_crossings);

// One orbit's crossings found from a run as it goes, with no integration of
// its own (a render's section panel, drawn from the run it draws): shown
// each accepted step of the run with its dense output
// (sim::Trajectory::observe_dense_steps), it locates and checks the
// crossings in it as section_crossings does for its own steps, and keeps
// those up to run.t_end. Shown the steps section_crossings takes, it finds
// bitwise its crossings.
class SectionObserver {
 public:
  SectionObserver(const RunSpec& run, const SectionSurface& surface);
  ~SectionObserver();
  SectionObserver(const SectionObserver&) = delete;
  SectionObserver& operator=(const SectionObserver&) = delete;

  // Throws numerics::IntegrationError for a crossing that loses the motion
  // (sim::MotionCheck with run.max_drift).
  void step(const DenseStep& step);
  const std::vector<Crossing>& crossings() const;

 private:
  struct Search;  // the crossing search section_crossings runs
  std::unique_ptr<Search> search_;
};

// Whether section_crossings_batched gives `run` the crossings
// section_crossings gives it: dop853 (the batch integrator's method). Other
// methods keep the scalar path.
bool sections_batched(const RunSpec& run);

// One orbit's crossings, or its failure (then its crossings are no result).
struct OrbitCrossings {
  std::vector<Crossing> crossings;
  std::optional<numerics::Failure> failure;
};

// section_crossings of every run, integrated side by side by the batch
// integrator (sim/ensemble.hpp, on the path EPVIZ_SIMD or the CPU
// chooses) on `threads` threads: each orbit a lane, every step of it shown to
// the same crossing search, which locates a crossing on the lane's dense
// output, bitwise the scalar stepper's. So the crossings and failures are
// bitwise those of section_crossings. The runs must all be sections_batched
// with one body, tolerance, step budget and t_end (std::invalid_argument
// otherwise);
// an orbit's failure ends that orbit only.
std::vector<OrbitCrossings> section_crossings_batched(const std::vector<RunSpec>& runs,
                                                      const SectionSurface& surface,
                                                      int max_crossings, int threads);

}  // namespace epviz::sim
