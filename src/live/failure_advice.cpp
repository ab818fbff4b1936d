#include "live/failure_advice.hpp"

#include "sim/run_spec.hpp"

namespace epviz::live {

std::string failure_advice(numerics::FailureKind kind, bool adaptive) {
  using numerics::FailureKind;
  // The controls named here are those of the Integrator panel and the Case and body panel.
  const std::string where = " in the Integrator panel";
  const std::string adaptive_method(sim::name(sim::Method::dop853));
  switch (kind) {
    case FailureKind::non_finite:
      if (adaptive)
        return "check the initial state in the Case and body panel, or lower the tolerance" +
               where + ".";
      return "lower the step" + where + ", or pick an adaptive method (" + adaptive_method +
             ") there.";
    case FailureKind::step_underflow:
      if (adaptive)
        return "raise the tolerance" + where +
               "; if the solution truly blows up here, check the initial state.";
      return "raise the step" + where + ".";
    case FailureKind::rejections:
      if (adaptive)
        return "raise the tolerance" + where +
               "; if the solution truly blows up here, check the initial state.";
      return "lower the step" + where + ".";
    case FailureKind::step_budget:
      if (adaptive) return "raise the tolerance" + where + ".";
      return "raise the step" + where + ".";
    case FailureKind::solver_divergence:
      if (adaptive) return "lower the tolerance" + where + ".";
      return "lower the step" + where +
             ": the fixed-point iteration converges only for steps well below the motion's "
             "fastest time scale.";
    case FailureKind::lost_motion:
      if (adaptive) return "lower the tolerance" + where + ".";
      return "lower the step" + where + ", or pick an adaptive method (" + adaptive_method +
             ") there.";
    case FailureKind::chart_pole:
      return "pick the " + std::string(sim::name(sim::Formulation::spinor)) +
             " formulation, which has no pole, or tick chart switch" + where + ".";
  }
  return "change the settings" + where + ".";  // not reached: every kind is listed
}

std::string failure_line(const numerics::Failure& f, bool adaptive) {
  return f.message() + "; " + failure_advice(f.kind, adaptive);
}

}  // namespace epviz::live
