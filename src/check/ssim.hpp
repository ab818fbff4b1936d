#pragma once
// Structural similarity (SSIM, Wang, Bovik, Sheikh & Simoncelli 2004) of two
// RGBA8 images, for goldens made on another renderer: antialiasing and
// rasterisation rules move edges by a fraction of a pixel, which a per-pixel
// threshold counts as differences while the structure stays the same.
//
// What epviz computes, exactly:
// - grey level L = 0.299 R + 0.587 G + 0.114 B (alpha ignored), 0..255;
// - every 8x8 window that lies inside the image (stride 1; a side shorter
//   than 8 pixels uses the whole side), uniform weights;
// - in each window, means, population variances and covariance (divided by
//   the window's pixel count), and
//     SSIM = (2 mx my + C1)(2 sxy + C2) / ((mx^2 + my^2 + C1)(sx^2 + sy^2 + C2))
//   with C1 = (0.01 * 255)^2 and C2 = (0.03 * 255)^2;
// - the mean over all windows. 1 means identical; lower is less similar.
#include <cstdint>
#include <span>

namespace epviz::check {

constexpr int kSsimWindow = 8;

// Throws std::invalid_argument when a buffer does not hold width x height pixels
// or the image is empty.
double ssim(int width, int height, std::span<const std::uint8_t> a,
            std::span<const std::uint8_t> b);

}  // namespace epviz::check
