#include "numerics/failure.hpp"

#include <cstdio>

namespace epviz::numerics {

std::string_view name(FailureKind kind) {
  switch (kind) {
    case FailureKind::non_finite: return "non_finite";
    case FailureKind::step_underflow: return "step_underflow";
    case FailureKind::step_budget: return "step_budget";
    case FailureKind::rejections: return "rejections";
    case FailureKind::solver_divergence: return "solver_divergence";
    case FailureKind::lost_motion: return "lost_motion";
    case FailureKind::chart_pole: return "chart_pole";
  }
  return "unknown";  // not reached: the switch lists every kind
}

std::string Failure::message() const {
  char when[64];
  std::snprintf(when, sizeof when, "%.10g", t);
  return method + " failed at t = " + when + ": " + detail;
}

IntegrationError::IntegrationError(Failure f)
    : std::runtime_error(f.message()), failure_(std::move(f)) {}

}  // namespace epviz::numerics
