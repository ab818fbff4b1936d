#include "sim/drift.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

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

Drifts InvariantMonitor::no_drift() const {
  Drifts d;
  if (initial_.extra) d.extra = 0.0;
  return d;
}

void InvariantMonitor::worsen(Drifts& worst, const Sample& s) const {
  const Drifts d = relative_drift(at(s));
  auto keep = [](double& w, double v) {
    if (!(v <= w)) w = v;
  };  // NaN wins
  keep(worst.gamma_norm2, d.gamma_norm2);
  keep(worst.area, d.area);
  keep(worst.energy, d.energy);
  if (d.extra && worst.extra) keep(*worst.extra, *d.extra);
}

Drifts InvariantMonitor::max_relative_drift(const std::vector<Sample>& samples) const {
  Drifts worst = no_drift();
  for (const auto& s : samples) worsen(worst, s);
  return worst;
}

RunDriftMonitor::RunDriftMonitor(const RunSpec& spec)
    : monitor_(spec.body, spec.case_id, spec.initial) {
  drifts_.steps = drifts_.output = monitor_.no_drift();
}

MotionCheck::MotionCheck(const physics::Body& body, const physics::InitialState& initial,
                         double max_drift)
    : monitor_(body, physics::Case::custom, initial), max_drift_(max_drift) {}

namespace {

bool finite(const Sample& s) {
  return s.omega.allFinite() && s.gamma.allFinite() &&
         (!s.attitude || s.attitude->coeffs().allFinite());
}

}  // namespace

std::optional<numerics::Failure> MotionCheck::failure(const Sample& s,
                                                      std::string_view method) const {
  if (!finite(s)) [[unlikely]]
    return numerics::Failure{s.t, std::string(method), numerics::FailureKind::non_finite,
                             "omega or gamma not finite (NaN or Inf)"};
  const Drifts d = monitor_.relative_drift(monitor_.at(s));
  if (d.energy <= max_drift_ && d.gamma_norm2 <= max_drift_) [[likely]]
    return std::nullopt;
  // Finite numbers whose squares overflow: the run has blown up, whatever the limit.
  if (!std::isfinite(d.energy) || !std::isfinite(d.gamma_norm2))
    return numerics::Failure{s.t, std::string(method), numerics::FailureKind::non_finite,
                             "energy or |gamma|^2 not finite (omega or gamma overflows)"};
  // The larger of the two is the one the user hears of.
  const bool energy = !(d.energy < d.gamma_norm2);
  char detail[128];
  std::snprintf(detail, sizeof detail, "lost the motion: relative %s drift %.3g above the limit %g",
                energy ? "energy" : "|gamma|^2", energy ? d.energy : d.gamma_norm2, max_drift_);
  return numerics::Failure{s.t, std::string(method), numerics::FailureKind::lost_motion, detail};
}

}  // namespace epviz::sim
