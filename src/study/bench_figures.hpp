#pragma once
// The figures of `epviz bench`, as plain chart and table specifications
// (chart/chart_spec.hpp) for a painter to draw; the file names say what each is:
//   work_precision_<case>.png        error vs CPU time (log-log), a line per formulation x method (x impl)
//   work_precision_evals_<case>.png  error vs rhs evaluations (log-log)
//   drift_<case>.png                 relative drift of C1 and the fourth integral vs time (log y),
//                                    a panel per method family on shared axes
//   stability.png                    the largest stable step, method x case, as a heat map
//   stability_chaos.png              time until a chaotic run separates, method x accuracy
//   stability_separatrix.png         error of the first flip's time, method x accuracy
//   stability_runs.png               the other stability rows (pole, sleeping top) as a table
#include <vector>

#include "chart/chart_spec.hpp"
#include "study/study_row.hpp"

namespace epviz::study {

// The charts (work-precision by case, then drift by case, cases in name order;
// colour by method, marker by formulation or peer library) and, when there
// are stability rows, the heat map and the table last.
std::vector<chart::Figure> bench_figures(const std::vector<StudyRow>& rows);

// The stability rows as a table (no rows when there are none); the rows the
// heat maps show (largest step, chaos, separatrix) only when asked for.
chart::TableSpec stability_table(const std::vector<StudyRow>& rows, bool with_heat_mapped = true);
// The largest stable step over the fastest period, a row per method and a
// column per case; NaN where even the smallest step tried fails.
chart::HeatMapSpec stability_heat_map(const std::vector<StudyRow>& rows);
// Method x accuracy level (coarsest first): the chaos study's time of
// separation (NaN: none within the run), the separatrix study's error of the
// first flip's time (NaN: no flip).
chart::HeatMapSpec chaos_heat_map(const std::vector<StudyRow>& rows);
chart::HeatMapSpec separatrix_heat_map(const std::vector<StudyRow>& rows);

}  // namespace epviz::study
