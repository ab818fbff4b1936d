// check::ssim against a direct evaluation of the formula, window by window,
// on tiny images (the implementation slides integer column sums instead).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "check/ssim.hpp"
#include "test_images.hpp"

namespace epviz::check {
namespace {

using Image = TestImage;

Image noise(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> d(0, 255);
  Image im{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4)};
  for (std::size_t i = 0; i < im.rgba.size(); ++i)
    im.rgba[i] = i % 4 == 3 ? 255 : std::uint8_t(d(rng));
  return im;
}

// A smooth picture with an edge, so that shifts and blurs change structure.
Image picture(int w, int h) {
  Image im{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4, 255)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      auto* p = &im.rgba[(std::size_t(y) * w + x) * 4];
      p[0] = std::uint8_t(x * 255 / (w - 1));
      p[1] = std::uint8_t(x + y < (w + h) / 2 ? 30 : 220);
      p[2] = std::uint8_t((x * 7 + y * 13) % 256);
    }
  return im;
}

Image shifted(const Image& a, int dx) {
  Image b = a;
  for (int y = 0; y < a.h; ++y)
    for (int x = 0; x < a.w; ++x)
      for (int c = 0; c < 4; ++c)
        b.rgba[(std::size_t(y) * a.w + x) * 4 + c] =
            a.rgba[(std::size_t(y) * a.w + std::clamp(x - dx, 0, a.w - 1)) * 4 + c];
  return b;
}

Image blurred(const Image& a) {
  Image b = a;
  for (int y = 0; y < a.h; ++y)
    for (int x = 0; x < a.w; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0, n = 0;
        for (int j = -1; j <= 1; ++j)
          for (int i = -1; i <= 1; ++i) {
            const int xx = x + i, yy = y + j;
            if (xx < 0 || yy < 0 || xx >= a.w || yy >= a.h) continue;
            sum += a.rgba[(std::size_t(yy) * a.w + xx) * 4 + c];
            ++n;
          }
        b.rgba[(std::size_t(y) * a.w + x) * 4 + c] = std::uint8_t(sum / n);
      }
  return b;
}

// The formula of ssim.hpp, evaluated directly: two-pass means and
// (co)variances in every window.
double direct_ssim(const Image& a, const Image& b) {
  const int wx = std::min(8, a.w), wy = std::min(8, a.h);
  const double n = double(wx) * wy, c1 = 2.55 * 2.55, c2 = 7.65 * 7.65;
  double total = 0;
  int windows = 0;
  for (int j = 0; j + wy <= a.h; ++j)
    for (int i = 0; i + wx <= a.w; ++i) {
      double mx = 0, my = 0;
      for (int y = j; y < j + wy; ++y)
        for (int x = i; x < i + wx; ++x) mx += a.grey(x, y), my += b.grey(x, y);
      mx /= n;
      my /= n;
      double vx = 0, vy = 0, cxy = 0;
      for (int y = j; y < j + wy; ++y)
        for (int x = i; x < i + wx; ++x) {
          const double dx = a.grey(x, y) - mx, dy = b.grey(x, y) - my;
          vx += dx * dx;
          vy += dy * dy;
          cxy += dx * dy;
        }
      vx /= n;
      vy /= n;
      cxy /= n;
      total += (2 * mx * my + c1) * (2 * cxy + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2));
      ++windows;
    }
  return total / windows;
}

double ssim_of(const Image& a, const Image& b) { return ssim(a.w, a.h, a.rgba, b.rgba); }

TEST(Ssim, OfAnImageWithItselfIsExactlyOne) {
  // Exactly: `epviz check --metric ssim --threshold 1` must pass identical frames.
  for (const auto& a :
       {disc_image(40, 30), disc_image(160, 120), picture(40, 30), noise(23, 17, 1)})
    EXPECT_EQ(ssim_of(a, a), 1.0) << a.w << "x" << a.h;
}

TEST(Ssim, AWorkspaceGivesTheSameAsAFreshOneForEveryFrameSize) {
  // Frames of different sizes through one workspace: nothing of the previous
  // frame (band rows, column sums) may leak into the next.
  SsimWorkspace workspace;
  const std::vector<std::pair<Image, Image>> frames = {
      {noise(30, 20, 8), noise(30, 20, 9)},
      {picture(12, 10), shifted(picture(12, 10), 1)},
      {noise(6, 5, 10), noise(6, 5, 11)},
      {noise(30, 20, 12), blurred(noise(30, 20, 12))}};
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& [a, b] : frames)
      EXPECT_NEAR(workspace.ssim(a.w, a.h, a.rgba, b.rgba), direct_ssim(a, b), 1e-9)
          << a.w << "x" << a.h << " pass " << pass;
}

TEST(Ssim, MatchesTheDirectFormula) {
  const auto a = noise(21, 13, 2), b = noise(21, 13, 3);
  EXPECT_NEAR(ssim_of(a, b), direct_ssim(a, b), 1e-9);
  EXPECT_LT(ssim_of(a, b), 0.2);  // independent noise has little structure in common
}

TEST(Ssim, DropsForAShiftedImage) {
  const auto a = picture(40, 30), b = shifted(a, 2);
  const double s = ssim_of(a, b);
  EXPECT_NEAR(s, direct_ssim(a, b), 1e-9);
  EXPECT_LT(s, 0.98);
  EXPECT_GT(s, 0.0);
}

TEST(Ssim, DropsForABlurredImage) {
  const auto a = noise(24, 20, 4), b = blurred(a);
  const double s = ssim_of(a, b);
  EXPECT_NEAR(s, direct_ssim(a, b), 1e-9);
  EXPECT_LT(s, 0.9);
}

TEST(Ssim, SidesShorterThanAWindowUseTheWholeSide) {
  const auto a = noise(5, 12, 5), b = noise(5, 12, 6);
  EXPECT_NEAR(ssim_of(a, b), direct_ssim(a, b), 1e-9);
}

TEST(Ssim, OfTwoFlatImagesIsTheRatioOfTheirMeans) {
  // No variance and no covariance: only the means' term is left,
  // (2 a b + C1) / (a^2 + b^2 + C1), with a and b the two grey levels.
  const double c1 = 2.55 * 2.55;
  for (const auto& [a, b] : {std::pair{40, 200}, std::pair{0, 255}, std::pair{128, 129}}) {
    const auto x = flat_image(19, 11, std::uint8_t(a), std::uint8_t(a), std::uint8_t(a));
    const auto y = flat_image(19, 11, std::uint8_t(b), std::uint8_t(b), std::uint8_t(b));
    EXPECT_NEAR(ssim_of(x, y), (2.0 * a * b + c1) / (double(a) * a + double(b) * b + c1), 1e-12)
        << a << " against " << b;
  }
}

TEST(Ssim, MatchesTheDirectFormulaAtEveryWidthAroundTheWindow) {
  // Widths from below one window to past two, so that rows end at every
  // position in a vector register and every window position is reached.
  for (int w = 1; w <= 19; ++w) {
    const auto a = noise(w, 10, unsigned(20 + w)), b = blurred(noise(w, 10, unsigned(40 + w)));
    EXPECT_EQ(ssim_of(a, a), 1.0) << "width " << w;
    EXPECT_NEAR(ssim_of(a, b), direct_ssim(a, b), 1e-9) << "width " << w;
  }
}

TEST(Ssim, MatchesTheDirectFormulaOnAFrameSizedPicture) {
  const auto a = picture(333, 97), b = blurred(shifted(a, 1));
  EXPECT_NEAR(ssim_of(a, b), direct_ssim(a, b), 1e-9);
}

TEST(Ssim, IgnoresAlpha) {
  auto a = picture(16, 16), b = a;
  for (std::size_t i = 3; i < b.rgba.size(); i += 4) b.rgba[i] = 0;
  EXPECT_NEAR(ssim_of(a, b), 1.0, 1e-12);
}

TEST(Ssim, RejectsBuffersOfTheWrongSize) {
  const auto a = picture(16, 16);
  EXPECT_THROW(ssim(16, 15, a.rgba, a.rgba), std::invalid_argument);
  EXPECT_THROW(ssim(0, 0, {}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace epviz::check
