#pragma once
// The tables `epviz bench` prints of its rows: work-precision per case, the
// peers' ratios, invariant drift and cost, and the five stability studies.
#include <string>
#include <vector>

#include "study/study_row.hpp"

namespace epviz::study {

// Every table of `rows`, in that order (text_table.hpp); a study without rows
// prints nothing.
std::string bench_tables(const std::vector<StudyRow>& rows);

}  // namespace epviz::study
