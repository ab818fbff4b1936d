#include "paint/gallery_figure.hpp"

#include <algorithm>
#include <vector>

#include "io/png_writer.hpp"
#include "paint/frame_files.hpp"

namespace epviz::paint {

GalleryFigureWritten write_gallery_figure(
    std::span<const GalleryStill> stills, const GalleryFigure& figure, FramePainter& painter,
    const io::ProgressOptions& progress,
    const std::function<void(const numerics::Failure&)>& on_failure) {
  GalleryFigureWritten out;
  std::vector<render::RgbaImage> tiles;
  // The clouds' spread charts on one time axis, so that tiles compare.
  double cloud_t_end = 0.0;
  for (const auto& still : stills)
    cloud_t_end =
        std::max(cloud_t_end, cloud_chart_t_end(*still.scene.plan, *still.scene.settings));
  for (const auto& still : stills) {
    FrameDrawer drawer(*still.scene.plan, *still.scene.settings);
    drawer.set_caption(still.scene.caption);
    drawer.set_cloud_chart_t_end(cloud_t_end);
    auto options = progress;
    options.label = still.label;
    auto written = write_frames(drawer, painter, {still.frame, still.frame}, std::nullopt, options);
    if (written.failure) {
      ++out.failures;
      on_failure(*written.failure);
    }
    tiles.push_back(
        written.kept
            ? std::move(*written.kept)
            : render::RgbaImage{figure.tile_width, figure.tile_height,
                                std::vector<std::uint8_t>(
                                    std::size_t(figure.tile_width) * figure.tile_height * 4, 0)});
  }
  std::vector<std::span<const std::uint8_t>> spans;
  for (const auto& t : tiles) spans.emplace_back(t.pixels);
  const auto image = io::tile_images(spans, figure.tile_width, figure.tile_height, figure.tiling);
  io::write_png_rgba(figure.path, image.width, image.height, image.pixels);
  out.width = image.width;
  out.height = image.height;
  return out;
}

}  // namespace epviz::paint
