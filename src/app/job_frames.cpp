#include "app/job_frames.hpp"

#include "app/usage_error.hpp"

namespace epviz::app {

scene::ScenePlan plan_job(const RenderJob& job) {
  const sim::RunSpec run = resolve(job.simulation);
  try {
    return scene::plan_scene(run, job.scene);
  } catch (const scene::PlanError& e) {
    throw UsageError(job.file.string() + ": " + e.what());
  }
}

JobFrameDrawer::JobFrameDrawer(const scene::ScenePlan& plan, const scene::SceneSettings& settings)
    : source_(plan, settings) {}

const render::RgbaImage& JobFrameDrawer::draw(int index, paint::FramePainter& painter,
                                              std::mutex* paint_lock) {
  const scene::Frame frame = source_.frame(index);
  if (!paint_lock) return painter.paint(frame);
  std::lock_guard lock(*paint_lock);
  return painter.paint(frame);
}

RenderedFrames render_job_frames(const scene::ScenePlan& plan, const scene::SceneSettings& settings,
                                 std::span<const int> frames, paint::FramePainter& painter,
                                 std::mutex* paint_lock) {
  RenderedFrames out;
  JobFrameDrawer drawer(plan, settings);
  try {
    for (const int i : frames) {
      // Copied: the painter's next paint overwrites its image.
      out.images.push_back(drawer.draw(i, painter, paint_lock));
    }
  } catch (const numerics::IntegrationError& e) {
    out.failure = e.failure();
  }
  return out;
}

}  // namespace epviz::app
