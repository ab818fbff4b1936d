#pragma once
// Small helpers shared by the trajectory-level tests.
#include "physics/cases.hpp"
#include "sim/run_spec.hpp"
#include "sim/simulate.hpp"

namespace epviz::test {

inline double max_gamma_difference(const sim::RunResult& a, const sim::RunResult& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.samples.size(), b.samples.size()); ++i)
    worst = std::max(worst, (a.samples[i].gamma - b.samples[i].gamma).norm());
  return worst;
}

}  // namespace epviz::test
