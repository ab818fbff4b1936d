#pragma once
// Checking one job's drawn frames against its goldens, or making them its
// goldens (`epviz check --update`): the results per frame with the time each
// took, the report images, why failing frames fail (what_changed.hpp), the
// warning when the goldens came from another renderer or font. Frames come in
// as images, one at a time; drawing them is the caller's business.
#include <chrono>
#include <cstddef>
#include <cstdint>
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
  RenderEnvironment environment;     // what draws this run's frames
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

class JobChecker;

// One job's frames, taken one at a time as they are drawn and checked (or,
// with --update, encoded) at once, so that memory does not grow with the
// number of frames: a frame is compared and let go, and an update keeps only
// compressed PNGs until it knows the simulation did not fail.
class JobFrames {
 public:
  // The next frame, in the order of job.frames.
  void add(const ImageView& image);
  // The outcome, once every frame is added, or fewer when the simulation
  // failed (`failure` says why).
  JobOutcome finish(const std::optional<std::string>& failure);

 private:
  friend class JobChecker;
  JobFrames(JobChecker& checker, const GoldenJob& job, std::size_t index, bool update);

  JobChecker& checker_;
  const GoldenJob& job_;
  std::size_t index_;
  bool update_;
  std::size_t added_ = 0;
  JobOutcome out_;
  std::optional<GoldenRecord> record_;           // golden.json as the check began (comparing only)
  std::chrono::steady_clock::time_point last_;   // when the previous frame was done
  std::vector<int> missing_;                     // frames without a golden
  std::vector<std::vector<std::uint8_t>> pngs_;  // --update: the goldens to write
};

// One per thread (it keeps SSIM buffers between frames).
class JobChecker {
 public:
  explicit JobChecker(CheckSettings settings);

  // The frames of `job` to come; `index` is the job's place in the run, which
  // keeps report image names apart. `update`: make them the goldens (none
  // when the simulation failed) instead of comparing. `job` must outlive it.
  JobFrames start(const GoldenJob& job, std::size_t index, bool update);

  // All at once: `images` holds the frames drawn, in the order of
  // job.frames; fewer than asked for when the simulation failed.
  JobOutcome compare(const GoldenJob& job, std::size_t index, std::span<const ImageView> images,
                     const std::optional<std::string>& failure);
  JobOutcome update(const GoldenJob& job, std::span<const ImageView> images,
                    const std::optional<std::string>& failure);

 private:
  friend class JobFrames;
  void compare_frame(const GoldenJob& job, std::size_t index, const ImageView& actual,
                     FrameResult& r, std::vector<int>& missing);
  std::string report_image(const GoldenJob& job, std::size_t index, int frame,
                           const char* kind) const;

  CheckSettings settings_;
  FrameJudge judge_;
};

}  // namespace epviz::check
