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
#include <set>
#include <thread>

#include "app/cli_values.hpp"
#include "app/gl_option.hpp"
#include "app/job_frames.hpp"
#include "app/render_job.hpp"
#include "app/usage_error.hpp"
#include "check/frame_result.hpp"
#include "check/golden_record.hpp"
#include "check/html_report.hpp"
#include "check/image_compare.hpp"
#include "check/junit_xml.hpp"
#include "check/ssim.hpp"
#include "io/atomic_file.hpp"
#include "io/frame_names.hpp"
#include "io/frame_range.hpp"
#include "io/png_reader.hpp"
#include "io/png_writer.hpp"
#include "render/gl_choice.hpp"

namespace epviz::app {
namespace {

namespace fs = std::filesystem;

// Defaults chosen from measurement (docs/ci.md, "How the defaults were chosen").
constexpr int kDefaultChannelThreshold = 1;          // of 255
constexpr double kDefaultMaxDifferingPercent = 0.5;  // of the frame's pixels
constexpr double kDefaultMinSsim = 0.999;

struct CheckOptions {
  std::vector<std::string> jobs;
  std::string golden, frames, report, junit, threshold, max_differing, metric = "pixel", workers,
                                                                       gl;
  bool update = false;
};

enum class Metric { pixel, ssim };

struct Tolerance {
  Metric metric = Metric::pixel;
  int max_channel_difference = kDefaultChannelThreshold;
  double max_differing_percent = kDefaultMaxDifferingPercent;
  double min_ssim = kDefaultMinSsim;

  std::string describe() const {
    char s[200];
    if (metric == Metric::pixel)
      std::snprintf(s, sizeof s,
                    "a pixel differs when a channel differs by more than %d/255; a frame fails "
                    "when more than %g %% of its pixels differ",
                    max_channel_difference, max_differing_percent);
    else
      std::snprintf(s, sizeof s,
                    "a frame fails when its SSIM (grey level, %dx%d windows) is below %g",
                    check::kSsimWindow, check::kSsimWindow, min_ssim);
    return s;
  }
};

// One job to check, everything about it validated.
struct CheckJob {
  RenderJob job;
  std::string shown;  // the job file as the user named it (or as a gallery lists it)
  fs::path golden_dir;
  scene::ScenePlan plan;
  std::vector<int> frames;
};

struct GlStrings {
  std::string renderer, version;
};

struct JobOutcome {
  std::vector<check::FrameResult> results;
  std::vector<std::string> lines;     // extra stdout lines after the frames
  std::vector<std::string> warnings;  // stderr
  int goldens_written = 0;
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

std::string percent(double fraction) {
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

Tolerance tolerance_from(const CheckOptions& o) {
  Tolerance t;
  if (o.metric == "ssim")
    t.metric = Metric::ssim;
  else if (o.metric != "pixel")
    throw UsageError("--metric: unknown metric '" + o.metric + "' (allowed: pixel, ssim)");
  if (t.metric == Metric::pixel) {
    if (!o.threshold.empty())
      t.max_channel_difference = int(parse_integer("--threshold", o.threshold, 0, 255));
    if (!o.max_differing.empty()) {
      t.max_differing_percent = parse_number("--max-differing", o.max_differing);
      if (!(t.max_differing_percent >= 0 && t.max_differing_percent <= 100))
        throw UsageError("--max-differing: expected a percentage of pixels from 0 to 100, got '" +
                         o.max_differing + "'");
    }
  } else {
    if (!o.max_differing.empty())
      throw UsageError(
          "--max-differing: applies to --metric pixel only (--metric ssim takes --threshold, the "
          "lowest SSIM that passes)");
    if (!o.threshold.empty()) {
      t.min_ssim = parse_number("--threshold", o.threshold);
      if (!(t.min_ssim > 0 && t.min_ssim <= 1))
        throw UsageError(
            "--threshold: with --metric ssim, expected the lowest SSIM that passes, above 0 and at "
            "most 1, got '" +
            o.threshold + "'");
    }
  }
  return t;
}

// --frames as a list of ranges (syntax checked now, ends resolved per job).
std::vector<io::FrameRangeSpec> frame_specs(const std::string& text) {
  std::vector<io::FrameRangeSpec> specs;
  if (text.empty()) return specs;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (item.empty())
      throw UsageError("--frames: empty item in '" + text +
                       "' (allowed: N, A:B, A:, :B separated by commas)");
    try {
      specs.push_back(io::parse_frame_range(item));
    } catch (const io::FrameRangeError& e) {
      throw UsageError(e.what());
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return specs;
}

std::vector<int> frames_of(const std::vector<io::FrameRangeSpec>& specs, int frame_count,
                           const std::string& job) {
  std::set<int> frames;
  if (specs.empty()) {
    frames = {0, (frame_count - 1) / 2, frame_count - 1};  // first, middle, last
  } else {
    for (const auto& spec : specs) {
      try {
        const auto r = io::resolve_frame_range(spec, frame_count);
        for (int i = r.first; i <= r.last; ++i) frames.insert(i);
      } catch (const io::FrameRangeError& e) {
        throw UsageError(job + ": " + e.what());
      }
    }
  }
  return {frames.begin(), frames.end()};
}

// The render jobs named on the command line: files, galleries (their jobs)
// and directories (their *.json files, bench-figures jobs skipped).
std::vector<std::pair<RenderJob, std::string>> expand_jobs(const std::vector<std::string>& args) {
  std::vector<std::pair<RenderJob, std::string>> out;
  std::set<fs::path> seen;
  auto add = [&](RenderJob job, const std::string& shown) {
    const auto key = fs::weakly_canonical(job.file);
    if (seen.insert(key).second) out.emplace_back(std::move(job), shown);
  };
  auto add_loaded = [&](const fs::path& file, bool from_dir) {
    auto loaded = load_render_job(file);
    if (loaded.bench) {
      if (from_dir) return;
      throw UsageError(file.string() +
                       ": a bench-figures job has no frames to check (allowed: a render job, a "
                       "gallery or a directory of them)");
    }
    if (loaded.gallery)
      for (auto& j : loaded.gallery->jobs) add(j, j.file.string());
    else
      add(std::move(*loaded.single), file.string());
  };
  for (const auto& arg : args) {
    if (fs::is_directory(arg)) {
      std::vector<fs::path> files;
      for (const auto& e : fs::directory_iterator(arg))
        if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
      std::sort(files.begin(), files.end());
      if (files.empty()) throw UsageError(arg + ": no render jobs (*.json) in this directory");
      for (const auto& f : files) add_loaded(f, true);
    } else {
      add_loaded(arg, false);
    }
  }
  return out;
}

void check_output_paths(const CheckOptions& o) {
  if (!o.report.empty()) {
    if (fs::exists(o.report) && !fs::is_directory(o.report))
      throw UsageError("--report: '" + o.report + "' exists and is not a directory");
    const auto parent = fs::absolute(o.report).parent_path();
    if (!fs::is_directory(parent))
      throw UsageError("--report: directory '" + parent.string() + "' does not exist");
  }
  if (!o.junit.empty()) {
    if (fs::is_directory(o.junit))
      throw UsageError("--junit: '" + o.junit + "' is a directory; expected a file name");
    const auto parent = fs::absolute(o.junit).parent_path();
    if (!fs::is_directory(parent))
      throw UsageError("--junit: directory '" + parent.string() + "' does not exist");
  }
  (void)render::GlChoice(o.gl);
}

std::vector<CheckJob> prepare_jobs(const CheckOptions& o) {
  const auto specs = frame_specs(o.frames);
  std::vector<CheckJob> jobs;
  std::map<fs::path, std::string> golden_owner;
  for (auto& [job, shown] : expand_jobs(o.jobs)) {
    CheckJob c;
    c.plan = plan_job(job);
    c.frames = frames_of(specs, c.plan.frames, shown);
    const std::string name = job.file.stem().string();
    c.golden_dir =
        o.golden.empty() ? job.file.parent_path() / "golden" / name : fs::path(o.golden) / name;
    const auto key = fs::weakly_canonical(c.golden_dir);
    if (auto [it, fresh] = golden_owner.emplace(key, shown); !fresh)
      throw UsageError(shown + ": its goldens would share " + c.golden_dir.string() + " with " +
                       it->second + " (jobs need distinct file names)");
    c.shown = shown;
    c.job = std::move(job);
    jobs.push_back(std::move(c));
  }
  return jobs;
}

// The command that (re)creates goldens for `frames` of a job.
std::string update_command(const CheckOptions& o, const CheckJob& c,
                           const std::vector<int>& frames) {
  std::string cmd = "epviz check " + shell_word(c.shown) + " --frames " + frame_list(frames);
  if (!o.golden.empty()) cmd += " --golden " + shell_word(o.golden);
  if (!o.gl.empty()) cmd += " --gl " + shell_word(o.gl);
  return cmd + " --update";
}

std::unique_ptr<render::GlContext> open_context(const CheckOptions& o) {
  return render::GlChoice(o.gl).open();
}

GlStrings gl_strings(const render::GlContext& context) {
  return {context.renderer(), context.version()};
}

class Checker {
 public:
  Checker(const CheckOptions& o, const Tolerance& t, const GlStrings& gl) : o_(o), t_(t), gl_(gl) {}

  JobOutcome check(const CheckJob& c, std::size_t index, const render::RgbaImage* images,
                   std::size_t count, const std::optional<numerics::Failure>& failure) const {
    JobOutcome out;
    if (o_.update) return update(c, images, count, failure);
    if (auto rec = check::read_golden_record(c.golden_dir / "golden.json");
        rec && (rec->gl_renderer != gl_.renderer || rec->gl_version != gl_.version))
      out.warnings.push_back("epviz: warning: " + c.shown + ": goldens were made with " +
                             rec->gl_renderer + ", " + rec->gl_version + "; this run uses " +
                             gl_.renderer + ", " + gl_.version +
                             " (see docs/ci.md: --metric ssim, or re-baseline with --update)");
    std::vector<int> missing;
    for (std::size_t k = 0; k < c.frames.size(); ++k) {
      check::FrameResult r;
      r.job = c.shown;
      r.frame = c.frames[k];
      if (k >= count) {
        r.problem = "numerical failure before this frame: " +
                    (failure ? failure->message() : std::string("?"));
        out.results.push_back(std::move(r));
        continue;
      }
      compare(c, index, images[k], r, missing);
      out.results.push_back(std::move(r));
    }
    if (!missing.empty()) {
      const std::string cmd = update_command(o_, c, missing);
      for (auto& r : out.results)
        if (std::find(missing.begin(), missing.end(), r.frame) != missing.end())
          r.problem += "; create it with: " + cmd;
    }
    return out;
  }

 private:
  std::string image_name(const CheckJob& c, std::size_t index, int frame, const char* kind) const {
    return std::to_string(index + 1) + "_" + c.job.file.stem().string() + "_" +
           io::frame_file_name(frame, c.plan.frames, "frame_", std::string(".") + kind + ".png");
  }

  void compare(const CheckJob& c, std::size_t index, const render::RgbaImage& actual,
               check::FrameResult& r, std::vector<int>& missing) const {
    const fs::path golden_path = c.golden_dir / io::frame_file_name(r.frame, c.plan.frames);
    const bool report = !o_.report.empty();
    auto keep_actual = [&] {
      if (!report) return;
      r.actual_image = image_name(c, index, r.frame, "actual");
      io::write_png_rgba(fs::path(o_.report) / r.actual_image, actual.width, actual.height,
                         actual.pixels);
    };
    const auto golden = io::read_png_rgba(golden_path);
    if (!golden) {
      r.problem = "no golden " + golden_path.string();
      missing.push_back(r.frame);
      keep_actual();
      return;
    }
    auto keep_golden = [&] {
      if (!report) return;
      r.golden_image = image_name(c, index, r.frame, "golden");
      fs::copy_file(golden_path, fs::path(o_.report) / r.golden_image,
                    fs::copy_options::overwrite_existing);
    };
    if (golden->width != actual.width || golden->height != actual.height) {
      r.problem = "the golden " + golden_path.string() + " is " + std::to_string(golden->width) +
                  "x" + std::to_string(golden->height) + " but the frame is " +
                  std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                  "; re-baseline with: " + update_command(o_, c, c.frames);
      keep_golden();
      keep_actual();
      return;
    }
    char m[160];
    if (t_.metric == Metric::pixel) {
      const auto d = check::compare_pixels(actual.width, actual.height, actual.pixels, golden->rgba,
                                           t_.max_channel_difference);
      r.passed = 100.0 * d.fraction_differing() <= t_.max_differing_percent;
      std::snprintf(m, sizeof m, "%s %% pixels differ (limit %g %%)",
                    percent(d.fraction_differing()).c_str(), t_.max_differing_percent);
    } else {
      const double s = check::ssim(actual.width, actual.height, actual.pixels, golden->rgba);
      r.passed = s >= t_.min_ssim;
      std::snprintf(m, sizeof m, "SSIM %.5f (limit %g)", s, t_.min_ssim);
    }
    r.measure = m;
    if (r.passed || !report) return;
    keep_golden();
    keep_actual();
    r.diff_image = image_name(c, index, r.frame, "diff");
    io::write_png_rgba(fs::path(o_.report) / r.diff_image, actual.width, actual.height,
                       check::diff_image(actual.width, actual.height, actual.pixels, golden->rgba,
                                         t_.max_channel_difference));
  }

  JobOutcome update(const CheckJob& c, const render::RgbaImage* images, std::size_t count,
                    const std::optional<numerics::Failure>& failure) const {
    JobOutcome out;
    if (failure || count != c.frames.size()) {
      check::FrameResult r;
      r.job = c.shown;
      r.frame = count < c.frames.size() ? c.frames[count] : c.frames.back();
      r.problem = "numerical failure, no goldens written: " +
                  (failure ? failure->message() : std::string("?"));
      out.results.push_back(std::move(r));
      return out;
    }
    fs::create_directories(c.golden_dir);
    // Small files for version control: the slowest, smallest PNG settings.
    const io::PngOptions small{.compression_level = 9, .filter = -1};
    for (std::size_t k = 0; k < count; ++k) {
      const fs::path path = c.golden_dir / io::frame_file_name(c.frames[k], c.plan.frames);
      io::write_png_rgba(path, images[k].width, images[k].height, images[k].pixels, small);
      out.lines.push_back("UPDATED " + c.shown + " frame " + std::to_string(c.frames[k]) + ": " +
                          path.string());
      ++out.goldens_written;
    }
    check::GoldenRecord rec;
    rec.epviz_version = EPVIZ_VERSION;
    rec.gl_renderer = gl_.renderer;
    rec.gl_version = gl_.version;
    rec.job_file = c.job.file.filename().string();
    rec.job_hash = check::job_file_hash(c.job.file);
    // Frames updated earlier stay goldens (their files are still there).
    std::set<int> frames(c.frames.begin(), c.frames.end());
    if (auto old = check::read_golden_record(c.golden_dir / "golden.json"))
      for (const int f : old->frames)
        if (f < c.plan.frames && fs::exists(c.golden_dir / io::frame_file_name(f, c.plan.frames)))
          frames.insert(f);
    rec.frames.assign(frames.begin(), frames.end());
    rec.width = c.job.scene.width;
    rec.height = c.job.scene.height;
    io::write_file_atomically(c.golden_dir / "golden.json", check::to_json_text(rec));
    return out;
  }

  const CheckOptions& o_;
  Tolerance t_;
  GlStrings gl_;
};

// Checks every job on `workers` threads, each with its own GL context; the
// outcomes come back in job order.
std::vector<std::future<JobOutcome>> check_jobs(const std::vector<CheckJob>& jobs,
                                                const CheckOptions& o, const Tolerance& t,
                                                int workers, std::vector<std::thread>& threads,
                                                std::string& renderer) {
  auto promises = std::make_shared<std::vector<std::promise<JobOutcome>>>(jobs.size());
  std::vector<std::future<JobOutcome>> futures;
  for (auto& p : *promises) futures.push_back(p.get_future());
  auto next = std::make_shared<std::atomic<std::size_t>>(0);
  auto paint_lock = std::make_shared<std::mutex>();
  auto gl_ready = std::make_shared<std::promise<GlStrings>>();
  auto gl_future = gl_ready->get_future().share();
  auto gl_once = std::make_shared<std::once_flag>();
  for (int w = 0; w < workers; ++w) {
    threads.emplace_back([&jobs, &o, t, promises, next, paint_lock, gl_ready, gl_once] {
      std::unique_ptr<render::GlContext> context;
      GlStrings gl;
      try {
        std::lock_guard lock(*paint_lock);
        context = open_context(o);
        gl = gl_strings(*context);
        std::call_once(*gl_once, [&] { gl_ready->set_value(gl); });
      } catch (...) {
        // No context on this worker: every job it takes reports the error.
        const auto error = std::current_exception();
        std::call_once(*gl_once, [&] { gl_ready->set_exception(error); });
        for (std::size_t i; (i = next->fetch_add(1)) < jobs.size();)
          (*promises)[i].set_exception(error);
        return;
      }
      const Checker checker(o, t, gl);
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
          const auto rendered =
              render_job_frames(c.plan, c.job.scene, c.frames, *painter, paint_lock.get());
          drop_painter();
          (*promises)[i].set_value(checker.check(c, i, rendered.images.data(),
                                                 rendered.images.size(), rendered.failure));
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
  const Tolerance t = tolerance_from(o);
  const int workers = o.workers.empty() ? 1 : int(parse_integer("-j", o.workers, 1, 64));
  check_output_paths(o);
  const auto jobs = prepare_jobs(o);
  if (!o.report.empty() && !o.update) fs::create_directories(o.report);

  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  std::string renderer;
  std::vector<std::future<JobOutcome>> futures;
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

  if (o.update) {
    const auto failed =
        std::count_if(results.begin(), results.end(), [](const auto& r) { return !r.passed; });
    std::printf("%d goldens written%s\n", written,
                failed ? (", " + std::to_string(failed) + " failed").c_str() : "");
  } else {
    std::printf("%s\n", check::summary(results).c_str());
  }
  if (!o.update && !o.report.empty()) {
    const auto index = fs::path(o.report) / "index.html";
    io::write_file_atomically(index, check::html_report(results, {t.describe(), renderer}));
    std::printf("report: %s\n", index.string().c_str());
  }
  if (!o.junit.empty()) io::write_file_atomically(o.junit, check::junit_xml(results, seconds));
  return std::all_of(results.begin(), results.end(), [](const auto& r) { return r.passed; }) ? 0
                                                                                             : 1;
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
                  "pixel: largest channel difference 0..255 that counts as equal (default 4); "
                  "ssim: lowest SSIM that passes (default 0.98)");
  cmd->add_option("--max-differing", o->max_differing,
                  "pixel: percentage of pixels allowed to differ (default 0.5)");
  cmd->add_option("-j,--jobs-in-parallel", o->workers, "check this many jobs at once (default 1)");
  add_gl_option(*cmd, o->gl);
  return [o] { return run_check(*o); };
}

}  // namespace epviz::app
