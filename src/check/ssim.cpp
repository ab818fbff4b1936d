#include "check/ssim.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace epviz::check {
namespace {

// Grey level x 1000 (0.299, 0.587, 0.114 as integers): every sum below is an
// exact integer. A window's sums stay under 2^53 (64 pixels of 255000^2), so
// they also convert to double exactly.
void grey_row(int width, const std::uint8_t* rgba, std::int32_t* grey) {
  for (int x = 0; x < width; ++x)
    grey[x] = 299 * rgba[4 * x] + 587 * rgba[4 * x + 1] + 114 * rgba[4 * x + 2];
}

}  // namespace

// Adds (sign +1) or removes (sign -1) the band row `row_in_band` to the column sums.
void SsimWorkspace::add_row(int width, int row_in_band, const std::uint8_t* a,
                            const std::uint8_t* b, std::int64_t sign) {
  std::int32_t* ga = &grey_a_[std::size_t(row_in_band) * width];
  std::int32_t* gb = &grey_b_[std::size_t(row_in_band) * width];
  if (sign > 0) {
    grey_row(width, a, ga);
    grey_row(width, b, gb);
  }
  for (int x = 0; x < width; ++x) {
    const std::int64_t u = ga[x], v = gb[x];
    col_x_[x] += sign * u;
    col_y_[x] += sign * v;
    col_xx_[x] += sign * u * u;
    col_yy_[x] += sign * v * v;
    col_xy_[x] += sign * u * v;
  }
}

// The SSIM of every window in the band's rows, summed.
double SsimWorkspace::row_of_windows(int width, int wx, int wy) {
  for (int x = 0; x < width; ++x) {
    run_x_[x + 1] = run_x_[x] + col_x_[x];
    run_y_[x + 1] = run_y_[x] + col_y_[x];
    run_xx_[x + 1] = run_xx_[x] + col_xx_[x];
    run_yy_[x + 1] = run_yy_[x] + col_yy_[x];
    run_xy_[x + 1] = run_xy_[x] + col_xy_[x];
  }
  // The formula of ssim.hpp multiplied through by (1000 n)^2 (n pixels a
  // window), so that means and (co)variances are the integers below.
  const std::int64_t n = std::int64_t(wx) * wy;
  const double scale = 1000.0 * double(n) * 1000.0 * double(n);
  const double c1 = (0.01 * 255) * (0.01 * 255) * scale, c2 = (0.03 * 255) * (0.03 * 255) * scale;
  double total = 0.0;
  for (int i = 0; i + wx <= width; ++i) {
    const std::int64_t sx = run_x_[i + wx] - run_x_[i], sy = run_y_[i + wx] - run_y_[i];
    const std::int64_t sxx = run_xx_[i + wx] - run_xx_[i], syy = run_yy_[i + wx] - run_yy_[i];
    const std::int64_t sxy = run_xy_[i + wx] - run_xy_[i];
    const std::int64_t means = 2 * sx * sy, squares = sx * sx + sy * sy;
    const std::int64_t covariance = 2 * (n * sxy - sx * sy);
    const std::int64_t variances = n * sxx - sx * sx + n * syy - sy * sy;
    total += (double(means) + c1) * (double(covariance) + c2) /
             ((double(squares) + c1) * (double(variances) + c2));
  }
  return total;
}

double SsimWorkspace::ssim(int width, int height, std::span<const std::uint8_t> a,
                           std::span<const std::uint8_t> b) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("SSIM of an empty image");
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  if (a.size() != pixels * 4 || b.size() != pixels * 4)
    throw std::invalid_argument("image buffers do not hold " + std::to_string(width) + "x" +
                                std::to_string(height) + " RGBA pixels");
  const int wx = std::min(kSsimWindow, width), wy = std::min(kSsimWindow, height);
  // assign() reuses the capacity of earlier calls.
  grey_a_.assign(std::size_t(wy) * width, 0);
  grey_b_.assign(std::size_t(wy) * width, 0);
  for (auto* col : {&col_x_, &col_y_, &col_xx_, &col_yy_, &col_xy_}) col->assign(width, 0);
  for (auto* run : {&run_x_, &run_y_, &run_xx_, &run_yy_, &run_xy_}) run->assign(width + 1, 0);

  // A band of wy rows slides down the image: the row entering is added to the
  // column sums, the row leaving (kept in the band) taken out.
  const std::size_t row_bytes = std::size_t(width) * 4;
  double total = 0.0;
  for (int y = 0; y < height; ++y) {
    const int slot = y % wy;
    if (y >= wy) add_row(width, slot, nullptr, nullptr, -1);
    add_row(width, slot, &a[y * row_bytes], &b[y * row_bytes], +1);
    if (y + 1 >= wy) total += row_of_windows(width, wx, wy);
  }
  const double windows = double(width - wx + 1) * double(height - wy + 1);
  return total / windows;
}

double ssim(int width, int height, std::span<const std::uint8_t> a,
            std::span<const std::uint8_t> b) {
  SsimWorkspace workspace;
  return workspace.ssim(width, height, a, b);
}

}  // namespace epviz::check
