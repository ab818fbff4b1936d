#include "check/tolerance.hpp"

#include <cmath>
#include <cstdio>

#include "check/ssim.hpp"
#include "io/bad_input.hpp"
#include "io/printable.hpp"

namespace epviz::check {

std::string number_text(double value) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", value);
  return s;
}

Tolerance tolerance_from(const std::string& metric, std::optional<double> threshold,
                         std::optional<double> max_differing) {
  Tolerance t;
  if (metric == "ssim")
    t.metric = Metric::ssim;
  else if (metric != "pixel")
    throw io::BadInput("--metric: unknown metric '" + io::printable(metric) +
                       "' (allowed: pixel, ssim)");
  if (t.metric == Metric::pixel) {
    if (threshold) {
      if (!(*threshold >= 0 && *threshold <= 255 && std::floor(*threshold) == *threshold))
        throw io::BadInput("--threshold: expected an integer from 0 to 255, got '" +
                           number_text(*threshold) + "'");
      t.max_channel_difference = int(*threshold);
    }
    if (max_differing) {
      if (!(*max_differing >= 0 && *max_differing <= 100))
        throw io::BadInput("--max-differing: expected a percentage of pixels from 0 to 100, got '" +
                           number_text(*max_differing) + "'");
      t.max_differing_percent = *max_differing;
    }
    return t;
  }
  if (max_differing)
    throw io::BadInput(
        "--max-differing: applies to --metric pixel only (--metric ssim takes --threshold, the "
        "lowest SSIM that passes)");
  if (threshold) {
    if (!(*threshold > 0 && *threshold <= 1))
      throw io::BadInput(
          "--threshold: with --metric ssim, expected the lowest SSIM that passes, above 0 and at "
          "most 1, got '" +
          number_text(*threshold) + "'");
    t.min_ssim = *threshold;
  }
  return t;
}

std::string Tolerance::describe() const {
  if (metric == Metric::pixel)
    return "a pixel differs when a channel differs by more than " +
           std::to_string(max_channel_difference) + "/255; a frame fails when more than " +
           number_text(max_differing_percent) + " % of its pixels differ";
  const std::string window = std::to_string(kSsimWindow);
  return "a frame fails when its SSIM (grey level, " + window + "x" + window +
         " windows) is below " + number_text(min_ssim);
}

}  // namespace epviz::check
