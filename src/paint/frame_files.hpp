#pragma once
// A range of a scene's frames drawn into files: one PNG per frame, written
// on a background thread, or one video through ffmpeg; a progress line on
// stderr while they are drawn.
#include <filesystem>
#include <optional>
#include <string>

#include "io/frame_range.hpp"
#include "io/progress.hpp"
#include "io/video_format.hpp"
#include "numerics/failure.hpp"
#include "paint/frame_drawer.hpp"

namespace epviz::paint {

// Where the frames go: dir/<name>_<frame>.png, or dir/<name>.<ext> for a video.
struct FrameFiles {
  std::filesystem::path dir;
  std::string name;
  std::optional<io::VideoFormat> video;  // empty: a PNG sequence
  double fps = 30.0;                     // of the video
  bool resume = false;                   // PNG: skip frames whose file is already complete
};

struct FramesWritten {
  int drawn = 0, skipped = 0;
  double seconds = 0.0;
  std::optional<numerics::Failure> failure;  // the frames after it are not drawn
  std::optional<render::RgbaImage> kept;     // the last frame drawn, when no files are written
};

// Draws frames range.first..range.last (frames before it are integrated
// through, not drawn) into `files`, or, without files, keeps the last frame.
// A video that fails is not kept (the writer removes it).
FramesWritten write_frames(FrameDrawer& drawer, FramePainter& painter, const io::FrameRange& range,
                           const std::optional<FrameFiles>& files,
                           const io::ProgressOptions& progress);

}  // namespace epviz::paint
