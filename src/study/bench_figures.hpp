#pragma once
// The figures of `epviz bench`, as plain chart and table specifications
// (chart/chart_spec.hpp) for a painter to draw; the file names say what each is:
//   work_precision_<case>.png        error vs CPU time (log-log), a line per formulation x method (x impl)
//   work_precision_evals_<case>.png  error vs rhs evaluations (log-log)
//   drift_<case>.png                 relative drift of C1 and the fourth integral vs time (log y)
//   stability.png                    the stability rows as a table
#include <vector>

#include "chart/chart_spec.hpp"
#include "study/study_row.hpp"

namespace epviz::study {

// The charts (work-precision by case, then drift by case, cases in name order)
// and, when there are stability rows, the stability table last.
std::vector<chart::Figure> bench_figures(const std::vector<StudyRow>& rows);

// The stability rows as a table (no rows when there are none).
chart::TableSpec stability_table(const std::vector<StudyRow>& rows);

}  // namespace epviz::study
