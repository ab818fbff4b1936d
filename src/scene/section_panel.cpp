#include "scene/section_panel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "physics/format.hpp"

namespace epviz::scene {
namespace {

Eigen::Vector2d plotted(const sim::Crossing& c, const std::array<sim::StateComponent, 2>& coords) {
  return {sim::value_of(coords[0], c.omega, c.gamma), sim::value_of(coords[1], c.omega, c.gamma)};
}

// [lo, hi] widened by 8 % of its span on each side, so that no dot sits on
// the frame; a span of (nearly) nothing gets a unit's width about its centre.
void pad(double& lo, double& hi) {
  const double span = hi - lo;
  if (!(span > 1e-9 * std::max(1.0, std::abs(lo) + std::abs(hi)))) {
    const double mid = 0.5 * (lo + hi);
    lo = mid - 0.5;
    hi = mid + 0.5;
    return;
  }
  lo -= 0.08 * span;
  hi += 0.08 * span;
}

}  // namespace

std::string section_title(const sim::SectionSurface& surface) {
  std::string s(sim::symbol(surface.function));
  s += " = ";
  s += physics::detail::num(surface.value);
  s += ", ";
  s += sim::name(surface.direction);
  return s;
}

SectionCrossings::SectionCrossings(const SectionPanelSettings& settings,
                                   std::vector<std::vector<sim::Crossing>> crossings)
    : settings_(settings), crossings_(std::move(crossings)) {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const auto& run : crossings_) {
    for (const auto& c : run) {
      const Eigen::Vector2d p = plotted(c, settings.coords);
      for (int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
  }
  for (int k = 0; k < 2; ++k) {
    if (!(lo[k] <= hi[k])) lo[k] = hi[k] = 0.0;  // no crossing at all
    pad(lo[k], hi[k]);
    range_[std::size_t(2 * k)] = lo[k];
    range_[std::size_t(2 * k + 1)] = hi[k];
  }
}

SectionPanel SectionCrossings::panel_at(double t, const std::vector<Rgba>& colours) const {
  SectionPanel p;
  p.title = section_title(settings_.surface);
  p.axes = {std::string(sim::symbol(settings_.coords[0])),
            std::string(sim::symbol(settings_.coords[1]))};
  p.range = range_;
  p.colours = colours;
  for (const auto& run : crossings_) {
    auto& dots = p.runs.emplace_back();
    for (const auto& c : run) {
      if (c.t > t) break;  // in time order
      dots.push_back(plotted(c, settings_.coords));
    }
  }
  return p;
}

}  // namespace epviz::scene
