#include "section/section_chart.hpp"

#include <charconv>

#include "physics/cases.hpp"

namespace epviz::section {
namespace {

std::string short_number(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 6);
  return std::string(buf, r.ptr);
}

std::string title(const SectionJob& job) {
  std::string t = "Poincaré section, ";
  t += physics::preset(job.case_id).title;
  t += ": ";
  t += sim::symbol(job.surface.function);
  t += " = ";
  t += short_number(job.surface.value);
  t += " ";
  t += sim::name(job.surface.direction);
  if (job.level) {
    t += ", C₁ = ";
    t += short_number(job.level->energy);
    t += ", C₀ = ";
    t += short_number(job.level->area);
  }
  t += " (";
  t += sim::name(job.method);
  t += sim::is_adaptive(job.method) ? ", tol " : ", step ";
  t += short_number(sim::is_adaptive(job.method) ? job.tol : job.step);
  t += ")";
  return t;
}

}  // namespace

chart::ChartSpec section_chart(const SectionJob& job, const std::vector<OrbitResult>& orbits) {
  chart::ChartSpec spec;
  spec.title = title(job);
  spec.x_label = sim::symbol(job.coords[0]);
  spec.y_label = sim::symbol(job.coords[1]);
  // The chart painter joins a series' points by lines and marks only short
  // series at every point, so each crossing is a series of one point, its
  // colour keyed by its orbit; the legend is one row for all of them.
  for (const auto& o : orbits) {
    if (o.failure) continue;
    for (const auto& c : o.crossings) {
      chart::ChartSeries s;
      s.points.push_back({sim::value_of(job.coords[0], c.omega, c.gamma),
                          sim::value_of(job.coords[1], c.omega, c.gamma)});
      s.colour_key = o.orbit - 1;
      s.marker_key = 0;
      spec.series.push_back(std::move(s));
    }
  }
  std::string legend = "crossings, one colour per orbit (";
  legend += std::to_string(orbits.size());
  legend += " orbits)";
  spec.marker_legend.push_back({legend, 0});
  return spec;
}

}  // namespace epviz::section
