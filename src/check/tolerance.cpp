#include "check/tolerance.hpp"

#include <cstdio>

#include "check/ssim.hpp"

namespace epviz::check {

std::string number_text(double value) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", value);
  return s;
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
