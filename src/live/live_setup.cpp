#include "live/live_setup.hpp"

#include <cstdio>
#include <exception>

#include "io/bad_input.hpp"
#include "io/data_dir.hpp"
#include "job/job_file.hpp"
#include "job/job_plan.hpp"
#include "job/resolve.hpp"

namespace epviz::live {

LiveSetup preset_setup(physics::Case c) {
  scene::SceneSettings scene;
  scene.trail_length = 20.0;
  scene.duration = 10.0;
  return setup_from_job(sim::preset_run(c, sim::Method::dop853, sim::Formulation::direct, 40.0, 1),
                        scene);
}

LiveSetup setup_from_job(const sim::RunSpec& run, const scene::SceneSettings& scene) {
  LiveSetup s;
  s.run = run;
  s.scene = scene;
  // The job plays t_end over its duration; interactively the trail shows what
  // the video's last frame would (the whole run when the job sets no length).
  s.speed = run.t_end / scene.duration;
  if (s.scene.trail_length <= 0.0) s.scene.trail_length = run.t_end;
  s.stay_in_case = run.case_id != physics::Case::custom;
  return s;
}

LiveSetup setup_from_job_file(const std::filesystem::path& file) {
  job::LoadedJob loaded = job::load_job_file(file);
  if (!loaded.single)
    throw io::BadInput(file.string() + ": serve needs a single render job (this file is a " +
                       (loaded.gallery ? "gallery" : "bench figures job") + ")");
  const job::RenderJob& job = *loaded.single;
  if (job.runs.empty()) return setup_from_job(job::resolve(job.simulation), job.scene);
  // A comparison: the first run is the one the panel edits, the others are drawn as given.
  const auto runs = job::run_requests(job);
  LiveSetup s = setup_from_job(runs.front().run, job.scene);
  s.label = runs.front().label;
  s.scene.formulation_given = runs.front().formulation_given;
  s.scene.auto_tolerance = runs.front().auto_tolerance;
  for (std::size_t i = 1; i < runs.size(); ++i) {
    ComparedRun c;
    c.given = runs[i];
    s.compared.push_back(std::move(c));
  }
  return s;
}

LiveSetup preset_from_jobs(physics::Case c) {
  const auto file = io::find_data_path("render_jobs/" + physics::case_name(c) + ".json");
  try {
    if (!file.empty() && std::filesystem::is_regular_file(file)) return setup_from_job_file(file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "epviz serve: %s (using the built-in preset)\n", e.what());
  }
  return preset_setup(c);
}

}  // namespace epviz::live
