#pragma once
// A process-wide count of the right-hand-side evaluations spent by the
// single-run integrations, sim::Trajectory (its steps and the interpolation
// between fixed steps) and sim::section_crossings, so that a test can check
// how often a piece of work integrates a run (a render with a section panel:
// the run and its shadow, no third pass) without reaching inside it. It is
// added to once per sample or per section: no cost worth measuring. The batch
// integrators (sim/ensemble.hpp) are not counted.
#include <atomic>

namespace epviz::sim {

namespace detail {
inline std::atomic<long> rhs_evals_tallied{0};
}  // namespace detail

inline void tally_rhs_evals(long n) {
  detail::rhs_evals_tallied.fetch_add(n, std::memory_order_relaxed);
}
inline long rhs_evals_tallied() {
  return detail::rhs_evals_tallied.load(std::memory_order_relaxed);
}

}  // namespace epviz::sim
