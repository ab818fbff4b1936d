#pragma once
// The frames of a planned scene drawn through scene::FrameSource and the
// frame painter, in increasing order: the simulation runs through the frames
// in between without drawing them. Shared by `epviz render` (frames to files)
// and `epviz check` (each frame compared with its golden as it is drawn).
#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "numerics/failure.hpp"
#include "paint/frame_painter.hpp"
#include "render/image.hpp"
#include "scene/frame_source.hpp"
#include "scene/plan.hpp"

namespace epviz::paint {

class FrameDrawer {
 public:
  FrameDrawer(const scene::ScenePlan& plan, const scene::SceneSettings& settings);
  // Frame `index` (indices must not decrease), valid until the painter's next
  // paint. `paint_lock`, when given, is held while painting only. Throws
  // numerics::IntegrationError on a numerical failure.
  const render::RgbaImage& draw(int index, FramePainter& painter, std::mutex* paint_lock = nullptr);
  // Frame `index` as draw() paints it (same order rule), for painters of
  // other kinds (vector/frame_still.hpp).
  scene::Frame frame(int index);
  const scene::FrameSource& source() const { return source_; }
  // A caption drawn under every frame (gallery tiles).
  void set_caption(std::string caption) { caption_ = std::move(caption); }
  // The end of the cloud's spread chart's time axis (a gallery's tiles: the
  // longest of theirs); 0: each scene's own.
  void set_cloud_chart_t_end(double t) { cloud_chart_t_end_ = t; }

 private:
  scene::FrameSource source_;
  std::string caption_;
  double cloud_chart_t_end_ = 0.0;
};

// The time a scene's cloud ends at (its last frame's), 0 without a cloud:
// what a gallery's tiles share as the spread chart's time axis.
double cloud_chart_t_end(const scene::ScenePlan& plan, const scene::SceneSettings& settings);

// Frames `frames` (increasing) of a scene, each handed to `on_frame` as soon
// as it is drawn (valid during the call only), so that no frame need be kept.
// `paint_lock`, when given, is held while painting only, so that simulations
// of scenes on other threads go on meanwhile (ImGui keeps its current context
// in one global, so painters on several threads must take turns). Returns the
// numerical failure that ended the frames early, or nullopt.
std::optional<numerics::Failure> draw_frames(
    const scene::ScenePlan& plan, const scene::SceneSettings& settings, std::span<const int> frames,
    FramePainter& painter, std::mutex* paint_lock,
    const std::function<void(const render::RgbaImage&)>& on_frame);

struct DrawnFrames {
  std::vector<render::RgbaImage> images;  // one per frame asked for, until a failure
  std::optional<numerics::Failure> failure;
};

// The same, the frames kept (a few frames: tests, stills).
DrawnFrames draw_frames(const scene::ScenePlan& plan, const scene::SceneSettings& settings,
                        std::span<const int> frames, FramePainter& painter,
                        std::mutex* paint_lock = nullptr);

}  // namespace epviz::paint
