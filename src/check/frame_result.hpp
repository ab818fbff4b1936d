#pragma once
// The outcome of checking one frame of one job, as the console, the JUnit
// file and the HTML report show it.
#include <filesystem>
#include <string>
#include <vector>

namespace epviz::check {

struct FrameResult {
  std::string job;  // the job file as the user named it
  int frame = 0;
  bool passed = false;
  std::string measure;  // "0.02 % pixels differ (limit 1 %)", "SSIM 0.9991 (limit 0.99)"
  std::string problem;  // why it failed when no measure applies ("no golden ...")
  // Images for the report, relative to the report directory (empty: none).
  std::string golden_image, actual_image, diff_image;
  // Drawing (with the simulation up to it) and checking the frame.
  double seconds = 0.0;

  // "PASS job frame 0: ..." / "FAIL job frame 0: ...".
  std::string line() const;
  // The failure message (measure or problem) for reports.
  std::string message() const;
};

// "3 passed, 1 failed".
std::string summary(const std::vector<FrameResult>& results);
// After an update: "3 goldens written" or "3 goldens written, 1 failed".
std::string update_summary(const std::vector<FrameResult>& results, int goldens_written);
// Whether the run passes (exit 0).
bool all_passed(const std::vector<FrameResult>& results);

}  // namespace epviz::check
