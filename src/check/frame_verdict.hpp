#pragma once
// The verdict on one frame against its golden image, by a tolerance: the one
// pass/fail rule behind `epviz check` and epviz's own snapshot tests.
#include <cstdint>
#include <span>
#include <string>

#include "check/image_compare.hpp"
#include "check/ssim.hpp"
#include "check/tolerance.hpp"

namespace epviz::check {

// A top-down RGBA8 image someone else owns (width * height * 4 bytes).
struct ImageView {
  int width = 0, height = 0;
  std::span<const std::uint8_t> rgba;
};

struct Verdict {
  bool passed = false;
  std::string measure;     // "0.02 % pixels differ (limit 0.5 %)", "SSIM 0.99910 (limit 0.999)"
  PixelComparison pixels;  // pixel metric: the counts behind the measure
  double ssim = 0.0;       // ssim metric: the value behind the measure
};

// Judges frames one after another; keeps the SSIM buffers between frames, so
// use one per thread.
class FrameJudge {
 public:
  explicit FrameJudge(const Tolerance& tolerance) : tolerance_(tolerance) {}
  const Tolerance& tolerance() const { return tolerance_; }

  // Both images the same size (throws std::invalid_argument otherwise).
  Verdict judge(const ImageView& actual, const ImageView& golden);

 private:
  Tolerance tolerance_;
  SsimWorkspace ssim_;
};

// "0", "0.0012", "3.47": a fraction as a percentage, small ones still visible.
std::string percent_text(double fraction);

}  // namespace epviz::check
