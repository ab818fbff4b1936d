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
