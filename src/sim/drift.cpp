#include "sim/drift.hpp"

#include <algorithm>
#include <cmath>

namespace epviz::sim {

InvariantMonitor::InvariantMonitor(const physics::Body& body, physics::Case c,
                                   const physics::InitialState& initial)
    : body_(body),
      case_(c),
      initial_(physics::invariants(body, c, initial.omega, initial.gamma)),
      scale_(physics::invariant_scales(body, c, initial.omega, initial.gamma)) {}

physics::Invariants InvariantMonitor::at(const Sample& s) const {
  return physics::invariants(body_, case_, s.omega, s.gamma);
}

Drifts InvariantMonitor::relative_drift(const physics::Invariants& now) const {
  auto rel = [](double v, double v0, double scale) { return std::abs(v - v0) / scale; };
  Drifts d;
  d.gamma_norm2 = rel(now.gamma_norm2, initial_.gamma_norm2, scale_.gamma_norm2);
  d.area = rel(now.area, initial_.area, scale_.area);
  d.energy = rel(now.energy, initial_.energy, scale_.energy);
  if (now.extra && initial_.extra && scale_.extra)
    d.extra = rel(*now.extra, *initial_.extra, *scale_.extra);
  return d;
}

Drifts InvariantMonitor::max_relative_drift(const std::vector<Sample>& samples) const {
  Drifts worst;
  if (initial_.extra) worst.extra = 0.0;
  for (const auto& s : samples) {
    const Drifts d = relative_drift(at(s));
    // NaN must win: a non-finite invariant is the worst drift there is.
    auto keep = [](double& w, double v) { if (!(v <= w)) w = v; };
    keep(worst.gamma_norm2, d.gamma_norm2);
    keep(worst.area, d.area);
    keep(worst.energy, d.energy);
    if (d.extra && worst.extra) keep(*worst.extra, *d.extra);
  }
  return worst;
}

}  // namespace epviz::sim
