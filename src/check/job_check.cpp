#include "check/job_check.hpp"

#include <algorithm>
#include <stdexcept>

#include "check/golden_record.hpp"
#include "check/what_changed.hpp"
#include "io/atomic_file.hpp"
#include "io/frame_names.hpp"
#include "io/png_reader.hpp"
#include "io/png_writer.hpp"
#include "io/printable.hpp"

namespace epviz::check {
namespace {

namespace fs = std::filesystem;

std::string size_text(std::int64_t width, std::int64_t height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

std::string failure_text(const std::optional<std::string>& failure) {
  return failure ? *failure : std::string("?");
}

}  // namespace

JobChecker::JobChecker(CheckSettings settings)
    : settings_(std::move(settings)), judge_(settings_.tolerance) {}

JobFrames JobChecker::start(const GoldenJob& job, std::size_t index, bool update) {
  return JobFrames(*this, job, index, update);
}

JobFrames::JobFrames(JobChecker& checker, const GoldenJob& job, std::size_t index, bool update)
    : checker_(checker),
      job_(job),
      index_(index),
      update_(update),
      last_(std::chrono::steady_clock::now()) {
  if (update_) return;
  record_ = read_golden_record(job.golden_dir / "golden.json");
  if (!record_) return;
  const auto differences = environment_differences(*record_, checker_.settings_.environment);
  if (differences.empty()) return;
  std::string warning = "epviz: warning: " + job.shown + ": goldens were made elsewhere: ";
  for (std::size_t k = 0; k < differences.size(); ++k) warning += (k ? "; " : "") + differences[k];
  out_.warnings.push_back(warning +
                          " (see docs/ci.md: --metric ssim, or re-baseline with --update)");
}

void JobFrames::add(const ImageView& image) {
  if (added_ >= job_.frames.size())
    throw std::logic_error(job_.shown + ": more frames drawn than the job checks");
  const int frame = job_.frames[added_++];
  if (update_) {
    pngs_.push_back(encode_golden_png(image));
    return;
  }
  FrameResult r;
  r.job = job_.shown;
  r.frame = frame;
  checker_.compare_frame(job_, index_, image, r, missing_);
  const auto now = std::chrono::steady_clock::now();
  r.seconds = std::chrono::duration<double>(now - last_).count();
  last_ = now;
  out_.results.push_back(std::move(r));
}

JobOutcome JobFrames::finish(const std::optional<std::string>& failure) {
  if (update_) {
    if (failure || added_ != job_.frames.size()) {
      FrameResult r;
      r.job = job_.shown;
      r.frame = job_.frames[std::min(added_, job_.frames.size() - 1)];
      r.problem = "numerical failure, no goldens written: " + failure_text(failure);
      out_.results.push_back(std::move(r));
      return std::move(out_);
    }
    const auto& s = checker_.settings_;
    const auto written = write_goldens(job_, pngs_, s.environment, s.epviz_version);
    for (std::size_t k = 0; k < written.size(); ++k)
      out_.lines.push_back("UPDATED " + job_.shown + " frame " + std::to_string(job_.frames[k]) +
                           ": " + written[k].string());
    out_.goldens_written = int(written.size());
    return std::move(out_);
  }
  for (std::size_t k = added_; k < job_.frames.size(); ++k) {
    FrameResult r;
    r.job = job_.shown;
    r.frame = job_.frames[k];
    r.problem = "numerical failure before this frame: " + failure_text(failure);
    out_.results.push_back(std::move(r));
  }
  const auto& s = checker_.settings_;
  if (!missing_.empty()) {
    const std::string cmd = s.update_command(job_, missing_);
    for (auto& r : out_.results)
      if (std::find(missing_.begin(), missing_.end(), r.frame) != missing_.end())
        r.problem += "; create it with: " + cmd;
  }
  // Frames compared and found different: say whether the job or the rendering changed.
  const auto differs = [](const FrameResult& r) { return !r.passed && !r.measure.empty(); };
  if (std::any_of(out_.results.begin(), out_.results.end(), differs)) {
    const std::string cause = failure_cause(record_, file_hash(job_.job_file), s.environment,
                                            s.update_command(job_, job_.frames));
    for (auto& r : out_.results)
      if (differs(r)) r.problem = r.problem.empty() ? cause : r.problem + "; " + cause;
  }
  return std::move(out_);
}

namespace {

JobOutcome all_at_once(JobFrames frames, std::span<const ImageView> images,
                       const std::optional<std::string>& failure) {
  for (const auto& image : images) frames.add(image);
  return frames.finish(failure);
}

}  // namespace

JobOutcome JobChecker::compare(const GoldenJob& job, std::size_t index,
                               std::span<const ImageView> images,
                               const std::optional<std::string>& failure) {
  return all_at_once(start(job, index, false), images, failure);
}

JobOutcome JobChecker::update(const GoldenJob& job, std::span<const ImageView> images,
                              const std::optional<std::string>& failure) {
  return all_at_once(start(job, 0, true), images, failure);
}

std::string JobChecker::report_image(const GoldenJob& job, std::size_t index, int frame,
                                     const char* kind) const {
  return std::to_string(index + 1) + "_" + job.job_file.stem().string() + "_" +
         io::frame_file_name(frame, job.frame_count, "frame_", std::string(".") + kind + ".png");
}

void JobChecker::compare_frame(const GoldenJob& job, std::size_t index, const ImageView& actual,
                               FrameResult& r, std::vector<int>& missing) {
  const fs::path golden_path = job.golden_path(r.frame);
  const fs::path& report = settings_.report_dir;
  auto keep_actual = [&] {
    if (report.empty()) return;
    r.actual_image = report_image(job, index, r.frame, "actual");
    io::write_png_rgba(report / r.actual_image, actual.width, actual.height, actual.rgba);
  };
  auto keep_golden = [&] {
    if (report.empty()) return;
    r.golden_image = report_image(job, index, r.frame, "golden");
    const fs::path copy = report / r.golden_image;
    if (std::error_code ec;
        (fs::copy_file(golden_path, copy, fs::copy_options::overwrite_existing, ec), ec))
      throw io::FileWriteError("--report: cannot write '" + io::printable(copy.string(), 200) +
                               "': " + ec.message());
  };
  auto damaged = [&](const char* why) {
    r.problem = "the golden " + golden_path.string() + " is damaged (" + why +
                "); re-baseline with: " + settings_.update_command(job, {r.frame});
    keep_actual();
  };
  // The header's size first: a golden is decoded only when it is the frame's
  // size, so a small file claiming a huge image costs nothing.
  const auto size = io::read_png_size(golden_path);
  std::error_code ec;
  if (!size && fs::exists(golden_path, ec)) return damaged("not a PNG");
  if (!size) {
    r.problem = "no golden " + golden_path.string();
    missing.push_back(r.frame);
    keep_actual();
    return;
  }
  if (size->width != actual.width || size->height != actual.height) {
    r.problem = "the golden " + golden_path.string() + " is " +
                size_text(size->width, size->height) + " but the frame is " +
                size_text(actual.width, actual.height) +
                "; re-baseline with: " + settings_.update_command(job, job.frames);
    keep_golden();
    keep_actual();
    return;
  }
  const auto golden = io::read_png_rgba(golden_path);
  if (!golden) return damaged("its image data cannot be decoded");
  const auto verdict = judge_.judge(actual, {golden->width, golden->height, golden->rgba});
  r.passed = verdict.passed;
  r.measure = verdict.measure;
  if (r.passed || report.empty()) return;
  keep_golden();
  keep_actual();
  r.diff_image = report_image(job, index, r.frame, "diff");
  io::write_png_rgba(report / r.diff_image, actual.width, actual.height,
                     diff_image(actual.width, actual.height, actual.rgba, golden->rgba,
                                settings_.tolerance.max_channel_difference));
}

}  // namespace epviz::check
