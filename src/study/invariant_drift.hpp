#pragma once
// Long-time drift of the first integrals on Kovalevskaya and
// Goryachev-Chaplygin (direct formulation) at the same budget of evaluations
// per time unit for every method, over 1e5 (full) / 1e3 (quick) time units.
#include <vector>

#include "study/options.hpp"
#include "study/study_row.hpp"

namespace epviz::study {

std::vector<DriftRow> drift_study(const StudyOptions& o);

}  // namespace epviz::study
