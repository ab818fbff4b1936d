#pragma once
// A section's crossings as charts for the figure painters, one per method
// (drawn side by side when there are several): one point per crossing at the
// job's two coordinates, one colour per orbit (the palette cycles), no lines:
// a scatter. The charts of one section share their axes, so that a method's
// drift off the invariant curves shows against the others.
#include <string>
#include <vector>

#include "chart/chart_spec.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"

namespace epviz::section {

// One chart per method of job.methods, in order, or with "sheets" two per
// method (the positive sheet, then the negative), and with "sheet" only that
// sheet's crossings. Lost orbits are left out, as in the CSV. A panel that
// folds two sheets (section/sheet_fold.hpp) says so in its title.
std::vector<chart::ChartSpec> section_charts(const SectionJob& job,
                                             const std::vector<OrbitResult>& orbits);

// One line for each panel of the picture that folds two sheets of the
// surface, naming the file, the panel and the measure; none when every
// panel is a chart.
std::vector<std::string> fold_warnings(const SectionJob& job,
                                       const std::vector<OrbitResult>& orbits);

}  // namespace epviz::section
