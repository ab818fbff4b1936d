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
//
// The window sums are exact (integers), so an image compared with itself
// gives exactly 1 and `--threshold 1` passes it.
#include <cstdint>
#include <span>
#include <vector>

namespace epviz::check {

constexpr int kSsimWindow = 8;

// The buffers one SSIM needs, kept between calls so that checking frame
// after frame allocates nothing once the widest frame has been seen. Its
// memory grows with the image width only (a band of window-high rows, about
// 280 kB at 1280 pixels). Not for use by two threads at once.
class SsimWorkspace {
 public:
  // Throws std::invalid_argument when a buffer does not hold width x height
  // pixels or the image is empty.
  double ssim(int width, int height, std::span<const std::uint8_t> a,
              std::span<const std::uint8_t> b);

 private:
  void reset(int width, int band_rows);
  void replace_row(int width, int slot, const std::uint8_t* a, const std::uint8_t* b);
  void add_row_of_windows(int width, int wx, int wy);

  // Grey levels x 1000 of the band's rows (image row y in slot y % band rows).
  std::vector<double> band_a_, band_b_;
  // Per column, sums over the band's rows of x, y, x^2, y^2 and x y.
  std::vector<double> col_x_, col_y_, col_xx_, col_yy_, col_xy_;
  // The same summed over each window's columns (index: the window's left column).
  std::vector<double> window_x_, window_y_, window_xx_, window_yy_, window_xy_;
  // Per window column, the SSIM of its windows so far.
  std::vector<double> ssim_sum_;
};

// One SSIM with a workspace of its own (allocates).
double ssim(int width, int height, std::span<const std::uint8_t> a,
            std::span<const std::uint8_t> b);

}  // namespace epviz::check
