#include "section/section_chart.hpp"

#include <charconv>

#include "physics/cases.hpp"
#include "physics/notation.hpp"

namespace epviz::section {
namespace {

std::string chart_number(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 6);
  return std::string(buf, r.ptr);
}

std::string title(const SectionJob& job, const SectionMethod& m) {
  std::string t = "Poincaré section, ";
  t += physics::preset(job.case_id).title;
  t += ": ";
  t += sim::symbol(job.surface.function);
  t += " = ";
  t += chart_number(job.surface.value);
  t += " ";
  t += sim::name(job.surface.direction);
  if (job.level) {
    t += ", ";
    t += physics::symbol::energy;
    t += " = ";
    t += chart_number(job.level->energy);
    t += ", ";
    t += physics::symbol::area;
    t += " = ";
    t += chart_number(job.level->area);
  }
  t += " (";
  t += sim::name(m.method);
  t += sim::is_adaptive(m.method) ? ", tol " : ", step ";
  t += chart_number(sim::is_adaptive(m.method) ? m.tol : m.step);
  t += ")";
  return t;
}

}  // namespace

std::vector<chart::ChartSpec> section_charts(const SectionJob& job,
                                             const std::vector<OrbitResult>& orbits) {
  std::vector<chart::ChartSpec> charts(job.methods.size());
  std::vector<long> runs(job.methods.size(), 0);
  for (std::size_t m = 0; m < charts.size(); ++m) {
    charts[m].title = title(job, job.methods[m]);
    charts[m].x_label = sim::symbol(job.coords[0]);
    charts[m].y_label = sim::symbol(job.coords[1]);
  }
  // Every chart's axes take in every crossing of every method.
  std::vector<chart::ChartPoint> extent;
  // An orbit is a scatter of small dots (the painter's `markers` style:
  // every point, no line), its colour keyed by its orbit; the legend is one
  // row for all of them.
  for (const auto& o : orbits) {
    ++runs[o.method];
    if (o.failure) continue;
    chart::ChartSeries s;
    s.style = chart::SeriesStyle::markers;
    s.marker_size = chart::MarkerSize::dot;
    s.colour_key = o.orbit - 1;
    s.marker_key = 0;
    s.points.reserve(o.crossings.size());
    for (const auto& c : o.crossings)
      s.points.push_back({sim::value_of(job.coords[0], c.omega, c.gamma),
                          sim::value_of(job.coords[1], c.omega, c.gamma)});
    if (charts.size() > 1) extent.insert(extent.end(), s.points.begin(), s.points.end());
    charts[o.method].series.push_back(std::move(s));
  }
  for (std::size_t m = 0; m < charts.size(); ++m) {
    std::string legend = "crossings, one colour per orbit (";
    legend += std::to_string(runs[m]);
    legend += " orbits)";
    charts[m].marker_legend.push_back({legend, 0});
    if (charts.size() > 1) charts[m].axis_extent = extent;
  }
  return charts;
}

}  // namespace epviz::section
