#include "app/check_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "app/cli_values.hpp"
#include "app/gl_option.hpp"
#include "check/frame_choice.hpp"
#include "check/frame_result.hpp"
#include "check/html_report.hpp"
#include "check/job_check.hpp"
#include "check/junit_xml.hpp"
#include "check/tolerance.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/frame_range.hpp"
#include "io/output_paths.hpp"
#include "job/job_file.hpp"
#include "job/job_list.hpp"
#include "job/job_plan.hpp"
#include "paint/frame_drawer.hpp"
#include "render/gl_choice.hpp"
#include "scene/plan.hpp"

namespace epviz::app {
namespace {

namespace fs = std::filesystem;
using job::RenderJob;

struct CheckOptions {
  std::vector<std::string> jobs;
  std::string golden, frames, report, junit, threshold, max_differing, metric = "pixel", workers,
                                                                       gl;
  bool update = false;
};

// One job to check, everything about it validated.
struct CheckJob {
  RenderJob job;
  scene::ScenePlan plan;
  check::GoldenJob golden;
};

// Single-quotes a shell word unless it is plainly safe.
std::string shell_word(const std::string& s) {
  const bool plain = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string_view("_./:=,@%+-").find(c) != std::string_view::npos;
  });
  if (plain) return s;
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string frame_list(const std::vector<int>& frames) {
  std::string s;
  for (const int f : frames) s += (s.empty() ? "" : ",") + std::to_string(f);
  return s;
}

check::Tolerance tolerance_from(const CheckOptions& o) {
  using check::Metric;
  check::Tolerance t;
  if (o.metric == "ssim")
    t.metric = Metric::ssim;
  else if (o.metric != "pixel")
    throw io::BadInput("--metric: unknown metric '" + o.metric + "' (allowed: pixel, ssim)");
  if (t.metric == Metric::pixel) {
    if (!o.threshold.empty())
      t.max_channel_difference = int(parse_integer("--threshold", o.threshold, 0, 255));
    if (!o.max_differing.empty()) {
      t.max_differing_percent = parse_number("--max-differing", o.max_differing);
      if (!(t.max_differing_percent >= 0 && t.max_differing_percent <= 100))
        throw io::BadInput("--max-differing: expected a percentage of pixels from 0 to 100, got '" +
                           o.max_differing + "'");
    }
  } else {
    if (!o.max_differing.empty())
      throw io::BadInput(
          "--max-differing: applies to --metric pixel only (--metric ssim takes --threshold, the "
          "lowest SSIM that passes)");
    if (!o.threshold.empty()) {
      t.min_ssim = parse_number("--threshold", o.threshold);
      if (!(t.min_ssim > 0 && t.min_ssim <= 1))
        throw io::BadInput(
            "--threshold: with --metric ssim, expected the lowest SSIM that passes, above 0 and at "
            "most 1, got '" +
            o.threshold + "'");
    }
  }
  return t;
}

void check_output_paths(const CheckOptions& o) {
  if (!o.report.empty()) {
    if (fs::exists(o.report) && !fs::is_directory(o.report))
      throw io::BadInput("--report: '" + o.report + "' exists and is not a directory");
    const auto parent = fs::absolute(o.report).parent_path();
    if (!fs::is_directory(parent))
      throw io::BadInput("--report: directory '" + parent.string() + "' does not exist");
  }
  if (!o.junit.empty()) {
    if (fs::is_directory(o.junit))
      throw io::BadInput("--junit: '" + o.junit + "' is a directory; expected a file name");
    const auto parent = fs::absolute(o.junit).parent_path();
    if (!fs::is_directory(parent))
      throw io::BadInput("--junit: directory '" + parent.string() + "' does not exist");
  }
  (void)render::GlChoice(o.gl);
}

std::vector<CheckJob> prepare_jobs(const CheckOptions& o) {
  const auto specs = io::parse_frame_ranges(o.frames);
  std::vector<CheckJob> jobs;
  std::map<fs::path, std::string> golden_owner;
  for (auto& [job, shown] : job::render_jobs_in(o.jobs)) {
    CheckJob c;
    c.plan = job::plan_job(job);
    auto& g = c.golden;
    try {
      g.frames = check::frames_to_check(specs, c.plan.frames);
    } catch (const io::FrameRangeError& e) {
      throw io::BadInput(shown + ": " + e.what());
    }
    g.golden_dir = check::golden_dir_of(job.file, o.golden);
    g.shown = shown;
    g.job_file = job.file;
    g.frame_count = c.plan.frames;
    g.width = job.scene.width;
    g.height = job.scene.height;
    check::check_golden_inputs(g, o.update);
    const auto key = fs::weakly_canonical(g.golden_dir);
    if (auto [it, fresh] = golden_owner.emplace(key, shown); !fresh)
      throw io::BadInput(shown + ": its goldens would share " + g.golden_dir.string() + " with " +
                         it->second + " (jobs need distinct file names)");
    c.job = std::move(job);
    jobs.push_back(std::move(c));
  }
  return jobs;
}

// The command that (re)creates goldens for `frames` of a job.
std::string update_command(const CheckOptions& o, const check::GoldenJob& job,
                           const std::vector<int>& frames) {
  std::string cmd = "epviz check " + shell_word(job.shown) + " --frames " + frame_list(frames);
  if (!o.golden.empty()) cmd += " --golden " + shell_word(o.golden);
  if (!o.gl.empty()) cmd += " --gl " + shell_word(o.gl);
  return cmd + " --update";
}

std::unique_ptr<render::GlContext> open_context(const CheckOptions& o) {
  return render::GlChoice(o.gl).open();
}

check::JobChecker job_checker(const CheckOptions& o, const check::Tolerance& t,
                              const check::RendererInfo& gl) {
  check::CheckSettings s;
  s.tolerance = t;
  if (!o.update) s.report_dir = o.report;
  s.renderer = gl;
  s.epviz_version = EPVIZ_VERSION;
  s.update_command = [&o](const check::GoldenJob& job, const std::vector<int>& frames) {
    return update_command(o, job, frames);
  };
  return check::JobChecker(std::move(s));
}

// Checks every job on `workers` threads, each with its own GL context; the
// outcomes come back in job order.
std::vector<std::future<check::JobOutcome>> check_jobs(const std::vector<CheckJob>& jobs,
                                                       const CheckOptions& o,
                                                       const check::Tolerance& t, int workers,
                                                       std::vector<std::thread>& threads,
                                                       std::string& renderer) {
  auto promises = std::make_shared<std::vector<std::promise<check::JobOutcome>>>(jobs.size());
  std::vector<std::future<check::JobOutcome>> futures;
  for (auto& p : *promises) futures.push_back(p.get_future());
  auto next = std::make_shared<std::atomic<std::size_t>>(0);
  auto paint_lock = std::make_shared<std::mutex>();
  auto gl_ready = std::make_shared<std::promise<check::RendererInfo>>();
  auto gl_future = gl_ready->get_future().share();
  auto gl_once = std::make_shared<std::once_flag>();
  for (int w = 0; w < workers; ++w) {
    threads.emplace_back([&jobs, &o, t, promises, next, paint_lock, gl_ready, gl_once] {
      std::unique_ptr<render::GlContext> context;
      check::RendererInfo gl;
      try {
        std::lock_guard lock(*paint_lock);
        context = open_context(o);
        gl = {context->renderer(), context->version()};
        std::call_once(*gl_once, [&] { gl_ready->set_value(gl); });
      } catch (...) {
        // No context on this worker: every job it takes reports the error.
        const auto error = std::current_exception();
        std::call_once(*gl_once, [&] { gl_ready->set_exception(error); });
        for (std::size_t i; (i = next->fetch_add(1)) < jobs.size();)
          (*promises)[i].set_exception(error);
        return;
      }
      auto checker = job_checker(o, t, gl);
      for (std::size_t i; (i = next->fetch_add(1)) < jobs.size();) {
        // Created, used and destroyed under the paint lock (also on an exception).
        std::unique_ptr<paint::FramePainter> painter;
        auto drop_painter = [&] {
          std::lock_guard lock(*paint_lock);
          painter.reset();
        };
        try {
          const auto& c = jobs[i];
          {
            std::lock_guard lock(*paint_lock);
            painter = std::make_unique<paint::FramePainter>(*context, c.job.scene.width,
                                                            c.job.scene.height);
          }
          // Each frame is checked as soon as it is drawn, and not kept.
          auto frames = checker.start(c.golden, i, o.update);
          const auto failure =
              paint::draw_frames(c.plan, c.job.scene, c.golden.frames, *painter, paint_lock.get(),
                                 [&](const render::RgbaImage& image) {
                                   frames.add({image.width, image.height, image.pixels});
                                 });
          drop_painter();
          (*promises)[i].set_value(
              frames.finish(failure ? std::optional(failure->message()) : std::nullopt));
        } catch (...) {
          drop_painter();
          (*promises)[i].set_exception(std::current_exception());
        }
      }
      std::lock_guard lock(*paint_lock);
      context.reset();
    });
  }
  const auto gl = gl_future.get();  // rethrows a context error
  renderer = gl.renderer + ", OpenGL " + gl.version;
  return futures;
}

int run_check(const CheckOptions& o) {
  // Everything the user gave is checked before anything is drawn or written.
  const check::Tolerance t = tolerance_from(o);
  const int workers = o.workers.empty() ? 1 : int(parse_integer("-j", o.workers, 1, 64));
  check_output_paths(o);
  const io::FifoReaderCheck junit_reader("--junit", o.junit);
  const auto jobs = prepare_jobs(o);
  if (!o.report.empty() && !o.update) io::make_output_folder("--report", o.report);

  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  std::string renderer;
  std::vector<std::future<check::JobOutcome>> futures;
  std::exception_ptr error;
  try {
    futures = check_jobs(jobs, o, t, std::min<int>(workers, int(jobs.size())), threads, renderer);
  } catch (...) {
    error = std::current_exception();
  }
  std::vector<check::FrameResult> results;
  int written = 0;
  for (auto& f : futures) {
    if (error) {
      f.wait();
      continue;
    }
    try {
      auto outcome = f.get();
      for (const auto& w : outcome.warnings) std::fprintf(stderr, "%s\n", w.c_str());
      for (const auto& r : outcome.results) std::printf("%s\n", r.line().c_str());
      for (const auto& l : outcome.lines) std::printf("%s\n", l.c_str());
      std::fflush(stdout);
      written += outcome.goldens_written;
      for (auto& r : outcome.results) results.push_back(std::move(r));
    } catch (...) {
      error = std::current_exception();
    }
  }
  for (auto& th : threads) th.join();
  if (error) std::rethrow_exception(error);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::string summary =
      o.update ? check::update_summary(results, written) : check::summary(results);
  std::printf("%s\n", summary.c_str());
  if (!o.update && !o.report.empty()) {
    const auto index = fs::path(o.report) / "index.html";
    io::write_file_atomically(index, check::html_report(results, {t.describe(), renderer}));
    std::printf("report: %s\n", index.string().c_str());
  }
  if (!o.junit.empty()) io::write_file_atomically(o.junit, check::junit_xml(results, seconds));
  return check::all_passed(results) ? 0 : 1;
}

}  // namespace

std::function<int()> add_check_command(CLI::App& app) {
  auto o = std::make_shared<CheckOptions>();
  auto* cmd = app.add_subcommand(
      "check", "Render frames of jobs in memory and compare them with goldens (for CI)");
  cmd->add_option("jobs", o->jobs, "render job files, galleries, or directories of jobs")
      ->required()
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--golden", o->golden,
                  "golden directory (default: golden/ next to each job); goldens are <dir>/<job "
                  "name>/frame_NNNN.png");
  cmd->add_option(
      "--frames", o->frames,
      "frames to check: N, A:B, A:, :B separated by commas (default: first, middle, last)");
  cmd->add_flag("--update", o->update, "write the goldens (and golden.json) instead of comparing");
  cmd->add_option("--report", o->report,
                  "write an HTML report (index.html and images) into this directory");
  cmd->add_option("--junit", o->junit, "write JUnit XML to this file");
  cmd->add_option("--metric", o->metric, "pixel (default) or ssim");
  cmd->add_option("--threshold", o->threshold,
                  "pixel: largest channel difference 0..255 that counts as equal (default " +
                      std::to_string(check::kDefaultChannelThreshold) +
                      "); ssim: lowest SSIM that passes (default " +
                      check::number_text(check::kDefaultMinSsim) + ")");
  cmd->add_option("--max-differing", o->max_differing,
                  "pixel: percentage of pixels allowed to differ (default " +
                      check::number_text(check::kDefaultMaxDifferingPercent) + ")");
  cmd->add_option("-j,--jobs-in-parallel", o->workers, "check this many jobs at once (default 1)");
  add_gl_option(*cmd, o->gl);
  return [o] { return run_check(*o); };
}

}  // namespace epviz::app
