#include "live/job_file.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "io/bad_input.hpp"
#include "io/json_text.hpp"
#include "io/output_paths.hpp"
#include "io/video_format.hpp"
#include "job/job_file.hpp"
#include "job/job_plan.hpp"
#include "job/schema.hpp"
#include "physics/cases.hpp"
#include "scene/plan.hpp"

namespace epviz::live {
namespace {

std::array<double, 3> vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// The horizon LiveScene plans an open-ended run's automatic tolerance for
// (live_scene.cpp, kToleranceHorizon): the two must agree, which
// job_file_moment_test checks against the live scene's own note.
constexpr double kLiveToleranceHorizon = 1e4;

const std::string kFrom = "the live setup";

// A run's body, state and integrator in full; `tol` for an adaptive method
// (a number: "auto" would be chosen again for the job's shorter run).
void set_run_fields(job::SimulationFields& sim, const sim::RunSpec& run, double tol) {
  sim.inertia.set(vec(run.body.inertia), kFrom);
  sim.com.set(vec(run.body.com), kFrom);
  sim.weight.set(run.body.weight, kFrom);
  sim.omega.set(vec(run.initial.omega), kFrom);
  sim.gamma.set(vec(run.initial.gamma), kFrom);
  sim.formulation.set(std::string(sim::name(run.formulation)), kFrom);
  sim.method.set(std::string(sim::name(run.method)), kFrom);
  if (!sim::is_adaptive(run.method))
    sim.step.set(run.step, kFrom);
  else
    sim.tol.set(tol, kFrom);
  if (run.formulation == sim::Formulation::riccati) sim.chart_switch.set(run.chart_switch, kFrom);
}

// The live plan of the setup's runs (their formulations and automatic tolerances resolved).
scene::ScenePlan live_plan(const LiveSetup& setup) {
  auto runs = run_requests(setup);
  for (auto& r : runs) r.run.t_end = std::max(r.run.t_end, kLiveToleranceHorizon);
  return scene::plan_scene(std::move(runs), setup.scene, scene::Horizon::none);
}

// A job's "runs" for a setup with compared runs: the first as "simulation"
// states it, each further one with only what differs from it (a run a job
// gave in full, in full).
std::vector<job::RunFields> compared_runs(const LiveSetup& setup, const LiveMoment& moment) {
  std::vector<job::RunFields> runs;
  if (setup.compared.empty()) return runs;
  runs.emplace_back();
  runs.front().label = setup.label;
  std::optional<scene::ScenePlan> plan;
  for (std::size_t i = 0; i < setup.compared.size(); ++i) {
    const ComparedRun& c = setup.compared[i];
    job::RunFields r;
    r.label = compared_label(c);
    auto& sim = r.simulation;
    const sim::RunSpec spec = compared_spec(setup.run, c);
    if (c.given) {
      // As the live scene resolved it: its formulation, and an automatic
      // tolerance as the number used (the same for every run of one picture).
      if (!plan) plan = live_plan(setup);
      const sim::RunSpec& planned = plan->others[i].run;
      const double tol =
          c.given->auto_tolerance && moment.tolerance ? *moment.tolerance : planned.tol;
      set_run_fields(sim, planned, tol);
      sim.case_name.set(physics::case_name(planned.case_id), kFrom);
    }
    if (c.method) {
      sim.method.set(std::string(sim::name(spec.method)), kFrom);
      if (sim::is_adaptive(spec.method))
        sim.tol.set(spec.tol, kFrom);
      else
        sim.step.set(spec.step, kFrom);
    }
    if (c.nudge != 0.0) {
      sim.gamma.set(vec(spec.initial.gamma), kFrom);
      // A nudge that breaks the case's conditions makes it a custom body, as live.
      if (spec.case_id != setup.run.case_id) sim.case_name.set("custom", kFrom);
    }
    runs.push_back(std::move(r));
  }
  return runs;
}

// A page's size as a job's video can have it: at most the job's 8192 a side
// (smaller alike, the shape kept), and even (MP4's yuv420p needs it).
void even_video_size(int& width, int& height) {
  constexpr int kLargest = 8192, kSmallest = 16;
  const double shrink = std::min(1.0, double(kLargest) / std::max({width, height, 1}));
  auto even = [&](int side) {
    const int s = int(std::lround(side * shrink)) / 2 * 2;
    return std::clamp(s, kSmallest, kLargest);
  };
  width = even(width);
  height = even(height);
}

}  // namespace

void check_render_accepts(const std::string& text, const std::string& file_name) {
  const nlohmann::json object = nlohmann::json::parse(text);
  job::JobDocument d = job::read_job(object, file_name);
  job::RenderJob job{file_name, std::move(d.simulation), std::move(d.runs), std::move(d.scene),
                     std::move(d.output)};
  io::check_file_name(file_name + ": output.name", job.output.name);
  if (job.output.video)
    if (const std::string why =
            io::video_size_problem(*job.output.video, job.scene.width, job.scene.height);
        !why.empty())
      throw io::BadInput(file_name + ": " + why);
  (void)job::plan_job(job);
}

std::optional<double> live_tolerance(const LiveSetup& setup) {
  if (!sim::is_adaptive(setup.run.method) || !setup.scene.auto_tolerance) return std::nullopt;
  // Planned with every run: the legend and the separation chart of a
  // comparison take room from the picture, whose resolution sets the tolerance.
  return live_plan(setup).run.tol;
}

job::JobDocument job_document(const LiveSetup& setup, const std::string& name,
                              const LiveMoment& moment, double duration_s) {
  const auto& run = setup.run;
  job::JobDocument d;
  auto& sim = d.simulation;
  if (run.case_id != physics::Case::custom)
    sim.case_name.set(physics::case_name(run.case_id), kFrom);
  // The tolerance the live run uses.
  set_run_fields(sim, run, moment.tolerance.value_or(run.tol));
  // From t = 0 to the moment shown, so that the video's last frame is the one seen.
  const double t_end = moment.time > 0 ? moment.time : setup.speed * duration_s;
  sim.t_end.set(t_end, kFrom);

  d.runs = compared_runs(setup, moment);

  d.scene = setup.scene;
  even_video_size(d.scene.width, d.scene.height);
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
  return io::json_text(job::write_job(job_document(setup, name, moment, duration_s)), 2) + "\n";
}

}  // namespace epviz::live
