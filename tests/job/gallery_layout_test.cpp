// The gallery's tiling and the size its grid video must have.
#include <gtest/gtest.h>

#include "io/bad_input.hpp"
#include "job/gallery_layout.hpp"

namespace epviz::job {
namespace {

GalleryJob gallery(int tile_width, int tile_height, int columns) {
  GalleryJob g;
  g.file = "gallery.json";
  g.tile_width = tile_width;
  g.tile_height = tile_height;
  g.columns = columns;
  return g;
}

TEST(GalleryLayout, AStillIsATileAndAVideoTheJobsOwnSizeInTheGallerysDirectory) {
  auto g = gallery(320, 180, 3);
  g.dir = "out/g";
  g.videos = io::VideoFormat::webm;
  RenderJob job;
  job.file = "jobs/euler.json";
  job.scene.width = 1280;
  job.output = {"elsewhere", io::VideoFormat::mp4, "frame", {}};
  const auto still = gallery_member(g, job, false);
  EXPECT_EQ(still.scene.width, 320);
  EXPECT_EQ(still.scene.height, 180);
  EXPECT_EQ(still.output.dir, "out/g");
  EXPECT_EQ(still.output.video, std::nullopt);
  const auto video = gallery_member(g, job, true);
  EXPECT_EQ(video.scene.width, 1280);  // a video at the size its job asks for
  EXPECT_EQ(video.scene.height, job.scene.height);
  EXPECT_EQ(video.output.video, io::VideoFormat::webm);
  EXPECT_EQ(video.output.name, "euler");
  EXPECT_EQ(video.output.dir, "out/g");
}

TEST(GalleryLayout, AStillIsTheFrameAtItsFractionOfTheRun) {
  auto g = gallery(320, 180, 3);
  g.at = 0.6;
  EXPECT_EQ(gallery_still_frame(g, 101), 60);
  EXPECT_EQ(gallery_still_frame(g, 1), 0);
  g.at = 1.0;
  EXPECT_EQ(gallery_still_frame(g, 270), 269);
}

TEST(GalleryLayout, TheTilingHasTheGallerysColumns) {
  EXPECT_EQ(gallery_tiling(gallery(320, 180, 4)).cols, 4);
}

TEST(GalleryLayout, GridVideoSizeCountsTilesGapsAndMargins) {
  // Five tiles in three columns: two rows; 4 px gaps between tiles and 4 px
  // margins around: 3*320 + 2*4 + 2*4 by 2*180 + 4 + 2*4.
  const auto size = grid_video_size(gallery(320, 180, 3), 5);
  EXPECT_EQ(size.width, 976);
  EXPECT_EQ(size.height, 372);
  // Fewer jobs than columns: only as many columns as jobs.
  EXPECT_EQ(grid_video_size(gallery(320, 180, 3), 2).width, 2 * 320 + 4 + 8);
}

TEST(GalleryLayout, AnOddGridIsRefusedNamingTheGallery) {
  // One 321-pixel tile with its margins is 329 pixels wide: odd.
  try {
    grid_video_size(gallery(321, 180, 3), 1);
    ADD_FAILURE() << "an odd grid was accepted";
  } catch (const io::BadInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("gallery.json: grid_video: the grid is 329x188 pixels"), std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace epviz::job
