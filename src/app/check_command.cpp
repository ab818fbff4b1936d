#include "app/check_command.hpp"

#include <iostream>
#include <memory>
#include <mutex>
#include <optional>

#include "app/cli_values.hpp"
#include "app/gl_option.hpp"
#include "check/check_run.hpp"
#include "check/update_command.hpp"
#include "io/frame_range.hpp"
#include "io/output_paths.hpp"
#include "io/printable.hpp"
#include "job/job_list.hpp"
#include "job/job_plan.hpp"
#include "paint/frame_drawer.hpp"
#include "render/gl_choice.hpp"
#include "render/gui_overlay.hpp"

namespace epviz::app {
namespace {

struct CheckOptions {
  std::vector<std::string> jobs;
  std::string golden, frames, report, junit, threshold, max_differing, metric = "pixel", workers,
                                                                       gl;
  bool update = false;
};

// The render jobs to check, planned, in the order of check's goldens.
struct PlannedJob {
  job::RenderJob job;
  scene::ScenePlan plan;
};

// Draws with a GL context of its own. Painting takes turns with the other
// workers' sources under one lock: ImGui keeps its current context in one
// process-wide variable, so painters are made, used and destroyed under it.
class GlFrames : public check::FrameSource {
 public:
  GlFrames(const std::string& gl, const std::vector<PlannedJob>& jobs, std::mutex& paint_lock)
      : jobs_(jobs), paint_lock_(paint_lock) {
    // The font first: when it is missing, no context is left to close.
    environment_ = check::render_environment("", "", render::default_overlay_font());
    std::lock_guard lock(paint_lock_);
    context_ = render::GlChoice(gl).open();
    environment_.gl_renderer = context_->renderer();
    environment_.gl_version = context_->version();
  }
  ~GlFrames() override {
    std::lock_guard lock(paint_lock_);
    context_.reset();
  }
  const check::RenderEnvironment& environment() const override { return environment_; }

  std::optional<std::string> draw(
      std::size_t index, const check::GoldenJob& golden,
      const std::function<void(const check::ImageView&)>& on_frame) override {
    const auto& [job, plan] = jobs_[index];
    const auto destroy = [this](paint::FramePainter* p) {
      std::lock_guard lock(paint_lock_);
      delete p;
    };
    std::unique_ptr<paint::FramePainter, decltype(destroy)> painter(nullptr, destroy);
    {
      std::lock_guard lock(paint_lock_);
      painter.reset(new paint::FramePainter(*context_, job.scene.width, job.scene.height));
    }
    const auto failure = paint::draw_frames(plan, job.scene, golden.frames, *painter, &paint_lock_,
                                            [&](const render::RgbaImage& image) {
                                              on_frame({image.width, image.height, image.pixels});
                                            });
    return failure ? std::optional(failure->message()) : std::nullopt;
  }

 private:
  const std::vector<PlannedJob>& jobs_;
  std::mutex& paint_lock_;
  std::unique_ptr<render::GlContext> context_;
  check::RenderEnvironment environment_;
};

std::optional<double> number(const char* option, const std::string& text) {
  return text.empty() ? std::nullopt : std::optional(parse_number(option, text));
}

int run_check(const CheckOptions& o) {
  // Everything the user gave is checked before anything is drawn or written.
  check::RunSettings s;
  s.tolerance = check::tolerance_from(o.metric, number("--threshold", o.threshold),
                                      number("--max-differing", o.max_differing));
  s.workers = o.workers.empty() ? 1 : int(parse_integer("-j", o.workers, 1, 64));
  check::check_output_paths(o.report, o.junit);
  (void)render::GlChoice(o.gl);
  const io::FifoReaderCheck junit_reader("--junit", o.junit);
  const auto ranges = io::parse_frame_ranges(o.frames);
  std::vector<PlannedJob> jobs;
  std::vector<check::GoldenJob> goldens;
  for (auto& [job, shown] : job::render_jobs_in(o.jobs)) {
    auto plan = job::plan_job(job);
    goldens.push_back(check::golden_job(shown, job.file, o.golden, plan.frames, job.scene.width,
                                        job.scene.height, ranges, o.update));
    jobs.push_back({std::move(job), std::move(plan)});
  }
  check::refuse_shared_golden_dirs(goldens);
  // --junit must not replace a job or a golden it checks (io/output_paths.hpp).
  io::NamedPaths inputs;
  for (const auto& g : goldens) {
    inputs.emplace_back("the job " + io::printable(g.shown), g.job_file.string());
    inputs.emplace_back("a golden of " + io::printable(g.shown),
                        (g.golden_dir / "golden.json").string());
    for (const int frame : g.frames)
      inputs.emplace_back("a golden of " + io::printable(g.shown), g.golden_path(frame).string());
  }
  io::require_separate_files(inputs, {{"--junit", o.junit}});
  if (!o.report.empty() && !o.update) io::make_output_folder("--report", o.report);

  s.update = o.update;
  s.report_dir = o.report;
  s.junit = o.junit;
  s.epviz_version = EPVIZ_VERSION;
  s.update_command = [&o](const check::GoldenJob& job, const std::vector<int>& frames) {
    return check::update_command(job.shown, frames, o.golden, o.gl);
  };
  std::mutex paint_lock;
  return check::run_checks(
      goldens, s, [&] { return std::make_unique<GlFrames>(o.gl, jobs, paint_lock); }, std::cout,
      std::cerr);
}

}  // namespace

std::function<int()> add_check_command(cli::Command app) {
  auto o = std::make_shared<CheckOptions>();
  cli::Command cmd = app.add_subcommand(
      "check", "Render frames of jobs in memory and compare them with goldens (for CI)");
  cmd.add_option("jobs", o->jobs, "render job files, galleries, or directories of jobs")
      .required()
      .take_all();
  cmd.add_option("--golden", o->golden,
                 "golden directory (default: golden/ next to each job); goldens are <dir>/<job "
                 "name>/frame_NNNN.png");
  cmd.add_option(
      "--frames", o->frames,
      "frames to check: N, A:B, A:, :B separated by commas (default: first, middle, last)");
  cmd.add_flag("--update", o->update, "write the goldens (and golden.json) instead of comparing");
  cmd.add_option("--report", o->report,
                 "write an HTML report (index.html and images) into this directory");
  cmd.add_option("--junit", o->junit, "write JUnit XML to this file");
  cmd.add_option("--metric", o->metric, "pixel (default) or ssim");
  cmd.add_option("--threshold", o->threshold,
                 "pixel: largest channel difference 0..255 that counts as equal (default " +
                     std::to_string(check::kDefaultChannelThreshold) +
                     "); ssim: lowest SSIM that passes (default " +
                     check::number_text(check::kDefaultMinSsim) + ")");
  cmd.add_option("--max-differing", o->max_differing,
                 "pixel: percentage of pixels allowed to differ (default " +
                     check::number_text(check::kDefaultMaxDifferingPercent) + ")");
  cmd.add_option("-j,--jobs-in-parallel", o->workers, "check this many jobs at once (default 1)");
  add_gl_option(cmd, o->gl);
  return [o] { return run_check(*o); };
}

}  // namespace epviz::app
