#include "check/ssim.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace epviz::check {
namespace {

// The loops below in two builds, chosen once when the program loads: AVX2
// (four doubles a register) where the CPU has it, SSE2 (two, the x86-64
// baseline the package is built for) elsewhere. Both give the same values,
// the same operations lane by lane (no FMA: nothing is contracted). GCC
// only: the clang builds (the sanitizer pass) keep the SSE2 loops alone, so
// that the tests run those too.
#if defined(__x86_64__) && defined(__ELF__) && !defined(__clang__)
#define EPVIZ_SSIM_CLONES [[gnu::target_clones("avx2", "default")]]
#else
#define EPVIZ_SSIM_CLONES
#endif

// Grey level x 1000 (0.299, 0.587, 0.114 as integers), so that every sum
// below is an integer. The largest, n * sum(x^2) for a window of n = 64
// pixels, stays under 2^48, so doubles hold the sums, and the means and
// (co)variances made of them, exactly. Doubles rather than 64-bit integers:
// SSE2 has no 64-bit multiply, two doubles share a vector register, and
// the division needs them as doubles anyway.
double grey(const std::uint8_t* rgba) {
  return double(299 * rgba[0] + 587 * rgba[1] + 114 * rgba[2]);
}

// out[i] = in[i] + ... + in[i + w - 1] for i + w <= width. A window of 8 in
// three passes of pairs (1 + 1, 2 + 2, 4 + 4) rather than seven additions,
// and not as running sums, which chain each window on the one before and so
// cannot be shared out among vector lanes.
EPVIZ_SSIM_CLONES void window_sums(int width, int w, const double* __restrict in,
                                   double* __restrict out) {
  if (w == kSsimWindow) {
    for (int i = 0; i + 1 < width; ++i) out[i] = in[i] + in[i + 1];
    for (int i = 0; i + 3 < width; ++i) out[i] = out[i] + out[i + 2];
    for (int i = 0; i + 7 < width; ++i) out[i] = out[i] + out[i + 4];
    return;
  }
  for (int i = 0; i + w <= width; ++i) {
    double s = 0;
    for (int k = 0; k < w; ++k) s += in[i + k];
    out[i] = s;
  }
}

// Per column, sums over the band's rows of x, y, x^2, y^2 and x y.
struct ColumnSums {
  double* __restrict x, * __restrict y, * __restrict xx, * __restrict yy, * __restrict xy;
};

// The column sums with the band's row (old_u, old_v) taken out and the
// image row (a, b) put in, whose grey levels then replace it in the band.
EPVIZ_SSIM_CLONES void update_columns(int width, const std::uint8_t* __restrict a,
                                      const std::uint8_t* __restrict b, double* __restrict old_u,
                                      double* __restrict old_v, ColumnSums c) {
  for (int i = 0; i < width; ++i) {
    const double ou = old_u[i], ov = old_v[i];
    const double u = grey(a + 4 * i), v = grey(b + 4 * i);
    c.x[i] += u - ou;
    c.y[i] += v - ov;
    c.xx[i] += u * u - ou * ou;
    c.yy[i] += v * v - ov * ov;
    c.xy[i] += u * v - ou * ov;
    old_u[i] = u;
    old_v[i] = v;
  }
}

// Per window, sums over its pixels of x, y, x^2, y^2 and x y.
struct WindowSums {
  const double* __restrict x, * __restrict y, * __restrict xx, * __restrict yy, * __restrict xy;
};

// Adds the SSIM of `count` windows of n pixels each, from their sums, to
// total[]: the formula of ssim.hpp multiplied through by (1000 n)^2, so that
// means and (co)variances are the integers below. Summed per window column,
// not along the row: one vector lane per column, and no reordered
// floating-point sum for the compiler to refuse.
EPVIZ_SSIM_CLONES void add_window_ssims(int count, double n, WindowSums s,
                                        double* __restrict total) {
  const double scale = 1000.0 * n * 1000.0 * n;
  const double c1 = (0.01 * 255) * (0.01 * 255) * scale, c2 = (0.03 * 255) * (0.03 * 255) * scale;
  for (int i = 0; i < count; ++i) {
    const double means = 2 * s.x[i] * s.y[i], squares = s.x[i] * s.x[i] + s.y[i] * s.y[i];
    const double covariance = 2 * (n * s.xy[i] - s.x[i] * s.y[i]);
    const double variances = n * s.xx[i] - s.x[i] * s.x[i] + n * s.yy[i] - s.y[i] * s.y[i];
    total[i] += (means + c1) * (covariance + c2) / ((squares + c1) * (variances + c2));
  }
}

}  // namespace

void SsimWorkspace::reset(int width, int band_rows) {
  // assign() reuses the capacity of earlier calls: nothing is allocated once
  // the widest frame has been seen.
  band_a_.assign(std::size_t(band_rows) * width, 0.0);
  band_b_.assign(std::size_t(band_rows) * width, 0.0);
  for (auto* row : {&col_x_, &col_y_, &col_xx_, &col_yy_, &col_xy_, &window_x_, &window_y_,
                    &window_xx_, &window_yy_, &window_xy_, &ssim_sum_})
    row->assign(width, 0.0);
}

// The band's row `slot` leaves the column sums and the image row (a, b)
// takes its place.
void SsimWorkspace::replace_row(int width, int slot, const std::uint8_t* a, const std::uint8_t* b) {
  const std::size_t band = std::size_t(slot) * width;
  update_columns(width, a, b, &band_a_[band], &band_b_[band],
                 {col_x_.data(), col_y_.data(), col_xx_.data(), col_yy_.data(), col_xy_.data()});
}

// Adds the SSIM of each window whose bottom row is the band's newest to the
// per-column totals.
void SsimWorkspace::add_row_of_windows(int width, int wx, int wy) {
  window_sums(width, wx, col_x_.data(), window_x_.data());
  window_sums(width, wx, col_y_.data(), window_y_.data());
  window_sums(width, wx, col_xx_.data(), window_xx_.data());
  window_sums(width, wx, col_yy_.data(), window_yy_.data());
  window_sums(width, wx, col_xy_.data(), window_xy_.data());
  add_window_ssims(
      width - wx + 1, double(wx) * double(wy),
      {window_x_.data(), window_y_.data(), window_xx_.data(), window_yy_.data(), window_xy_.data()},
      ssim_sum_.data());
}

double SsimWorkspace::ssim(int width, int height, std::span<const std::uint8_t> a,
                           std::span<const std::uint8_t> b) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("SSIM of an empty image");
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  if (a.size() != pixels * 4 || b.size() != pixels * 4)
    throw std::invalid_argument("image buffers do not hold " + std::to_string(width) + "x" +
                                std::to_string(height) + " RGBA pixels");
  const int wx = std::min(kSsimWindow, width), wy = std::min(kSsimWindow, height);
  reset(width, wy);

  // A band of wy rows slides down the image: the row entering replaces the
  // one leaving in the column sums (rows of zeros while the band fills).
  const std::size_t row_bytes = std::size_t(width) * 4;
  for (int y = 0; y < height; ++y) {
    replace_row(width, y % wy, &a[y * row_bytes], &b[y * row_bytes]);
    if (y + 1 >= wy) add_row_of_windows(width, wx, wy);
  }
  double total = 0.0;
  for (int i = 0; i + wx <= width; ++i) total += ssim_sum_[i];
  const double windows = double(width - wx + 1) * double(height - wy + 1);
  return total / windows;
}

double ssim(int width, int height, std::span<const std::uint8_t> a,
            std::span<const std::uint8_t> b) {
  SsimWorkspace workspace;
  return workspace.ssim(width, height, a, b);
}

}  // namespace epviz::check
