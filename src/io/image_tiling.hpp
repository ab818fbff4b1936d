#pragma once
// Composes equally sized RGBA8 images into one grid image, for the gallery's
// comparison figure. Only placement: the tiles are copied unchanged (captions
// and labels are drawn by the renderer into each tile beforehand), the gaps and
// the outer margin are filled with the background colour.
//
// Layout: tiles in row-major order (left to right, then top to bottom), tile i
// at column i % cols, row i / cols, its top-left corner at
//   x = margin + col * (tile_width + gap),  y = margin + row * (tile_height + gap).
// Cells of the last row without an image keep the background.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace epviz::io {

struct TilingOptions {
  int cols = 0;    // columns; 0 chooses ceil(sqrt(n)) (a near-square grid)
  int gap = 0;     // pixels between neighbouring tiles
  int margin = 0;  // pixels around the whole grid
  std::array<std::uint8_t, 4> background = {255, 255, 255,
                                            255};  // RGBA of gaps, margin and empty cells
};

// An RGBA8 image of top-down rows (the same layout as render::RgbaImage).
struct TiledImage {
  int width = 0;
  int height = 0;
  int cols = 0;
  int rows = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 4 bytes
};

struct GridSize {
  int cols = 0;
  int rows = 0;
  int width = 0;
  int height = 0;
};

// The grid's shape and pixel size for `count` tiles. Throws std::invalid_argument
// for count < 1, non-positive tile size, negative gap/margin or cols < 0.
GridSize tiled_size(int count, int tile_width, int tile_height, const TilingOptions& options = {});

// Tiles `tiles` (each tile_width * tile_height * 4 bytes) into a grid. Throws
// std::invalid_argument if a tile has the wrong size or the arguments are invalid.
TiledImage tile_images(std::span<const std::span<const std::uint8_t>> tiles, int tile_width,
                       int tile_height, const TilingOptions& options = {});

// Copies a src_width x src_height RGBA image into `dst` (dst_width wide) with
// its top-left corner at (x, y); the part outside dst is clipped.
void blit_rgba(std::span<std::uint8_t> dst, int dst_width, int dst_height,
               std::span<const std::uint8_t> src, int src_width, int src_height, int x, int y);

}  // namespace epviz::io
