#pragma once
// Stability studies: methods pushed into their failure regimes, where the
// failure must be detected and reported. The fifth, the south-pole passage of
// the Riccati chart, is in study/pole_passage.hpp. These four measure runs
// against a reference that is none of the methods at a setting they study
// (study/reference.hpp, CheckedReference: DOP853 at 1e-14 checked by Gauss6).
#include <string>
#include <vector>

#include "physics/cases.hpp"
#include "sim/simulate.hpp"
#include "study/options.hpp"
#include "study/reference.hpp"
#include "study/study_row.hpp"

namespace epviz::study {

// The largest state error at t_end, against the reference, of a run that
// keeps the motion's shape.
inline constexpr double kMaxStateError = 0.1;

// Whether one fixed-step run of `c`'s preset over t_end keeps the motion: no
// failure (in particular none of the run's own drift check, sim::MotionCheck
// at the default limit) and a state error at most kMaxStateError at t_end.
struct StepVerdict {
  bool ok = true;
  // "" when ok: "blew up: ..." (not finite), "lost the motion: ..." (the drift
  // check), "failed: ..." (another failure) or "off the reference: error ...".
  std::string reason;
  double error = 0.0, energy_drift = 0.0, failure_t = 0.0;
};
StepVerdict check_fixed_step(physics::Case c, sim::Method m, double step, double t_end,
                             const sim::Sample& reference_end);

// The largest fixed step keeping the motion, on Kovalevskaya and Lagrange.
std::vector<MaxStepRow> stability_max_step(const StudyOptions& o);
// The Euler case near the separatrix: the first and last flips of Omega_2.
std::vector<SeparatrixRow> stability_separatrix(const StudyOptions& o);
// A fast sleeping top (Omega3 = 50): the cheapest run with gamma error < 1e-3.
std::vector<SleepingTopRow> stability_sleeping(const StudyOptions& o);
// The generic body from a strongly chaotic state: when a run separates from
// the reference, an independent one (study/reference.hpp, CheckedReference).
std::vector<ChaosRow> stability_chaos(const StudyOptions& o);

// A run has separated from the motion once its state error from the
// reference passes this.
inline constexpr double kChaosThreshold = 1e-3;
// The reference judges a run only while its two halves (DOP853 and Gauss6)
// agree to this fraction of the threshold: a separation it sees is then one
// from the true motion, give or take a tenth.
inline constexpr double kReferenceMargin = 0.1;

// Sets row.separated and row.separation_time (the first sample where the run
// is off `ref` by more than row.threshold, or not finite), looking only as
// far as the reference is trusted (trusted_until(threshold x margin)); and
// row.reference_horizon and row.reference_decides: false when the run has not separated by then and
// the reference is not trusted to the end (a cell the reference cannot decide).
void judge_separation(ChaosRow& row, const std::vector<sim::Sample>& run,
                      const CheckedReference& ref);

// The initial state of the generic body used by the chaos study: one with a
// short Lyapunov time, so that the study's runs separate within its time span.
physics::InitialState chaos_initial_state();

}  // namespace epviz::study
