#pragma once
// How a gallery (job/job_file.hpp) lays its tiles out: the figure and the
// grid video share one tiling, and the grid video's size is checked before
// any work.
#include "io/image_tiling.hpp"
#include "job/job_file.hpp"

namespace epviz::job {

// A job of the gallery as the gallery draws it, into the gallery's
// directory: as a still (no video) at the tile size, or as the gallery's
// video of it at the job's own size (in the gallery's video format, named
// after the job's file).
RenderJob gallery_member(const GalleryJob& gallery, RenderJob job, bool video);

// The frame of a job's still, of its `frames`: `at` of the way through.
int gallery_still_frame(const GalleryJob& gallery, int frames);

// The gallery's tiling of its figure and grid video.
io::TilingOptions gallery_tiling(const GalleryJob& gallery);

// The grid video's size in pixels for `jobs` tiles. Throws io::BadInput naming
// the gallery file when the width or height is odd (a video needs them even).
io::GridSize grid_video_size(const GalleryJob& gallery, int jobs);

}  // namespace epviz::job
