#pragma once
// Small helpers shared by the trajectory-level tests.
#include "physics/cases.hpp"
#include "sim/run_spec.hpp"
#include "sim/simulate.hpp"

namespace epviz::test {

inline sim::RunSpec preset_spec(physics::Case c, sim::Method m, sim::Formulation f,
                                double t_end, int samples) {
  const auto& p = physics::preset(c);
  sim::RunSpec s;
  s.case_id = c;
  s.body = p.body;
  s.initial = p.initial;
  s.method = m;
  s.formulation = f;
  s.t_end = t_end;
  s.samples = samples;
  return s;
}

inline double max_gamma_difference(const sim::RunResult& a, const sim::RunResult& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.samples.size(), b.samples.size()); ++i)
    worst = std::max(worst, (a.samples[i].gamma - b.samples[i].gamma).norm());
  return worst;
}

}  // namespace epviz::test
