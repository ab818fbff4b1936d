#include "sim/failure_advice.hpp"

#include "sim/run_spec.hpp"

namespace epviz::sim {
namespace {

// How the user names each setting the advice may mention. An empty name is a
// setting that front end does not have (the panel has no end time): the
// advice leaves that remedy out.
struct Words {
  std::string tol;   // follows "tighten" / "loosen"
  std::string step;  // follows "a smaller" / "a larger"
  std::string t_end, max_drift;
  std::string method_before, method_after;  // around a method's name
  std::string formulation_before, formulation_after;
  std::string chart_switch_on;
  std::string initial_state;
  std::string method(std::string_view m) const {
    return method_before + std::string(m) + method_after;
  }
  std::string formulation(std::string_view f) const {
    return formulation_before + std::string(f) + formulation_after;
  }
};

Words words_for(SettingsIn where) {
  switch (where) {
    case SettingsIn::command_line:
      return {"--tol",
              "--step",
              "--t-end",
              "--max-drift",
              "--method ",
              "",
              "--formulation ",
              "",
              "drop --no-chart-switch",
              "the initial state"};
    case SettingsIn::render_job:
      return {"simulation.tol",
              "simulation.step",
              "simulation.t_end",
              "simulation.max_drift",
              "simulation.method ",
              "",
              "simulation.formulation ",
              "",
              "simulation.chart_switch true",
              "the initial state"};
    case SettingsIn::python:
      return {"tol", "step",           "t_end", "max_drift",         "method=\"",
              "\"",  "formulation=\"", "\"",    "chart_switch=True", "the initial state"};
    case SettingsIn::panel: {
      const std::string in = " in the Integrator panel";
      return {"the tolerance" + in,
              "step" + in,
              "",
              "",
              "",
              " in the method list",
              "the ",
              " formulation",
              "tick chart switch" + in,
              "the initial state in the Case and body panel"};
    }
  }
  return words_for(SettingsIn::command_line);  // not reached: every value is listed
}

// " or <verb> <setting>" where the front end has the setting, else "".
std::string or_also(std::string_view joint, std::string_view verb, const std::string& setting) {
  if (setting.empty()) return "";
  return std::string(joint) + std::string(verb) + setting;
}

// The adaptive method to suggest in place of a fixed-step one, and the
// formulation without a pole.
std::string_view suggested_adaptive() { return name(Method::dop853); }
std::string_view pole_free() { return name(Formulation::spinor); }

}  // namespace

std::string failure_advice(numerics::FailureKind kind, std::string_view method, bool adaptive,
                           SettingsIn where) {
  using numerics::FailureKind;
  const Words w = words_for(where);
  const std::string more_drift = or_also(", or accept more drift with ", "a larger ", w.max_drift);
  switch (kind) {
    case FailureKind::non_finite:
      if (adaptive)
        return "check " + w.initial_state + "; if it is sound, tighten " + w.tol +
               " so that the method's steps follow the solution.";
      return "use a smaller " + w.step + ", or an adaptive method (" +
             w.method(suggested_adaptive()) + ") that shortens its steps where the motion is fast.";
    case FailureKind::step_underflow:
    case FailureKind::rejections:
      if (adaptive)
        return "loosen " + w.tol + "; if the solution truly blows up here, check " +
               w.initial_state + ".";
      return kind == FailureKind::rejections ? "use a smaller " + w.step + "."
                                             : "use a larger " + w.step + ".";
    case FailureKind::step_budget:
      if (adaptive) {
        std::string s = "loosen " + w.tol + or_also(" or ", "shorten ", w.t_end);
        if (method != suggested_adaptive())
          s += ", or use " + w.method(suggested_adaptive()) +
               ", which needs fewer steps at tight tolerances";
        return s + ".";
      }
      return "use a larger " + w.step + or_also(" or ", "shorten ", w.t_end) + ".";
    case FailureKind::solver_divergence:
      if (adaptive)
        return "tighten " + w.tol +
               " so that the method's steps stay below the motion's fastest time scale.";
      return "use a smaller " + w.step +
             ": the fixed-point iteration converges only for steps well below the motion's "
             "fastest time scale.";
    case FailureKind::lost_motion:
      // Raising the limit is for those who want to watch a run go wrong.
      if (adaptive) return "tighten " + w.tol + more_drift + ".";
      return "use a smaller " + w.step + " or an adaptive method (" +
             w.method(suggested_adaptive()) + ")" + more_drift + ".";
    case FailureKind::chart_pole:
      return "use " + w.formulation(pole_free()) +
             ", which has no pole, or leave chart switching on (" + w.chart_switch_on + ").";
  }
  return "check the run's settings.";  // not reached: every kind is listed
}

std::string failure_line(const numerics::Failure& f, SettingsIn where) {
  const auto m = method_from_name(f.method);
  const bool adaptive = m && is_adaptive(*m);
  return f.message() + "; " + failure_advice(f.kind, f.method, adaptive, where);
}

}  // namespace epviz::sim
