#pragma once
// One point of an energy-momentum map: a level (C1, C0) of the two integrals
// every body has, and a measure of chaos over M orbits that start on it
// (physics/level_set.hpp gives the states; docs/cluster.md, "Energy-momentum
// maps"). A level below the least energy at its C0 (physics/admissible.hpp)
// has no states: its row says so, as a fact about the level, not a failure.
#include <optional>
#include <string>

#include "physics/level_set.hpp"
#include "sim/run_spec.hpp"
#include "sweep/point_run.hpp"
#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {

// An orbit counts as chaotic when its FTLE is above this (1/time). An
// integrable orbit's FTLE falls only like log(T) / T (its separation grows
// linearly), and more slowly near a separatrix: on the shipped Kovalevskaya
// map at T = 100 it reaches 0.095 (away from C0 = 0, docs/cluster.md), while
// the generic body's chaotic levels keep 0.15 to 0.3.
inline constexpr double kChaoticFtle = 0.1;

// An FTLE alone cannot tell chaos from a hyperbolic set of an integrable top
// (a separatrix, an unstable periodic orbit such as Kovalevskaya's planar
// pendulum at C0 = 0): neighbours part exponentially from both. A case with
// a fourth integral is integrable, and an orbit that keeps that integral lies
// on a 2-dimensional set of (C0, C1, the integral), where no motion is chaotic:
// its FTLE above kChaoticFtle counts as hyperbolic, not chaotic. Kept means a
// largest relative range (max − min over the window ends, divided by its
// scale) of at most this, 1e4 times what dop853 at tol 1e-12 leaves (1e-10);
// beyond it the run is too coarse to say, and the orbit is undecided.
inline constexpr double kKeptIntegral = 1e-6;

struct LevelMetrics {
  bool admissible = false;
  double minimum_energy = 0.0;  // the least C1 at this C0
  int orbits = 0;  // states on the level (up to the sweep's level_orbits; level_point.cpp)
  int lost = 0;    // orbits whose FTLE is undefined (a failed integration)
  std::optional<double> largest_ftle;  // over the orbits that were not lost
  // Orbits not lost whose FTLE is above kChaoticFtle: in a case without a
  // fourth integral chaotic; in one with it hyperbolic where the orbit kept it
  // (to kKeptIntegral), else undecided.
  int chaotic = 0, hyperbolic = 0, undecided = 0;
  // chaotic / (orbits not lost and not undecided); nullopt when none is left.
  std::optional<double> chaotic_share;
  // The case's fourth integral: the largest (max - min) / scale over an
  // orbit's window ends, over the orbits (invariant_scales); nullopt without one.
  std::optional<double> extra_integral_range;
  double cpu_seconds = 0.0;
};

// Runs `orbits` orbits of `level` with `run`'s body, method, accuracy and
// t_end (its initial state is not used), each with the FTLE of `ftle`.
LevelMetrics level_metrics(const sim::RunSpec& run, const physics::Level& level, int orbits,
                           const FtleSettings& ftle);

// The row of a level point: its index, sweep, axes, the run's settings and
// the LevelMetrics ("ftle" the largest FTLE, so that the self-check and the
// atlas read it as any sweep's).
PointRow level_row(const PreparedPoint& point, const std::string& sweep_hash,
                   const LevelMetrics& m);

}  // namespace epviz::sweep
