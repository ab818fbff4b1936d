#include "app/diagram_figure.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include "physics/notation.hpp"

namespace epviz::app {
namespace {

std::string diagram_number(double x, int digits) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, digits);
  return std::string(buf, r.ptr);
}

// Grey for the sampled states; the curves in colours that stand apart on it
// and from each other (paint's palette: vermillion, blue, bluish green,
// reddish purple, near black, wine).
constexpr int kDotsColour = 12;
constexpr std::array<int, 6> kCurveColours{1, 0, 2, 3, 6, 7};
constexpr int kRegionColour = 6;  // near black: the regions' points

chart::ChartSeries dot_series(int colour) {
  chart::ChartSeries s;
  s.style = chart::SeriesStyle::markers;
  s.marker_size = chart::MarkerSize::dot;
  s.colour_key = colour;
  s.marker_key = 0;
  return s;
}

// The span of the values the chart shows, to space a trace's dots by.
struct Extent {
  double dx = 1.0, dy = 1.0;
};
Extent diagram_extent(const physics::BifurcationDiagram& d) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  const auto take = [&](const physics::ValuePoint& p) {
    if (!std::isfinite(p.energy) || !std::isfinite(p.integral)) return;
    x0 = std::min(x0, p.energy), x1 = std::max(x1, p.energy);
    y0 = std::min(y0, p.integral), y1 = std::max(y1, p.integral);
  };
  for (const auto& p : d.sampled) take(p);
  for (const auto& c : d.curves)
    for (const auto& p : c.points) take(p);
  if (!(x1 > x0) || !(y1 > y0)) return {};
  return {x1 - x0, y1 - y0};
}

// The painter draws every marker over every line, so a curve through the
// cloud of sampled dots would vanish under them: the curve is drawn a second
// time as dots of its colour, spaced a thousandth of the chart's span apart
// (under a pixel on the figure), which lie over the grey ones.
chart::ChartSeries trace_over_dots(const chart::ChartSeries& line, int colour, Extent e) {
  chart::ChartSeries trace = dot_series(colour);
  const auto& p = line.points;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!std::isfinite(p[i].x)) continue;
    if (i + 1 == p.size() || !std::isfinite(p[i + 1].x)) {
      trace.points.push_back(p[i]);  // the end of an attained part
      continue;
    }
    const double dx = (p[i + 1].x - p[i].x) / e.dx, dy = (p[i + 1].y - p[i].y) / e.dy;
    const int steps = std::max(1, int(std::ceil(std::hypot(dx, dy) * 1000.0)));
    for (int k = 0; k < steps; ++k) {
      const double t = double(k) / steps;
      trace.points.push_back(
          {p[i].x + t * (p[i + 1].x - p[i].x), p[i].y + t * (p[i + 1].y - p[i].y)});
    }
  }
  return trace;
}

// A region's label as straight strokes in a box 2% of the chart's width
// wide and 3% of its height high, up and to the right of its point (to the
// left where that would pass the largest energy shown), as a line
// series (NaN points lift the pen); the chart has no text of its own to
// place there. Labels past N are named in no letter (the legend still
// counts them).
chart::ChartSeries region_letter(const DiagramRegion& region, Extent e, double energy_max) {
  static const std::array<const char*, 14> strokes{
      "0,0 5,10 10,0|2.5,5 7.5,5",                          // A
      "0,0 0,10 7,10 10,8 7,5.5 0,5.5|7,5.5 10,3 7,0 0,0",  // B
      "10,10 0,10 0,0 10,0",                                // C
      "0,0 0,10 6,10 10,7 10,3 6,0 0,0",                    // D
      "10,10 0,10 0,0 10,0|0,5 7,5",                        // E
      "10,10 0,10 0,0|0,5 7,5",                             // F
      "10,10 0,10 0,0 10,0 10,5 5,5",                       // G
      "0,0 0,10|10,0 10,10|0,5 10,5",                       // H
      "5,0 5,10|2,10 8,10|2,0 8,0",                         // I
      "2,10 10,10 10,0 0,0 0,3",                            // J
      "0,0 0,10|10,10 0,5 10,0",                            // K
      "0,10 0,0 10,0",                                      // L
      "0,0 0,10 5,5 10,10 10,0",                            // M
      "0,0 0,10 10,0 10,10",                                // N
  };
  chart::ChartSeries s;
  if (region.label.size() != 1 || region.label[0] < 'A' ||
      std::size_t(region.label[0] - 'A') >= strokes.size())
    return s;
  const bool left = region.point.energy + 0.035 * e.dx > energy_max;
  const double x0 = region.point.energy + (left ? -0.032 : 0.012) * e.dx;
  const double y0 = region.point.integral + 0.012 * e.dy;
  const double sx = 0.002 * e.dx, sy = 0.003 * e.dy;  // per tenth of the box
  const std::string text = strokes[std::size_t(region.label[0] - 'A')];
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == '|') {
      s.points.push_back({NAN, NAN});
      ++i;
      continue;
    }
    if (text[i] == ' ') {
      ++i;
      continue;
    }
    double x = 0, y = 0;
    const auto rx = std::from_chars(text.data() + i, text.data() + text.size(), x);
    const auto ry = std::from_chars(rx.ptr + 1, text.data() + text.size(), y);
    i = std::size_t(ry.ptr - text.data());
    s.points.push_back({x0 + sx * x, y0 + sy * y});
  }
  return s;
}

}  // namespace

chart::Figure diagram_figure(const physics::DiagramRequest& request,
                             const physics::BifurcationDiagram& diagram,
                             const std::vector<DiagramRegion>& regions) {
  chart::ChartSpec c;
  c.title = "Bifurcation diagram, ";
  c.title += physics::preset(request.case_id).title;
  c.title += ", ";
  c.title += physics::symbol::area;
  c.title += " = ";
  c.title += diagram_number(request.area, 6);
  c.x_label = physics::symbol::energy;
  c.y_label = physics::integral_symbol(request.case_id);
  // A row per colour: the dots' grey, then each curve's.
  std::string dots_name = "sampled states of the level (";
  dots_name += std::to_string(diagram.sampled.size());
  dots_name += ", one point per orbit)";
  c.colour_legend.push_back({dots_name, kDotsColour});
  chart::ChartSeries dots = dot_series(kDotsColour);
  for (const auto& p : diagram.sampled) dots.points.push_back({p.energy, p.integral});
  c.series.push_back(std::move(dots));
  const Extent extent = diagram_extent(diagram);
  for (std::size_t i = 0; i < diagram.curves.size(); ++i) {
    const auto& curve = diagram.curves[i];
    if (curve.points.empty()) continue;
    const int colour = kCurveColours[i % kCurveColours.size()];
    c.colour_legend.push_back({curve.label, colour});
    chart::ChartSeries s;
    s.colour_key = colour;
    s.marker_key = 0;
    s.style = curve.isolated ? chart::SeriesStyle::markers : chart::SeriesStyle::line;
    for (const auto& p : curve.points) s.points.push_back({p.energy, p.integral});
    if (!curve.isolated) c.series.push_back(trace_over_dots(s, colour, extent));
    c.series.push_back(std::move(s));
  }
  // The regions' points last, over everything, each with its letter.
  for (const auto& region : regions) {
    chart::ChartSeries m;
    m.style = chart::SeriesStyle::markers;
    m.colour_key = kRegionColour;
    m.marker_key = 0;
    m.points.push_back({region.point.energy, region.point.integral});
    c.series.push_back(std::move(m));
    chart::ChartSeries letter = region_letter(region, extent, diagram.energy_max);
    if (!letter.points.empty()) c.series.push_back(trace_over_dots(letter, kRegionColour, extent));
  }
  if (!regions.empty()) {
    std::string name = "region ";
    name += regions.front().label;
    if (regions.size() > 1) name += " to " + regions.back().label;
    name += ": the point whose level section_<region> shows";
    c.colour_legend.push_back({name, kRegionColour});
  }
  return {"diagram.png", std::move(c)};
}

std::string critical_curves_csv(const physics::BifurcationDiagram& diagram) {
  std::string text = "curve,energy,integral\n";
  for (const auto& curve : diagram.curves)
    for (const auto& p : curve.points) {
      if (!std::isfinite(p.energy)) continue;
      text += curve.id;
      text += ",";
      text += diagram_number(p.energy, 17);
      text += ",";
      text += diagram_number(p.integral, 17);
      text += "\n";
    }
  return text;
}

std::string regions_csv(const std::vector<DiagramRegion>& regions) {
  std::string text = "region,energy,integral,clearance,samples\n";
  for (const auto& r : regions) {
    text += r.label + "," + diagram_number(r.point.energy, 17) + "," +
            diagram_number(r.point.integral, 17) + "," + diagram_number(r.clearance, 6) + "," +
            std::to_string(r.samples) + "\n";
  }
  return text;
}

std::string sampled_values_csv(const physics::BifurcationDiagram& diagram) {
  std::string text = "energy,integral\n";
  for (const auto& p : diagram.sampled) {
    text += diagram_number(p.energy, 17);
    text += ",";
    text += diagram_number(p.integral, 17);
    text += "\n";
  }
  return text;
}

}  // namespace epviz::app
