#include "paint/grid_video.hpp"

#include <algorithm>
#include <memory>
#include <vector>

#include "io/video_writer.hpp"
#include "paint/frame_drawer.hpp"

namespace epviz::paint {

GridVideoWritten write_grid_video(std::span<const GridScene> scenes, const GridVideo& video,
                                  FramePainter& painter,
                                  const io::ProgressOptions& progress_options,
                                  const std::function<void(const numerics::Failure&)>& on_failure) {
  GridVideoWritten out;
  std::vector<std::unique_ptr<FrameDrawer>> drawers;
  std::vector<render::RgbaImage> tiles;
  std::vector<bool> failed(scenes.size(), false);
  // The clouds' spread charts on one time axis, as in the gallery's figure.
  double cloud_t_end = 0.0;
  for (const auto& s : scenes)
    cloud_t_end = std::max(cloud_t_end, cloud_chart_t_end(*s.plan, *s.settings));
  for (const auto& s : scenes) {
    drawers.push_back(std::make_unique<FrameDrawer>(*s.plan, *s.settings));
    drawers.back()->set_caption(s.caption);
    drawers.back()->set_cloud_chart_t_end(cloud_t_end);
    tiles.push_back(
        {video.tile_width, video.tile_height,
         std::vector<std::uint8_t>(std::size_t(video.tile_width) * video.tile_height * 4, 0)});
    out.frames = std::max(out.frames, s.plan->frames);
  }
  out.size = io::tiled_size(int(scenes.size()), video.tile_width, video.tile_height, video.tiling);
  io::VideoWriter writer(video.path, io::VideoFormat::mp4, out.size.width, out.size.height,
                         video.fps);
  io::ProgressLine progress(out.frames, progress_options);
  for (int i = 0; i < out.frames; ++i) {
    for (std::size_t k = 0; k < scenes.size(); ++k) {
      if (failed[k]) continue;
      try {
        tiles[k] = drawers[k]->draw(std::min(i, scenes[k].plan->frames - 1), painter);
      } catch (const numerics::IntegrationError& e) {
        failed[k] = true;
        ++out.failures;
        on_failure(e.failure());
      }
    }
    std::vector<std::span<const std::uint8_t>> spans;
    for (const auto& t : tiles) spans.emplace_back(t.pixels);
    const auto grid = io::tile_images(spans, video.tile_width, video.tile_height, video.tiling);
    writer.write_frame(grid.pixels.data());
    progress.advance();
  }
  progress.finish();
  writer.finish();
  return out;
}

}  // namespace epviz::paint
