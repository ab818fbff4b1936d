#pragma once
// A section's crossings as a chart for the figure painters: one point per
// crossing at the job's two coordinates, one colour per orbit (the palette
// cycles), no lines: a scatter.
#include <vector>

#include "chart/chart_spec.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"

namespace epviz::section {

// Lost orbits are left out, as in the CSV.
chart::ChartSpec section_chart(const SectionJob& job, const std::vector<OrbitResult>& orbits);

}  // namespace epviz::section
