#include "live/job_file.hpp"

#include "job/schema.hpp"

namespace epviz::live {
namespace {

std::array<double, 3> vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

job::JobDocument job_document(const LiveSetup& setup, const std::string& name, double duration_s) {
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
  // An adaptive method's tolerance ("auto" unless it was chosen), a fixed step otherwise.
  if (!sim::is_adaptive(run.method))
    sim.step.set(run.step, from);
  else if (!setup.scene.auto_tolerance)
    sim.tol.set(run.tol, from);
  if (run.formulation == sim::Formulation::riccati) sim.chart_switch.set(run.chart_switch, from);
  sim.t_end.set(setup.speed * duration_s, from);

  d.scene = setup.scene;
  d.scene.fps = 30.0;
  d.scene.duration = duration_s;
  d.output.dir = "out/" + name;
  d.output.format = job::OutputFormat::mp4;
  d.output.name = name;
  return d;
}

std::string render_job_json(const LiveSetup& setup, const std::string& name, double duration_s) {
  return job::write_job(job_document(setup, name, duration_s)).dump(2) + "\n";
}

}  // namespace epviz::live
