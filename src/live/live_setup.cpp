#include "live/live_setup.hpp"

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

}  // namespace epviz::live
