#pragma once
// The reference solution used by `epviz bench` to measure global errors, and
// the error measure itself. The reference is computed by a different method
// from those it judges at much tighter accuracy: Richardson extrapolation of
// Gauss6 (fixed steps h and h/2, combined as (64 y_{h/2} - y_h) / 63 to cancel
// the h^6 term of the global error), checked against DOP853 at tolerance 1e-14.
#include <vector>

#include "physics/body.hpp"
#include "sim/simulate.hpp"

namespace epviz::study {

// Global error of one state against another: |Omega - Omega_ref|_2 + |gamma - gamma_ref|_2
// (Euclidean norms of the two 3-vectors, added).
double state_error(const sim::Sample& a, const sim::Sample& b);

// 2 pi / |Omega|: the period of the fastest rotation of a state.
double fastest_period(const physics::InitialState& s);

struct Reference {
  std::vector<sim::Sample> samples;  // at output_times(t_end, samples)
  double step = 0.0;                 // the coarse Gauss6 step h (the fine one is h / 2)
  // Max over the samples of state_error(Richardson, DOP853 at tol 1e-14): the
  // two independent references' disagreement.
  double self_check = 0.0;
  double cpu_seconds = 0.0;
};

// Reference trajectory of (body, initial) in the direct formulation. `h_target`
// is the largest Gauss6 step; it is shortened so that h and h/2 both divide the
// output spacing. Throws std::runtime_error if either reference run fails.
Reference compute_reference(const physics::Body& body, const physics::InitialState& initial,
                            double t_end, int samples, double h_target);

// A reasonable h_target: min(0.01, T / 200) with T = fastest_period(initial).
double reference_step(const physics::InitialState& initial);

// A reference for a study that judges the methods themselves, independent of
// every method at the settings it studies: DOP853 at tolerance 1e-14 (below
// any tolerance studied), checked sample by sample against Gauss6 at a fixed
// step far below any step studied, a method of another family. On a chaotic
// orbit both drift from the true motion as their round-off grows; where they
// disagree, the reference cannot say whether a run has left the motion.
struct CheckedReference {
  std::vector<sim::Sample> samples;  // DOP853 at tol, at output_times(t_end, samples)
  std::vector<double> disagreement;  // state_error(DOP853, Gauss6) at each sample
  double tol = 1e-14;                // DOP853's
  double check_step = 0.0;           // Gauss6's (h_target shortened to divide the spacing)
  double cpu_seconds = 0.0;
  // The largest disagreement over all samples: the two references' agreement.
  double self_check() const;
  // The last sample time up to which the disagreement stays at most `margin`
  // (every sample before it included); the first sample's time (0) when even
  // that one disagrees, the last one's (t_end) when none does.
  double trusted_until(double margin) const;
};

// `h_target` is the largest Gauss6 step; it is shortened to divide the
// output spacing t_end / samples. Throws std::runtime_error if either run fails.
CheckedReference compute_checked_reference(const physics::Body& body,
                                           const physics::InitialState& initial, double t_end,
                                           int samples, double h_target);

// The Gauss6 step of the stability studies' checked references: an eighth
// of reference_step(initial), below every step those studies take.
double check_step(const physics::InitialState& initial);

}  // namespace epviz::study
