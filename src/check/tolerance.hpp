#pragma once
// How close a frame must be to its golden to pass: the metric and its limits.
// The default numbers live here only; `epviz check --help` prints them from
// here and a test holds docs/ci.md to them.
#include <optional>
#include <string>

namespace epviz::check {

// Chosen from measurement (docs/ci.md, "How the defaults were chosen").
constexpr int kDefaultChannelThreshold = 1;          // of 255
constexpr double kDefaultMaxDifferingPercent = 0.5;  // of the frame's pixels
constexpr double kDefaultMinSsim = 0.999;

enum class Metric { pixel, ssim };

struct Tolerance {
  Metric metric = Metric::pixel;
  // pixel: a pixel differs when a channel differs by more than this (0..255);
  // the frame fails when more than max_differing_percent of its pixels differ.
  // The diff image of a failing frame marks pixels by this threshold, whatever the metric.
  int max_channel_difference = kDefaultChannelThreshold;
  double max_differing_percent = kDefaultMaxDifferingPercent;
  // ssim: the frame fails when its SSIM is below this (0 < min_ssim <= 1).
  double min_ssim = kDefaultMinSsim;

  // One sentence for reports: "a pixel differs when ...; a frame fails when ...".
  std::string describe() const;
};

// The tolerance of `epviz check --metric M --threshold T --max-differing P`
// (nullopt: the option was not given). Throws io::BadInput naming the option,
// the value and what is allowed: an unknown metric, a pixel threshold that is
// not an integer 0..255, a percentage outside 0..100, a lowest SSIM outside
// (0, 1], --max-differing with --metric ssim.
Tolerance tolerance_from(const std::string& metric, std::optional<double> threshold,
                         std::optional<double> max_differing);

// A number as the help text and the reports print it ("0.5", "0.999", "1").
std::string number_text(double value);

}  // namespace epviz::check
