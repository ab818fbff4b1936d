#pragma once
// Checking one job's drawn frames against its goldens, or making them its
// goldens (`epviz check --update`): the results per frame, the report images,
// the warning when the goldens came from another renderer. Frames come in as
// images; drawing them is the caller's business.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "check/frame_result.hpp"
#include "check/frame_verdict.hpp"
#include "check/golden_files.hpp"

namespace epviz::check {

struct CheckSettings {
  Tolerance tolerance;
  std::filesystem::path report_dir;  // empty: no report images
  RendererInfo renderer;             // what draws this run's frames
  std::string epviz_version;         // recorded in golden.json
  // The command that (re)creates the goldens of `frames` of `job`, named in
  // the lines of missing or mis-sized goldens.
  std::function<std::string(const GoldenJob& job, const std::vector<int>& frames)> update_command;
};

struct JobOutcome {
  std::vector<FrameResult> results;   // one per frame checked, in order
  std::vector<std::string> lines;     // lines to print after the results ("UPDATED ...")
  std::vector<std::string> warnings;  // lines for stderr
  int goldens_written = 0;
};

// One per thread (it keeps SSIM buffers between frames).
class JobChecker {
 public:
  explicit JobChecker(CheckSettings settings);

  // `images` holds the frames drawn, in the order of job.frames; fewer than
  // asked for when the simulation failed (`failure` says why). `index` is the
  // job's place in the run, which keeps report image names apart.
  JobOutcome compare(const GoldenJob& job, std::size_t index, std::span<const ImageView> images,
                     const std::optional<std::string>& failure);
  // Writes the images as goldens; none when the simulation failed.
  JobOutcome update(const GoldenJob& job, std::span<const ImageView> images,
                    const std::optional<std::string>& failure) const;

 private:
  void compare_frame(const GoldenJob& job, std::size_t index, const ImageView& actual,
                     FrameResult& r, std::vector<int>& missing);
  std::string report_image(const GoldenJob& job, std::size_t index, int frame,
                           const char* kind) const;

  CheckSettings settings_;
  FrameJudge judge_;
};

}  // namespace epviz::check
