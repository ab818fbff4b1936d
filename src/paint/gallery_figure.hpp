#pragma once
// A gallery's comparison figure: one still of each scene, drawn with its
// caption and tiled into one PNG. A scene whose still fails (a numerical
// failure before that frame) leaves its tile blank, so that the others still
// compare.
#include <filesystem>
#include <functional>
#include <span>
#include <string>

#include "io/image_tiling.hpp"
#include "io/progress.hpp"
#include "numerics/failure.hpp"
#include "paint/frame_painter.hpp"
#include "paint/grid_video.hpp"

namespace epviz::paint {

struct GalleryStill {
  GridScene scene;
  int frame = 0;      // which of the scene's frames is its still
  std::string label;  // of its progress line
};

struct GalleryFigure {
  std::filesystem::path path;  // a PNG
  int tile_width = 0, tile_height = 0;
  io::TilingOptions tiling;
};

struct GalleryFigureWritten {
  int failures = 0;  // stills that failed (blank tiles)
  int width = 0, height = 0;
};

// Draws each still with `painter` (of the tile size) and writes the figure.
// Each numerical failure is passed to `on_failure` when it happens.
GalleryFigureWritten write_gallery_figure(
    std::span<const GalleryStill> stills, const GalleryFigure& figure, FramePainter& painter,
    const io::ProgressOptions& progress,
    const std::function<void(const numerics::Failure&)>& on_failure);

}  // namespace epviz::paint
