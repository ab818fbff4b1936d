#include "paint/frame_drawer.hpp"

#include <vector>

#include "paint/frame_typesetting.hpp"

namespace epviz::paint {

FrameDrawer::FrameDrawer(const scene::ScenePlan& plan, const scene::SceneSettings& settings)
    : source_(plan, settings) {}

scene::Frame FrameDrawer::frame(int index) {
  scene::Frame frame = source_.frame(index);
  frame.caption = caption_;
  typeset_frame_text(frame);
  if (frame.cloud && cloud_chart_t_end_ > 0.0) frame.cloud->chart_t_end = cloud_chart_t_end_;
  // A single run's overlay shows its drift at the steps beside the drawn
  // states' (a comparison's rows are its runs, one figure each).
  // Empty where the rows are not those of the column.
  if (!frame.comparison && source_.run_count() == 1) {
    auto column = source_.step_drift_column();
    if (column.size() == frame.overlay.drifts.size()) frame.overlay.step_drifts = std::move(column);
  }
  return frame;
}

double cloud_chart_t_end(const scene::ScenePlan& plan, const scene::SceneSettings& settings) {
  if (!settings.cloud.enabled() || plan.open_ended || plan.frames < 1) return 0.0;
  return plan.frame_time(plan.frames - 1);
}

const render::RgbaImage& FrameDrawer::draw(int index, FramePainter& painter,
                                           std::mutex* paint_lock) {
  const scene::Frame frame = this->frame(index);
  if (!paint_lock) return painter.paint(frame);
  std::lock_guard lock(*paint_lock);
  return painter.paint(frame);
}

std::optional<numerics::Failure> draw_frames(
    const scene::ScenePlan& plan, const scene::SceneSettings& settings, std::span<const int> frames,
    FramePainter& painter, std::mutex* paint_lock,
    const std::function<void(const render::RgbaImage&)>& on_frame) {
  FrameDrawer drawer(plan, settings);
  try {
    for (const int i : frames) on_frame(drawer.draw(i, painter, paint_lock));
  } catch (const numerics::IntegrationError& e) {
    return e.failure();
  }
  return std::nullopt;
}

DrawnFrames draw_frames(const scene::ScenePlan& plan, const scene::SceneSettings& settings,
                        std::span<const int> frames, FramePainter& painter,
                        std::mutex* paint_lock) {
  DrawnFrames out;
  // Copied: the painter's next paint overwrites its image.
  out.failure = draw_frames(plan, settings, frames, painter, paint_lock,
                            [&](const render::RgbaImage& image) { out.images.push_back(image); });
  return out;
}

}  // namespace epviz::paint
