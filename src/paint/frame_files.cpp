#include "paint/frame_files.hpp"

#include <chrono>
#include <memory>

#include "io/frame_names.hpp"
#include "io/png_writer.hpp"
#include "io/queued_video_writer.hpp"
#include "io/temp_name.hpp"

namespace epviz::paint {

namespace fs = std::filesystem;

FramesWritten write_frames(FrameDrawer& drawer, FramePainter& painter, const io::FrameRange& range,
                           const std::optional<FrameFiles>& files,
                           const io::ProgressOptions& progress_options) {
  FramesWritten out;
  std::unique_ptr<io::AsyncPngWriter> pngs;
  std::unique_ptr<io::QueuedVideoWriter> video;
  if (files) {
    fs::create_directories(files->dir);
    // Temporaries of runs killed before they could clean up (SIGKILL).
    io::remove_stale_temporaries(files->dir);
    if (!files->video) {
      pngs = std::make_unique<io::AsyncPngWriter>();
    } else {
      const auto format = *files->video;
      // On a thread of its own: the next frame is drawn while ffmpeg takes this one.
      video = std::make_unique<io::QueuedVideoWriter>(std::make_unique<io::VideoWriter>(
          files->dir / (files->name + std::string(io::video_format_extension(format))), format,
          painter.width(), painter.height(), files->fps));
    }
  }
  const int frame_count = drawer.source().plan().frames;
  io::ProgressLine progress(range.count(), progress_options);

  const auto start = std::chrono::steady_clock::now();
  try {
    for (int i = range.first; i <= range.last; ++i) {
      if (pngs) {
        const fs::path png_path =
            files->dir / io::frame_file_name(i, frame_count, files->name + "_", ".png");
        if (files->resume && io::png_frame_complete(png_path)) {
          ++out.skipped;
          progress.advance();
          continue;
        }
        const render::RgbaImage& image = drawer.draw(i, painter);
        pngs->submit(png_path, image.width, image.height, image.pixels);
      } else {
        const render::RgbaImage& image = drawer.draw(i, painter);
        if (video) video->write_frame(image.pixels);
        if (!files) out.kept = image;
      }
      ++out.drawn;
      progress.advance();
    }
  } catch (const numerics::IntegrationError& e) {
    out.failure = e.failure();
  }
  progress.finish();
  if (pngs) pngs->close();
  if (video && !out.failure) video->finish();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace epviz::paint
