#pragma once
// Study options small enough for a unit test: the quick form, one CPU-time
// repeat, and only the methods, cases and formulations named (empty: the
// study's own).
#include <vector>

#include "study/options.hpp"

namespace epviz::testing {

inline study::StudyOptions quick_options(std::vector<sim::Method> methods = {},
                                         std::vector<physics::Case> cases = {},
                                         std::vector<sim::Formulation> formulations = {}) {
  study::StudyOptions o;
  o.quick = true;
  o.repeats = 1;
  o.methods = std::move(methods);
  o.cases = std::move(cases);
  o.formulations = std::move(formulations);
  return o;
}

}  // namespace epviz::testing
