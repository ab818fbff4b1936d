#include "app/failure_advice.hpp"

#include "sim/run_spec.hpp"

namespace epviz::app {
namespace {

// How the user names each setting the advice may mention.
struct Words {
  std::string tol, step, t_end, max_drift;
  std::string method_prefix, formulation_prefix;  // followed by the quoted value
  std::string chart_switch_on;
  std::string method(std::string_view m) const { return method_prefix + std::string(m); }
  std::string formulation(std::string_view f) const { return formulation_prefix + std::string(f); }
};

Words words_for(SettingsIn where) {
  switch (where) {
    case SettingsIn::command_line:
      return {"--tol",
              "--step",
              "--t-end",
              "--max-drift",
              "--method ",
              "--formulation ",
              "drop --no-chart-switch"};
    case SettingsIn::render_job:
      return {"simulation.tol",
              "simulation.step",
              "simulation.t_end",
              "simulation.max_drift",
              "simulation.method ",
              "simulation.formulation ",
              "simulation.chart_switch true"};
  }
  return words_for(SettingsIn::command_line);  // not reached: every value is listed
}

// The adaptive method to suggest in place of a fixed-step one, and the
// formulation without a pole.
std::string_view suggested_adaptive() { return sim::name(sim::Method::dop853); }
std::string_view pole_free() { return sim::name(sim::Formulation::spinor); }

}  // namespace

std::string failure_advice(numerics::FailureKind kind, std::string_view method, bool adaptive,
                           SettingsIn where) {
  using numerics::FailureKind;
  const Words w = words_for(where);
  switch (kind) {
    case FailureKind::non_finite:
      if (adaptive)
        return "check the initial state; if it is sound, tighten " + w.tol +
               " so that the steps follow the solution.";
      return "use a smaller " + w.step + ", or an adaptive method (" +
             w.method(suggested_adaptive()) + ") that shortens its steps where the motion is fast.";
    case FailureKind::step_underflow:
      if (adaptive)
        return "loosen " + w.tol +
               "; if the solution truly blows up here, check the initial state.";
      return "use a larger " + w.step + ".";
    case FailureKind::step_budget:
      if (adaptive) {
        std::string s = "loosen " + w.tol + " or shorten " + w.t_end;
        if (method != suggested_adaptive())
          s += ", or use " + w.method(suggested_adaptive()) +
               ", which needs fewer steps at tight tolerances";
        return s + ".";
      }
      return "use a larger " + w.step + " or shorten " + w.t_end + ".";
    case FailureKind::rejections:
      if (adaptive)
        return "loosen " + w.tol +
               "; if the solution truly blows up here, check the initial state.";
      return "use a smaller " + w.step + ".";
    case FailureKind::solver_divergence:
      if (adaptive)
        return "tighten " + w.tol +
               " so that the steps stay below the motion's fastest time scale.";
      return "use a smaller " + w.step +
             ": the fixed-point iteration converges only for steps well below the motion's "
             "fastest time scale.";
    case FailureKind::lost_motion:
      // Raising the limit is for those who want to watch a run go wrong.
      if (adaptive)
        return "tighten " + w.tol + ", or accept more drift with a larger " + w.max_drift + ".";
      return "use a smaller " + w.step + " or an adaptive method (" +
             w.method(suggested_adaptive()) + "), or accept more drift with a larger " +
             w.max_drift + ".";
    case FailureKind::chart_pole:
      return "use " + w.formulation(pole_free()) +
             ", which has no pole, or leave chart switching on (" + w.chart_switch_on + ").";
  }
  return "check the run's settings.";  // not reached: every kind is listed
}

std::string failure_line(const numerics::Failure& f, SettingsIn where) {
  const auto m = sim::method_from_name(f.method);
  const bool adaptive = m && sim::is_adaptive(*m);
  return f.message() + "; " + failure_advice(f.kind, f.method, adaptive, where);
}

}  // namespace epviz::app
