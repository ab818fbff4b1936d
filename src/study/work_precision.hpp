#pragma once
// Work-precision: global error at t_end against the case's reference
// (study/reference.hpp) over a sweep of tolerances (adaptive methods) or steps
// (fixed-step ones), for each case, formulation and method.
#include <vector>

#include "physics/cases.hpp"
#include "study/options.hpp"
#include "study/study_row.hpp"

namespace epviz::study {

// The final time of the work-precision runs of case c.
double wp_t_end(physics::Case c);
// The final time of p's work-precision runs: a job's own, else wp_t_end(p.id).
double wp_t_end(const Problem& p);

// Per case: its WorkPrecisionRows, then its ReferenceRow.
std::vector<StudyRow> work_precision_study(const StudyOptions& o);

}  // namespace epviz::study
