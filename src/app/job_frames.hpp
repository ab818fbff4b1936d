#pragma once
// A render job turned into pictures: the scene plan a job needs, and the
// frames of it drawn through scene::FrameSource and paint::FramePainter.
// Shared by `epviz render` (frames to files) and `epviz check` (frames in
// memory, compared with goldens).
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <vector>

#include "app/render_job.hpp"
#include "numerics/failure.hpp"
#include "paint/frame_painter.hpp"
#include "render/image.hpp"
#include "scene/frame_source.hpp"
#include "scene/plan.hpp"

namespace epviz::app {

// The scene plan of `job` (simulation resolved, tolerance chosen for its
// resolution). Throws UsageError naming the job file when it cannot be drawn.
scene::ScenePlan plan_job(const RenderJob& job);

// What the render report (--report-json) says of each run of a scene after
// its frames: method, the step used (fixed) or tolerance (adaptive), steps,
// evaluations, the drift of its steps, and its pixel-true horizon.
nlohmann::json runs_report(const scene::FrameSource& source);

// Draws frames of one job in increasing order; the simulation runs through
// the frames in between without drawing them.
class JobFrameDrawer {
 public:
  JobFrameDrawer(const scene::ScenePlan& plan, const scene::SceneSettings& settings);
  // Frame `index` (indices must not decrease), valid until the painter's next
  // paint. Throws numerics::IntegrationError on a numerical failure.
  const render::RgbaImage& draw(int index, paint::FramePainter& painter,
                                std::mutex* paint_lock = nullptr);
  const scene::FrameSource& source() const { return source_; }
  // A caption drawn under every frame (gallery tiles).
  void set_caption(std::string caption) { caption_ = std::move(caption); }

 private:
  scene::FrameSource source_;
  std::string caption_;
};

// A gallery tile's caption: the job's name, method and accuracy.
std::string tile_caption(const RenderJob& job, const scene::ScenePlan& plan);

struct RenderedFrames {
  std::vector<render::RgbaImage> images;  // one per frame asked for, until a failure
  std::optional<numerics::Failure> failure;
};

// Frames `frames` (increasing) of a job into images. `paint_lock`, when
// given, is held while painting only, so that simulations of jobs on other
// threads go on meanwhile (ImGui keeps its current context in one global, so
// painters on several threads must take turns).
RenderedFrames render_job_frames(const scene::ScenePlan& plan, const scene::SceneSettings& settings,
                                 std::span<const int> frames, paint::FramePainter& painter,
                                 std::mutex* paint_lock = nullptr);

}  // namespace epviz::app
