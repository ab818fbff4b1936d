#include "live/job_file.hpp"

#include <algorithm>

#include "job/schema.hpp"
#include "scene/plan.hpp"

namespace epviz::live {
namespace {

std::array<double, 3> vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// The horizon LiveScene plans an open-ended run's automatic tolerance for
// (live_scene.cpp, kToleranceHorizon): the two must agree, which
// job_file_moment_test checks against the live scene's own note.
constexpr double kLiveToleranceHorizon = 1e4;

}  // namespace

std::optional<double> live_tolerance(const LiveSetup& setup) {
  if (!sim::is_adaptive(setup.run.method) || !setup.scene.auto_tolerance) return std::nullopt;
  sim::RunSpec run = setup.run;
  run.t_end = std::max(run.t_end, kLiveToleranceHorizon);
  return scene::plan_scene(run, setup.scene, scene::Horizon::none).run.tol;
}

job::JobDocument job_document(const LiveSetup& setup, const std::string& name,
                              const LiveMoment& moment, double duration_s) {
  const auto& run = setup.run;
  const std::string from = "the live setup";
  job::JobDocument d;
  auto& sim = d.simulation;
  if (run.case_id != physics::Case::custom)
    sim.case_name.set(physics::case_name(run.case_id), from);
  sim.inertia.set(vec(run.body.inertia), from);
  sim.com.set(vec(run.body.com), from);
  sim.weight.set(run.body.weight, from);
  sim.omega.set(vec(run.initial.omega), from);
  sim.gamma.set(vec(run.initial.gamma), from);
  sim.formulation.set(std::string(sim::name(run.formulation)), from);
  sim.method.set(std::string(sim::name(run.method)), from);
  // The tolerance the live run uses, as a number: "auto" would be chosen
  // again for the job's shorter run, looser than what was seen.
  if (!sim::is_adaptive(run.method))
    sim.step.set(run.step, from);
  else
    sim.tol.set(moment.tolerance.value_or(run.tol), from);
  if (run.formulation == sim::Formulation::riccati) sim.chart_switch.set(run.chart_switch, from);
  // From t = 0 to the moment shown, so that the video's last frame is the one seen.
  const double t_end = moment.time > 0 ? moment.time : setup.speed * duration_s;
  sim.t_end.set(t_end, from);

  d.scene = setup.scene;
  if (sim::is_adaptive(run.method)) d.scene.auto_tolerance = false;  // the tol written is the one
  d.scene.fps = 30.0;
  // Frames 1/fps s apart at the live speed, the first at t = 0 and the last
  // at t_end: one frame more than t_end / speed seconds hold, so that the
  // frames (and the trail samples between them) fall where the live ones did.
  d.scene.duration = t_end / std::max(setup.speed, 1e-9) + 1.0 / d.scene.fps;
  d.output.dir = "out/" + name;
  d.output.video = io::VideoFormat::mp4;
  d.output.name = name;
  return d;
}

std::string render_job_json(const LiveSetup& setup, const std::string& name,
                            const LiveMoment& moment, double duration_s) {
  return job::write_job(job_document(setup, name, moment, duration_s)).dump(2) + "\n";
}

}  // namespace epviz::live
