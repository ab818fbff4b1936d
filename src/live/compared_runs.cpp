#include "live/compared_runs.hpp"

#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include "live/live_setup.hpp"
#include "physics/cases.hpp"

namespace epviz::live {

ComparedRun with_method(sim::Method method, double step, double tol) {
  ComparedRun c;
  c.method = method;
  c.step = step;
  c.tol = tol;
  return c;
}

ComparedRun nudged_by(double angle) {
  ComparedRun c;
  c.nudge = angle;
  return c;
}

Eigen::Vector3d nudged_gamma(const Eigen::Vector3d& gamma, double angle) {
  // Any axis perpendicular to gamma: across e1, or across e2 when gamma lies along e1.
  Eigen::Vector3d axis = gamma.cross(Eigen::Vector3d::UnitX());
  if (axis.norm() < 1e-3 * gamma.norm()) axis = gamma.cross(Eigen::Vector3d::UnitY());
  return Eigen::AngleAxisd(angle, axis.normalized()) * gamma;
}

sim::RunSpec compared_spec(const sim::RunSpec& first, const ComparedRun& c) {
  if (c.given) return c.given->run;
  sim::RunSpec run = first;
  if (c.method) {
    run.method = *c.method;
    if (sim::is_adaptive(run.method))
      run.tol = c.tol;
    else
      run.step = c.step;
  }
  if (c.nudge != 0.0) {
    run.initial.gamma = nudged_gamma(first.initial.gamma, c.nudge);
    if (physics::broken_condition(run.case_id, run.body, run.initial))
      run.case_id = physics::Case::custom;
  }
  return run;
}

std::string compared_label(const ComparedRun& c) {
  if (c.given) return c.given->label;
  if (c.nudge == 0.0) return "";
  char text[48];
  std::snprintf(text, sizeof text, "nudged %.3g", c.nudge);
  return text;
}

std::vector<scene::RunRequest> run_requests(const LiveSetup& setup) {
  const auto& s = setup.scene;
  std::vector<scene::RunRequest> runs{
      {setup.run, setup.label, s.formulation_given, s.auto_tolerance}};
  for (const auto& c : setup.compared) {
    if (c.given) {
      runs.push_back(*c.given);
      continue;
    }
    // Another method's accuracy is its own; a nudged run's is the first run's.
    const bool auto_tolerance = !c.method && s.auto_tolerance;
    runs.push_back(
        {compared_spec(setup.run, c), compared_label(c), s.formulation_given, auto_tolerance});
  }
  return runs;
}

}  // namespace epviz::live
