#include "check/frame_verdict.hpp"

#include <cstdio>
#include <stdexcept>

namespace epviz::check {

std::string percent_text(double fraction) {
  const double p = 100.0 * fraction;
  char s[32];
  if (p == 0.0)
    std::snprintf(s, sizeof s, "0");
  else if (p < 0.01)
    std::snprintf(s, sizeof s, "%.2g", p);
  else
    std::snprintf(s, sizeof s, "%.2f", p);
  return s;
}

Verdict FrameJudge::judge(const ImageView& actual, const ImageView& golden) {
  if (actual.width != golden.width || actual.height != golden.height)
    throw std::invalid_argument("cannot judge a " + std::to_string(actual.width) + "x" +
                                std::to_string(actual.height) + " frame against a " +
                                std::to_string(golden.width) + "x" + std::to_string(golden.height) +
                                " golden");
  Verdict v;
  char m[160];
  if (tolerance_.metric == Metric::pixel) {
    v.pixels = compare_pixels(actual.width, actual.height, actual.rgba, golden.rgba,
                              tolerance_.max_channel_difference);
    v.passed = 100.0 * v.pixels.fraction_differing() <= tolerance_.max_differing_percent;
    std::snprintf(m, sizeof m, "%s %% pixels differ (limit %g %%)",
                  percent_text(v.pixels.fraction_differing()).c_str(),
                  tolerance_.max_differing_percent);
  } else {
    v.ssim = ssim_.ssim(actual.width, actual.height, actual.rgba, golden.rgba);
    v.passed = v.ssim >= tolerance_.min_ssim;
    std::snprintf(m, sizeof m, "SSIM %.5f (limit %g)", v.ssim, tolerance_.min_ssim);
  }
  v.measure = m;
  return v;
}

}  // namespace epviz::check
