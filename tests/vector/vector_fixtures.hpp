#pragma once
// What the vector figure tests share: a chart, a heat map and a table whose
// labels use Greek letters, sub- and superscripts, and a way to run the
// poppler and librsvg tools on what they write.
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "chart/chart_spec.hpp"
#include "paint/figure_fixtures.hpp"

namespace epviz::testing {

// The paint tests' log-log chart of two series, its labels in Unicode.
inline chart::Figure unicode_chart() {
  chart::ChartSpec s = two_series();
  s.title = "Drift of γ over time";
  s.x_label = "time t / T₀";
  s.y_label = "|ΔΩ|² error";
  s.series[0].name = "rk4 (Ω₃ = 5)";
  return {"drift.png", s};
}

// A 3 x 4 grid of values, each cell with its value as text, one missing.
inline chart::Figure unicode_heat_map() {
  chart::HeatMapSpec s;
  s.title = "Largest stable step";
  s.x_label = "method";
  s.y_label = "ω₃";
  s.value_label = "h·Ω";
  s.rows = {"50", "5", "0.5"};
  s.columns = {"euler", "rk4", "gauss6", "dop853"};
  s.values = {{1e-3, 2e-2, 0.5, 0.1}, {3e-3, 5e-2, 0.9, std::nan("")}, {1e-2, 0.2, 2.0, 0.7}};
  return {"atlas.png", s};
}

inline chart::Figure unicode_table() {
  chart::TableSpec s;
  s.title = "Cost to reach γ error 1e-6";
  s.header = {"method", "γ error", "evals"};
  s.rows = {{"rk4", "8.1e-7", "12000"}, {"gauss6", "2.3e-7", "3400"}, {"dop853", "9.9e-7", "5100"}};
  return {"cost.png", s};
}

struct ToolRun {
  int exit_code = -1;
  std::string out;  // stdout and stderr
};
inline ToolRun run_tool(const std::string& command) {
  ToolRun r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return r;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) r.out.append(buf, n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}
inline bool have_tool(const std::string& name) {
  return run_tool("command -v " + name).exit_code == 0;
}

// Whether `file` is well-formed XML, as Python's parser reads it.
inline ToolRun parse_xml(const std::string& file) {
  return run_tool("python3 -c 'import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])' '" +
                  file + "'");
}

}  // namespace epviz::testing
