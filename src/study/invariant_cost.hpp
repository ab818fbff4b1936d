#pragma once
// Invariant cost: on Kovalevskaya (direct formulation), for each method the
// cheapest accuracy setting on a ladder (coarse to fine; tolerances for
// adaptive methods, steps for fixed-step ones) whose largest relative drift of
// C1 and of the fourth integral over t_end stays below `target`; reached is
// false when the finest setting within the ladder's cost cap still misses.
// t_end <= 0: 1e4 (full) / 1e3 (quick).
#include <vector>

#include "study/options.hpp"
#include "study/study_row.hpp"

namespace epviz::study {

inline constexpr double kInvariantCostTarget = 1e-8;
std::vector<InvariantCostRow> invariant_cost_study(const StudyOptions& o, double t_end = 0.0,
                                                   double target = kInvariantCostTarget);

}  // namespace epviz::study
