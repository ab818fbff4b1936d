#pragma once
// Several scenes at once, tiled frame by frame into one video: frame i of
// each scene side by side, a scene that has ended held at its last frame, a
// scene that failed held at its last good frame.
#include <filesystem>
#include <functional>
#include <span>
#include <string>

#include "io/image_tiling.hpp"
#include "io/progress.hpp"
#include "numerics/failure.hpp"
#include "paint/frame_painter.hpp"
#include "scene/plan.hpp"

namespace epviz::paint {

struct GridScene {
  const scene::ScenePlan* plan = nullptr;
  const scene::SceneSettings* settings = nullptr;
  std::string caption;  // under every frame of its tile
};

struct GridVideo {
  std::filesystem::path path;  // an MP4
  int tile_width = 0, tile_height = 0;
  io::TilingOptions tiling;
  double fps = 30.0;
};

struct GridVideoWritten {
  int frames = 0;    // the longest scene's
  int failures = 0;  // scenes that failed
  io::GridSize size;
};

// Draws the scenes with `painter` (of the tile size) into the video. Each
// numerical failure is passed to `on_failure` when it happens.
GridVideoWritten write_grid_video(std::span<const GridScene> scenes, const GridVideo& video,
                                  FramePainter& painter, const io::ProgressOptions& progress,
                                  const std::function<void(const numerics::Failure&)>& on_failure);

}  // namespace epviz::paint
