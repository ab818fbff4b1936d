#include "io/image_tiling.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace epviz::io {

GridSize tiled_size(int count, int tile_width, int tile_height, const TilingOptions& options) {
  if (count < 1) throw std::invalid_argument("tile_images: need at least one image");
  if (tile_width <= 0 || tile_height <= 0)
    throw std::invalid_argument("tile_images: tile size " + std::to_string(tile_width) + "x" +
                                std::to_string(tile_height) + " must be positive");
  if (options.gap < 0 || options.margin < 0 || options.cols < 0)
    throw std::invalid_argument("tile_images: cols, gap and margin must not be negative");
  GridSize grid;
  grid.cols = options.cols > 0 ? options.cols
                               : static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  grid.cols = std::min(grid.cols, count);
  grid.rows = (count + grid.cols - 1) / grid.cols;
  grid.width = 2 * options.margin + grid.cols * tile_width + (grid.cols - 1) * options.gap;
  grid.height = 2 * options.margin + grid.rows * tile_height + (grid.rows - 1) * options.gap;
  return grid;
}

void blit_rgba(std::span<std::uint8_t> dst, int dst_width, int dst_height,
               std::span<const std::uint8_t> src, int src_width, int src_height, int x, int y) {
  if (dst.size() !=
          static_cast<std::size_t>(dst_width) * static_cast<std::size_t>(dst_height) * 4 ||
      src.size() != static_cast<std::size_t>(src_width) * static_cast<std::size_t>(src_height) * 4)
    throw std::invalid_argument("blit_rgba: buffer size does not match the image size");
  const int x0 = std::max(0, x), x1 = std::min(dst_width, x + src_width);
  const int y0 = std::max(0, y), y1 = std::min(dst_height, y + src_height);
  if (x0 >= x1 || y0 >= y1) return;
  const std::size_t row_bytes = static_cast<std::size_t>(x1 - x0) * 4;
  for (int row = y0; row < y1; ++row) {
    const std::size_t d = (static_cast<std::size_t>(row) * dst_width + x0) * 4;
    const std::size_t s = (static_cast<std::size_t>(row - y) * src_width + (x0 - x)) * 4;
    std::memcpy(dst.data() + d, src.data() + s, row_bytes);
  }
}

TiledImage tile_images(std::span<const std::span<const std::uint8_t>> tiles, int tile_width,
                       int tile_height, const TilingOptions& options) {
  const GridSize grid =
      tiled_size(static_cast<int>(tiles.size()), tile_width, tile_height, options);
  const std::size_t tile_bytes =
      static_cast<std::size_t>(tile_width) * static_cast<std::size_t>(tile_height) * 4;
  for (std::size_t i = 0; i < tiles.size(); ++i)
    if (tiles[i].size() != tile_bytes)
      throw std::invalid_argument("tile_images: image " + std::to_string(i) + " has " +
                                  std::to_string(tiles[i].size()) + " bytes, expected " +
                                  std::to_string(tile_bytes) + " (" + std::to_string(tile_width) +
                                  "x" + std::to_string(tile_height) + " RGBA)");
  TiledImage out;
  out.width = grid.width;
  out.height = grid.height;
  out.cols = grid.cols;
  out.rows = grid.rows;
  out.pixels.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4);
  for (std::size_t p = 0; p < out.pixels.size(); p += 4)
    std::memcpy(out.pixels.data() + p, options.background.data(), 4);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const int col = static_cast<int>(i) % grid.cols;
    const int row = static_cast<int>(i) / grid.cols;
    blit_rgba(out.pixels, out.width, out.height, tiles[i], tile_width, tile_height,
              options.margin + col * (tile_width + options.gap),
              options.margin + row * (tile_height + options.gap));
  }
  return out;
}

}  // namespace epviz::io
