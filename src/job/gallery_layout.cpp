#include "job/gallery_layout.hpp"

#include <cmath>
#include <string>

#include "io/bad_input.hpp"

namespace epviz::job {

RenderJob gallery_member(const GalleryJob& gallery, RenderJob job, bool video) {
  // A still is a tile; a video is the job's own, at the size the job asks for.
  if (!video) {
    job.scene.width = gallery.tile_width;
    job.scene.height = gallery.tile_height;
  }
  job.output.dir = gallery.dir;
  job.output.video.reset();
  if (video) {
    job.output.video = gallery.videos;
    job.output.name = job.file.stem().string();
  }
  return job;
}

int gallery_still_frame(const GalleryJob& gallery, int frames) {
  return int(std::lround(gallery.at * (frames - 1)));
}

io::TilingOptions gallery_tiling(const GalleryJob& gallery) {
  io::TilingOptions tiling;
  tiling.cols = gallery.columns;
  tiling.gap = 4;
  tiling.margin = 4;
  tiling.background = {16, 18, 22, 255};
  return tiling;
}

io::GridSize grid_video_size(const GalleryJob& gallery, int jobs) {
  const auto grid =
      io::tiled_size(jobs, gallery.tile_width, gallery.tile_height, gallery_tiling(gallery));
  if (grid.width % 2 || grid.height % 2)
    throw io::BadInput(gallery.file.string() + ": grid_video: the grid is " +
                       std::to_string(grid.width) + "x" + std::to_string(grid.height) +
                       " pixels; a video needs an even width and height (change the tile size)");
  return grid;
}

}  // namespace epviz::job
