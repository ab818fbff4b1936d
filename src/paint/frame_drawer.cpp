#include "paint/frame_drawer.hpp"

namespace epviz::paint {

FrameDrawer::FrameDrawer(const scene::ScenePlan& plan, const scene::SceneSettings& settings)
    : source_(plan, settings) {}

const render::RgbaImage& FrameDrawer::draw(int index, FramePainter& painter,
                                           std::mutex* paint_lock) {
  scene::Frame frame = source_.frame(index);
  frame.caption = caption_;
  if (!paint_lock) return painter.paint(frame);
  std::lock_guard lock(*paint_lock);
  return painter.paint(frame);
}

DrawnFrames draw_frames(const scene::ScenePlan& plan, const scene::SceneSettings& settings,
                        std::span<const int> frames, FramePainter& painter,
                        std::mutex* paint_lock) {
  DrawnFrames out;
  FrameDrawer drawer(plan, settings);
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

}  // namespace epviz::paint
