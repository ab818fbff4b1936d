#include "check/ssim.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace epviz::check {
namespace {

std::vector<double> grey_levels(std::span<const std::uint8_t> rgba, std::size_t pixels) {
  std::vector<double> g(pixels);
  for (std::size_t p = 0; p < pixels; ++p)
    g[p] = 0.299 * rgba[p * 4] + 0.587 * rgba[p * 4 + 1] + 0.114 * rgba[p * 4 + 2];
  return g;
}

// Summed-area table with a zero row and column in front: S(x, y) is the sum of
// v over [0, x) x [0, y). Makes every window sum four look-ups, so the SSIM of
// a 720p frame costs a few passes over it instead of 64 per pixel.
class SummedArea {
 public:
  SummedArea(int width, int height, const std::vector<double>& v)
      : w_(width + 1), s_(std::size_t(w_) * (height + 1)) {
    for (int y = 0; y < height; ++y) {
      double row = 0.0;
      for (int x = 0; x < width; ++x) {
        row += v[std::size_t(y) * width + x];
        s_[std::size_t(y + 1) * w_ + x + 1] = s_[std::size_t(y) * w_ + x + 1] + row;
      }
    }
  }
  double window(int x, int y, int wx, int wy) const {
    return at(x + wx, y + wy) - at(x, y + wy) - at(x + wx, y) + at(x, y);
  }

 private:
  double at(int x, int y) const { return s_[std::size_t(y) * w_ + x]; }
  int w_;
  std::vector<double> s_;
};

}  // namespace

double ssim(int width, int height, std::span<const std::uint8_t> a,
            std::span<const std::uint8_t> b) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("SSIM of an empty image");
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  if (a.size() != pixels * 4 || b.size() != pixels * 4)
    throw std::invalid_argument("image buffers do not hold " + std::to_string(width) + "x" +
                                std::to_string(height) + " RGBA pixels");
  const auto x = grey_levels(a, pixels), y = grey_levels(b, pixels);
  std::vector<double> xx(pixels), yy(pixels), xy(pixels);
  for (std::size_t p = 0; p < pixels; ++p) {
    xx[p] = x[p] * x[p];
    yy[p] = y[p] * y[p];
    xy[p] = x[p] * y[p];
  }
  const SummedArea sx(width, height, x), sy(width, height, y), sxx(width, height, xx),
      syy(width, height, yy), sxy(width, height, xy);
  const int wx = std::min(kSsimWindow, width), wy = std::min(kSsimWindow, height);
  const double n = double(wx) * wy;
  constexpr double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
  double total = 0.0;
  long windows = 0;
  for (int j = 0; j + wy <= height; ++j) {
    for (int i = 0; i + wx <= width; ++i) {
      const double mx = sx.window(i, j, wx, wy) / n, my = sy.window(i, j, wx, wy) / n;
      // Clamped at 0: the sums' rounding can make a flat window's variance a tiny negative.
      const double vx = std::max(0.0, sxx.window(i, j, wx, wy) / n - mx * mx);
      const double vy = std::max(0.0, syy.window(i, j, wx, wy) / n - my * my);
      const double cxy = sxy.window(i, j, wx, wy) / n - mx * my;
      total += (2 * mx * my + c1) * (2 * cxy + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2));
      ++windows;
    }
  }
  return total / double(windows);
}

}  // namespace epviz::check
