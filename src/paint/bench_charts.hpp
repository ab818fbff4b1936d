#pragma once
// Charts of an `epviz bench` JSON document (as bench_command writes it),
// rendered with the chart painter and written as PNGs:
//   work_precision_<case>.png        error vs CPU time (log-log), a line per formulation x method (x impl)
//   work_precision_evals_<case>.png  error vs rhs evaluations (log-log)
//   drift_<case>.png                 relative drift of C1 and the fourth integral vs time (log y)
//   stability.png                    the stability_* rows as a table
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "paint/chart_painter.hpp"

namespace epviz::paint {

struct NamedChart {
  std::string file_name;  // e.g. "work_precision_euler.png"
  ChartSpec spec;
};

// The chart specs of a bench document, one per file, in a stable order.
std::vector<NamedChart> bench_chart_specs(const nlohmann::json& bench);
// The stability rows as a table (empty rows when there are none).
TableSpec bench_stability_table(const nlohmann::json& bench);

// Renders every chart and the table (when there are stability rows) into
// `out_dir` (created if missing), each file written atomically; returns the
// paths written. `gl_backend`: as render::make_gl_context takes it.
std::vector<std::filesystem::path> write_bench_charts(const nlohmann::json& bench,
                                                      const std::filesystem::path& out_dir,
                                                      const std::string& gl_backend,
                                                      const ChartOptions& options = {});

}  // namespace epviz::paint
