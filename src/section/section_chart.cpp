#include "section/section_chart.hpp"

#include <charconv>
#include <optional>
#include <string>

#include "physics/cases.hpp"
#include "physics/notation.hpp"
#include "section/sheet_fold.hpp"

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
  t += sim::surface_function_symbol(job.surface);
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

namespace {

// One panel of the picture: a method's crossings, on one sheet or on both.
struct Panel {
  std::size_t method = 0;
  std::optional<SheetChoice::Show> side;  // none: every crossing
};

std::vector<Panel> panels_of(const SectionJob& job) {
  std::vector<Panel> panels;
  for (std::size_t m = 0; m < job.methods.size(); ++m) {
    if (!job.sheet) {
      panels.push_back({m, std::nullopt});
    } else if (job.sheet->show == SheetChoice::Show::both_apart) {
      panels.push_back({m, SheetChoice::Show::positive});
      panels.push_back({m, SheetChoice::Show::negative});
    } else {
      panels.push_back({m, job.sheet->show});
    }
  }
  return panels;
}

bool on_side(const SectionJob& job, const Panel& p, const sim::Crossing& c) {
  if (!p.side) return true;
  const double v = sim::value_of(job.sheet->component, c.omega, c.gamma);
  return *p.side == SheetChoice::Show::positive ? v > 0.0 : v < 0.0;
}

std::string sheet_label(const SectionJob& job, const Panel& p) {
  if (!p.side) return "";
  std::string t = ", ";
  t += sim::symbol(job.sheet->component);
  t += *p.side == SheetChoice::Show::positive ? " > 0" : " < 0";
  return t;
}

// The crossing at the plot's two coordinates; none where one is undefined
// (an Andoyer angle on its singular set).
std::optional<chart::ChartPoint> point_of(const SectionJob& job, const sim::Crossing& c) {
  const auto x = value_of(job.coords[0], job.body, c.omega, c.gamma);
  const auto y = value_of(job.coords[1], job.body, c.omega, c.gamma);
  if (!x || !y) return std::nullopt;
  return chart::ChartPoint{*x, *y};
}

// The panel's crossings as plotted, with their states, for measure_folds.
std::vector<PlottedCrossing> plotted(const SectionJob& job, const Panel& p,
                                     const std::vector<OrbitResult>& orbits) {
  std::vector<PlottedCrossing> out;
  for (const auto& o : orbits) {
    if (o.method != p.method || o.failure) continue;
    for (const auto& c : o.crossings) {
      if (!on_side(job, p, c)) continue;
      const auto at = point_of(job, c);
      if (!at) continue;
      out.push_back(
          {at->x,
           at->y,
           {c.omega.x(), c.omega.y(), c.omega.z(), c.gamma.x(), c.gamma.y(), c.gamma.z()}});
    }
  }
  return out;
}

std::string fold_text(const FoldMeasure& f) {
  return std::to_string(f.far_pairs) + " of " + std::to_string(f.close_pairs) +
         " pairs of crossings close in the plot are far apart in state";
}

}  // namespace

std::vector<chart::ChartSpec> section_charts(const SectionJob& job,
                                             const std::vector<OrbitResult>& orbits) {
  const std::vector<Panel> panels = panels_of(job);
  std::vector<chart::ChartSpec> charts(panels.size());
  std::vector<long> runs(job.methods.size(), 0);
  for (const auto& o : orbits) ++runs[o.method];
  // Every chart's axes take in every crossing of every panel.
  std::vector<chart::ChartPoint> extent;
  for (std::size_t n = 0; n < panels.size(); ++n) {
    const Panel& p = panels[n];
    chart::ChartSpec& chart = charts[n];
    chart.title = title(job, job.methods[p.method]) + sheet_label(job, p);
    // Said on the picture itself, not only by the command: a figure that
    // folds two sheets shows crossings of orbits that do not cross.
    const FoldMeasure folds = measure_folds(plotted(job, p, orbits));
    if (folds.far_pairs > 0)
      chart.title += "; two sheets folded (" + std::to_string(folds.far_pairs) + " of " +
                     std::to_string(folds.close_pairs) + " close pairs)";
    chart.x_label = symbol(job.coords[0]);
    chart.y_label = symbol(job.coords[1]);
    long undefined = 0;  // crossings with a coordinate undefined there: not drawn, counted
    // An orbit is a scatter of small dots (the painter's `markers` style:
    // every point, no line), its colour keyed by its orbit; the legend is one
    // row for all of them.
    for (const auto& o : orbits) {
      if (o.method != p.method || o.failure) continue;
      chart::ChartSeries s;
      s.style = chart::SeriesStyle::markers;
      s.marker_size = chart::MarkerSize::dot;
      s.colour_key = o.orbit - 1;
      s.marker_key = 0;
      s.points.reserve(o.crossings.size());
      for (const auto& c : o.crossings) {
        if (!on_side(job, p, c)) continue;
        if (const auto at = point_of(job, c))
          s.points.push_back(*at);
        else
          ++undefined;
      }
      if (panels.size() > 1) extent.insert(extent.end(), s.points.begin(), s.points.end());
      chart.series.push_back(std::move(s));
    }
    std::string legend = "crossings, one colour per orbit (";
    legend += std::to_string(runs[p.method]);
    legend += " orbits)";
    if (undefined > 0)
      legend +=
          "; " + std::to_string(undefined) + " on the Andoyer variables' singular set, not drawn";
    chart.marker_legend.push_back({legend, 0});
  }
  if (panels.size() > 1)
    for (auto& chart : charts) chart.axis_extent = extent;
  return charts;
}

std::vector<std::string> fold_warnings(const SectionJob& job,
                                       const std::vector<OrbitResult>& orbits) {
  std::vector<std::string> warnings;
  for (const Panel& p : panels_of(job)) {
    const FoldMeasure folds = measure_folds(plotted(job, p, orbits));
    if (folds.far_pairs == 0) continue;
    std::string w = job.file + ": the picture";
    if (job.methods.size() > 1) w += " of " + method_label(job.methods[p.method]);
    w += sheet_label(job, p);
    w += " folds two sheets of the surface onto one plane (";
    w += fold_text(folds);
    w += "); give \"sheets\" or \"sheet\" (docs/sections.md, \"Sheets\")";
    warnings.push_back(std::move(w));
  }
  return warnings;
}

}  // namespace epviz::section
