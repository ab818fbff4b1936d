#pragma once
// How an integrator says that it cannot go on. Every stepper throws
// IntegrationError instead of returning a state it does not trust.
//
// A Failure is data: what kind of trouble, where, and the plain fact found.
// What the user should do about it depends on what the user can change (a
// command-line option, a control in a panel), so the advice is worded with
// each front end's settings (sim/failure_advice), never here.
#include <array>
#include <stdexcept>
#include <string>
#include <string_view>

namespace epviz::numerics {

enum class FailureKind {
  non_finite,         // the state or its derivative became NaN or Inf
  step_underflow,     // the adaptive step shrank below the round-off limit of t
  step_budget,        // more steps than the stepper may take
  rejections,         // too many rejected steps in a row
  solver_divergence,  // the implicit stage equations did not converge
  lost_motion,        // finite, but too far from the true motion to be trusted
  chart_pole,         // the state reached a pole of its chart (e.g. Riccati)
};

// Every kind, for tests and listings (keep in step with the enum).
inline constexpr std::array<FailureKind, 7> kFailureKinds{
    FailureKind::non_finite, FailureKind::step_underflow,    FailureKind::step_budget,
    FailureKind::rejections, FailureKind::solver_divergence, FailureKind::lost_motion,
    FailureKind::chart_pole,
};

// Stable snake_case identifier ("step_underflow"), e.g. for JSON reports.
std::string_view name(FailureKind kind);

struct Failure {
  double t = 0.0;      // time at which the failure was detected
  std::string method;  // e.g. "dop853"
  FailureKind kind = FailureKind::non_finite;
  std::string detail;  // the fact, no advice: "step size 3e-17 below the round-off limit"

  // "dop853 failed at t = 1.2345: <detail>" (the front ends append their advice).
  std::string message() const;
};

class IntegrationError : public std::runtime_error {
 public:
  explicit IntegrationError(Failure f);
  const Failure& failure() const noexcept { return failure_; }

 private:
  Failure failure_;
};

}  // namespace epviz::numerics
