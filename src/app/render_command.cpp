#include "app/render_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "app/bench_command.hpp"
#include "app/cli_values.hpp"
#include "app/gl_option.hpp"
#include "app/render_h5.hpp"
#include "h5/columns_file.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/frame_range.hpp"
#include "io/json_text.hpp"
#include "io/number_text.hpp"
#include "io/output_paths.hpp"
#include "io/print_size.hpp"
#include "io/printable.hpp"
#include "io/progress.hpp"
#include "io/temp_name.hpp"
#include "io/temp_registry.hpp"
#include "io/video_writer.hpp"
#include "job/gallery_layout.hpp"
#include "job/job_file.hpp"
#include "job/job_help.hpp"
#include "job/job_plan.hpp"
#include "job/render_report.hpp"
#include "job/shipped_jobs.hpp"
#include "numerics/failure.hpp"
#include "paint/frame_files.hpp"
#include "paint/gallery_figure.hpp"
#include "paint/grid_video.hpp"
#include "render/gl_choice.hpp"
#include "scene/plan.hpp"
#include "shard/checksum.hpp"
#include "shard/frame_shard.hpp"
#include "sim/failure_advice.hpp"
#include "vector/figure_format.hpp"
#include "vector/frame_still.hpp"

namespace epviz::app {
namespace {

namespace fs = std::filesystem;
using job::GalleryJob;
using job::RenderJob;

struct RenderOptions {
  std::string job, out, frames, width, height, format, gl, report_json, shard, shard_count, h5;
  io::PrintSizeText print;  // --figure-width, --font-size, --dpi
  bool resume = false, quiet = false, progress = false, list_jobs = false, help_job = false;
};

// What one job needs before any pixel is drawn: everything checked.
struct PreparedJob {
  RenderJob job;
  scene::ScenePlan plan;
  io::FrameRange range;
  std::string caption;                        // under every frame (gallery tiles)
  std::optional<vector::FigureFormat> still;  // --format svg|pdf: vector stills
  std::optional<io::PrintSize> print;         // --figure-width
};

// --format svg|pdf: the frames as vector stills (vector/frame_still.hpp)
// instead of PNG frames or a video.
std::optional<vector::FigureFormat> still_format(const RenderOptions& o) {
  if (o.format != "svg" && o.format != "pdf") return std::nullopt;
  return vector::parse_figure_format(o.format);
}

// --format, checked; when given, `video` becomes its video format (none for
// png and the vector stills).
void format_option(const RenderOptions& o, std::optional<io::VideoFormat>& video) {
  if (o.format.empty()) return;
  if (still_format(o)) {
    video.reset();
    return;
  }
  auto names = job::output_format_names();
  if (std::find(names.begin(), names.end(), o.format) == names.end()) {
    std::string message = "--format: unknown format '";
    message += io::printable(o.format);
    message += "' (allowed: ";
    for (const auto& n : names) message += n + ", ";
    message += "svg, pdf)";
    throw io::BadInput(message);
  }
  video = job::parse_output_format("--format", o.format);
}

// The job's figure_width, font_size and dpi with the options over them;
// a size or dpi without a width refused naming where each came from.
std::optional<io::PrintSize> print_size_of(const RenderJob& job, const RenderOptions& o) {
  const auto& file = job.output.print;
  if (file.width.empty() && o.print.width.empty()) {
    const std::string key = !file.font.empty()  ? "output.font_size"
                            : !file.dpi.empty() ? "output.dpi"
                                                : "";
    if (!key.empty() && o.print.font.empty() && o.print.dpi.empty())
      throw io::BadInput(job.file.string() + ": " + key +
                         ": applies to a figure of a printed size; give output.figure_width or "
                         "--figure-width too");
    return io::parse_print_size(o.print);  // refuses --font-size, --dpi alone
  }
  // Each value was checked where it came from (the file on reading); the
  // options' names go to what is left to check (the pixels of --dpi).
  io::PrintSizeText text = file;
  for (auto [from, to] : {std::pair{&o.print.width, &text.width},
                          {&o.print.font, &text.font},
                          {&o.print.dpi, &text.dpi}})
    if (!from->empty()) *to = *from;
  return io::parse_print_size(text);
}

PreparedJob prepare(RenderJob job, const RenderOptions& o) {
  if (!o.width.empty()) job.scene.width = int(parse_integer("--width", o.width, 16, 8192));
  if (!o.height.empty()) job.scene.height = int(parse_integer("--height", o.height, 16, 8192));
  const auto print = print_size_of(job, o);
  if (print) {
    if (!o.width.empty() || !o.height.empty())
      throw io::BadInput(std::string(o.width.empty() ? "--height" : "--width") +
                         ": a figure of a printed size (--figure-width) takes its pixels from "
                         "--dpi; give one of them");
    std::vector<sim::RunSpec> runs;
    for (const auto& r : job::run_requests(job)) runs.push_back(r.run);
    scene::set_printed_size(job.scene, runs, print->width_units(), print->font_units());
    if (job.scene.width > 8192 || job.scene.height > 8192)
      throw io::BadInput("--figure-width: at --dpi " + io::number_text(print->dpi, 6) +
                         " the figure would be " + std::to_string(job.scene.width) + " x " +
                         std::to_string(job.scene.height) +
                         " pixels (at most 8192 a side); give a smaller --dpi");
  }
  format_option(o, job.output.video);
  if (!o.out.empty()) job.output.dir = o.out;
  // Every output is checked before any work, so that nothing is written on exit 2.
  io::check_file_name(job.file.string() + ": output.name", job.output.name);
  io::check_output_dir(o.out.empty() ? job.file.string() + ": output.dir" : "--out",
                       job.output.dir);
  const auto& video = job.output.video;
  if (const auto why =
          video ? io::video_size_problem(*video, job.scene.width, job.scene.height) : std::string();
      !why.empty())
    throw io::BadInput(job.file.string() + ": " + why);
  if (video && !io::ffmpeg_available())
    throw io::BadInput(
        "--format " + std::string(io::video_format_name(*video)) +
        ": ffmpeg not found on PATH; install the Debian package ffmpeg (scripts/setup.sh does)");
  if (o.resume && video)
    throw io::BadInput("--resume: applies to PNG sequences only (a video is written whole)");
  PreparedJob p;
  p.still = still_format(o);
  p.print = print;
  if (p.still && o.resume)
    throw io::BadInput("--resume: applies to PNG sequences only (--format " + o.format +
                       " writes each still whole)");

  p.plan = job::plan_job(job);
  // A vector still is of one frame: without --frames, the job's last.
  p.range = !o.frames.empty() ? io::parse_frame_range(o.frames, p.plan.frames)
            : p.still         ? io::FrameRange{p.plan.frames - 1, p.plan.frames - 1}
                              : io::all_frames(p.plan.frames);
  p.job = std::move(job);
  return p;
}

struct RenderStats {
  paint::FramesWritten written;
  nlohmann::json runs;  // job::runs_report after the last frame
};

io::ProgressOptions progress_options(const RenderOptions& o, std::string label) {
  io::ProgressOptions po;
  po.mode = o.quiet      ? io::ProgressMode::off
            : o.progress ? io::ProgressMode::on
                         : io::ProgressMode::automatic;
  po.label = std::move(label);
  return po;
}

// Renders the prepared job's frame range to its output.
RenderStats render_frames(const PreparedJob& p, paint::FramePainter& painter,
                          const RenderOptions& o) {
  const auto& job = p.job;
  paint::FrameDrawer drawer(p.plan, job.scene);
  drawer.set_caption(p.caption);
  const auto progress = progress_options(o, job.file.stem().string());
  RenderStats stats;
  if (p.still) {
    stats.written = vector::write_frame_stills(
        drawer, painter, p.range,
        {job.output.dir, job.output.name, *p.still, p.print ? p.print->pt_per_unit() : 1.0},
        progress);
  } else {
    const paint::FrameFiles files{job.output.dir, job.output.name, job.output.video, job.scene.fps,
                                  o.resume};
    stats.written = paint::write_frames(drawer, painter, p.range, files, progress);
  }
  stats.runs = job::runs_report(drawer.source());
  return stats;
}

job::RenderCounts counts(const RenderStats& st) {
  const auto& w = st.written;
  return {w.drawn, w.skipped, w.seconds, w.failure};
}

nlohmann::json job_report(const PreparedJob& p, const RenderStats& st) {
  return job::render_report(p.job, p.plan, counts(st), st.runs);
}

// Which GL implementation drew the frames (goldens are compared per backend).
void add_gl_report(nlohmann::json& j, const render::GlContext& context) {
  j["gl_backend"] = std::string(context.backend());
  j["gl_platform"] = context.platform();
  j["gl_renderer"] = context.renderer();
  j["gl_version"] = context.version();
}

// Where the one-line summaries go: stderr when standard output carries the
// JSON report (--report-json -), so that the report stays parseable.
std::FILE* summary_stream(const RenderOptions& o) {
  return !o.report_json.empty() && io::writes_to_standard_output(o.report_json) ? stderr : stdout;
}

void print_job_line(std::FILE* out, const PreparedJob& p, const RenderStats& st) {
  std::fputs(job::render_summary(p.job, p.plan, counts(st)).c_str(), out);
}

int report_failure(const std::optional<numerics::Failure>& f) {
  if (!f) return 0;
  std::fprintf(stderr, "epviz: numerical failure: %s\n",
               sim::failure_line(*f, sim::SettingsIn::render_job).c_str());
  return 3;
}

// The render the shards of `job` split: its hash is of the job as drawn (its
// canonical keys with the options applied), its command draws it again.
shard::FrameBatch frame_batch(const RenderJob& job, int frames) {
  job::JobDocument doc{job.simulation, job.runs, job.scene, job.output};
  doc.output.dir = "";
  shard::FrameBatch b;
  b.origin.source = fs::absolute(job.file).lexically_normal().string();
  b.origin.hash = shard::checksum_of(io::json_text(job::write_job(doc)));
  b.origin.command = {"epviz",
                      "render",
                      b.origin.source,
                      "--out",
                      fs::absolute(job.output.dir).lexically_normal().string(),
                      "--width",
                      std::to_string(job.scene.width),
                      "--height",
                      std::to_string(job.scene.height),
                      "--format",
                      std::string(job::output_format_name(job.output.video))};
  b.dir = job.output.dir;
  b.name = job.output.name;
  if (job.output.video) b.video_extension = io::video_format_extension(*job.output.video);
  b.frames = frames;
  return b;
}

int render_single(RenderJob job, const RenderOptions& o, const render::GlChoice& gl) {
  auto p = prepare(std::move(job), o);
  // A shard draws a contiguous range of frames (shard/frame_shard.hpp).
  shard::FrameBatch batch;
  std::optional<shard::FrameShard> shard;
  if (p.still && !o.shard.empty())
    throw io::BadInput("--shard: a vector still (--format " + o.format +
                       ") is one frame; give --frames instead");
  // A still is never sharded, not even by an array job's environment.
  if (const auto spec =
          p.still ? std::nullopt : shard::shard_from_options(o.shard, o.shard_count)) {
    if (!o.frames.empty())
      throw io::BadInput("--frames: a shard's frames follow from --shard; give one of them");
    batch = frame_batch(p.job, p.plan.frames);
    shard = shard::plan_frame_shard(batch, *spec);
    p.range = {int(shard->frames.first), int(shard->frames.end - 1)};
    p.job.output.name = shard->output_name;
  }
  if (shard && !o.h5.empty())
    throw io::BadInput(
        "--h5: a shard draws only some frames; give --h5 to a render of the whole job instead");
  auto context = gl.open();
  paint::FramePainter painter(*context, p.job.scene.width, p.job.scene.height, {},
                              p.job.scene.page);
  if (shard) shard::start_frame_shard(*shard);
  const auto st = render_frames(p, painter, o);
  if (shard && !st.written.failure) shard::finish_frame_shard(*shard, batch);
  print_job_line(summary_stream(o), p, st);
  auto report = job_report(p, st);
  add_gl_report(report, *context);
  if (!o.report_json.empty())
    io::write_file_atomically(o.report_json, io::json_text(report, 2) + "\n");
  const int frames_code = report_failure(st.written.failure);
  if (o.h5.empty()) return frames_code;
  const auto h5 =
      write_render_h5(o.h5, p.job, p.plan, report, progress_options(o, p.job.file.stem().string()));
  std::fputs(render_h5_summary(o.h5, h5).c_str(), summary_stream(o));
  // A run that failed beyond the frames drawn (--frames) fails the render too.
  if (h5.failure && frames_code == 0)
    std::fprintf(stderr, "epviz: numerical failure: %s\n", h5.failure->c_str());
  return h5.failure ? 3 : frames_code;
}

// Every job of the gallery at once, tiled frame by frame into one MP4
// (grid.mp4). Returns the number of jobs that failed.
int render_grid_video(const GalleryJob& g, const std::vector<PreparedJob>& jobs,
                      paint::FramePainter& painter, const RenderOptions& o) {
  std::vector<paint::GridScene> scenes;
  for (const auto& p : jobs) scenes.push_back({&p.plan, &p.job.scene, p.caption});
  paint::GridVideo video;
  video.path = g.dir / "grid.mp4";
  video.tile_width = g.tile_width;
  video.tile_height = g.tile_height;
  video.tiling = job::gallery_tiling(g);
  video.fps = jobs.front().job.scene.fps;  // the first job's: the tiles share one clock
  const auto written =
      paint::write_grid_video(scenes, video, painter, progress_options(o, "grid"),
                              [](const numerics::Failure& f) { report_failure(f); });
  std::fprintf(summary_stream(o), "%s: %d frames of %zu jobs tiled into %s (%dx%d)\n",
               g.file.string().c_str(), written.frames, jobs.size(), video.path.string().c_str(),
               written.size.width, written.size.height);
  return written.failures;
}

int render_gallery(GalleryJob g, const RenderOptions& o, const render::GlChoice& gl) {
  if (!o.frames.empty())
    throw io::BadInput("--frames: a gallery renders whole jobs; give --frames to a single job");
  if (!o.shard.empty())
    throw io::BadInput("--shard: a gallery renders whole jobs; shard a single job");
  if (!o.h5.empty())
    throw io::BadInput("--h5: writes one job's runs; give --h5 to a single job of the gallery");
  if (!o.print.width.empty() || !o.print.font.empty() || !o.print.dpi.empty())
    throw io::BadInput(
        "--figure-width: a gallery's tiles are screen pictures; give a single job for a figure of "
        "a printed size");
  for (const auto& job : g.jobs)
    if (const auto& p = job.output.print; !p.width.empty() || !p.font.empty() || !p.dpi.empty())
      throw io::BadInput(job.file.string() +
                         ": output.figure_width: a gallery's tiles are screen pictures; render "
                         "this job alone for a figure of a printed size");
  if (!o.out.empty()) g.dir = o.out;
  // --width and --height size every tile (gallery.png, the grid video) and
  // every job's video, which is otherwise drawn at the size its job asks for.
  if (!o.width.empty()) g.tile_width = int(parse_integer("--width", o.width, 16, 8192));
  if (!o.height.empty()) g.tile_height = int(parse_integer("--height", o.height, 16, 8192));
  io::check_output_dir(o.out.empty() ? g.file.string() + ": dir" : "--out", g.dir);
  if (still_format(o))
    throw io::BadInput("--format " + o.format +
                       ": a gallery writes gallery.png and videos; give a single job for a vector "
                       "still");
  format_option(o, g.videos);
  // Check every job before rendering any.
  std::vector<PreparedJob> stills, videos;
  RenderOptions job_opts = o;
  job_opts.out.clear();
  job_opts.format.clear();
  for (const auto& job : g.jobs) {
    auto ps = prepare(job::gallery_member(g, job, /*video=*/false), job_opts);
    const int at = job::gallery_still_frame(g, ps.plan.frames);
    ps.range = {at, at};
    ps.caption = job::tile_caption(ps.job, ps.plan);
    stills.push_back(std::move(ps));
    if (g.videos) {
      auto video = job::gallery_member(g, job, /*video=*/true);
      if (!o.width.empty()) video.scene.width = g.tile_width;
      if (!o.height.empty()) video.scene.height = g.tile_height;
      videos.push_back(prepare(std::move(video), job_opts));
    }
  }
  if (g.grid_video) {
    job::grid_video_size(g, int(stills.size()));
    if (!io::ffmpeg_available())
      throw io::BadInput(
          g.file.string() +
          ": grid_video: ffmpeg not found on PATH; install the Debian package ffmpeg");
  }
  fs::create_directories(g.dir);
  io::remove_stale_temporaries(g.dir);
  auto context = gl.open();
  paint::FramePainter painter(*context, g.tile_width, g.tile_height);

  std::vector<paint::GalleryStill> still_scenes;
  for (const auto& p : stills)
    still_scenes.push_back(
        {{&p.plan, &p.job.scene, p.caption}, p.range.first, p.job.file.stem().string()});
  const paint::GalleryFigure figure{g.dir / "gallery.png", g.tile_width, g.tile_height,
                                    job::gallery_tiling(g)};
  const auto drawn =
      paint::write_gallery_figure(still_scenes, figure, painter, progress_options(o, ""),
                                  [](const numerics::Failure& f) { report_failure(f); });
  int failures = drawn.failures;
  std::fprintf(summary_stream(o), "%s: %zu cases tiled into %s (%dx%d)\n", g.file.string().c_str(),
               stills.size(), figure.path.string().c_str(), drawn.width, drawn.height);

  nlohmann::json reports = nlohmann::json::array();

  for (const auto& p : videos) {
    // A painter of the video's own size; the tiles' one where they agree.
    std::optional<paint::FramePainter> own_size;
    if (p.job.scene.width != g.tile_width || p.job.scene.height != g.tile_height)
      own_size.emplace(*context, p.job.scene.width, p.job.scene.height);
    const auto st = render_frames(p, own_size ? *own_size : painter, o);
    print_job_line(summary_stream(o), p, st);
    reports.push_back(job_report(p, st));
    add_gl_report(reports.back(), *context);
    failures += report_failure(st.written.failure) != 0;
  }
  if (g.grid_video) failures += render_grid_video(g, stills, painter, o);
  if (!o.report_json.empty())
    io::write_file_atomically(o.report_json, io::json_text(reports, 2) + "\n");
  return failures ? 3 : 0;
}

int run_render(const RenderOptions& o) {
  if (o.list_jobs || o.help_job) {
    std::fputs(
        (o.list_jobs ? job::shipped_jobs_text(job::shipped_jobs_dir()) : job::job_keys_help())
            .c_str(),
        stdout);
    return 0;
  }
  if (o.job.empty())
    throw io::BadInput("render: give a job file or a shipped job's name (--list-jobs lists them)");
  io::check_output_file("--report-json", o.report_json);
  h5::check_h5_output("--h5", o.h5);
  // SIGINT/SIGTERM remove the temporaries of the frames and videos being written.
  io::install_temporary_cleanup();
  const render::GlChoice gl(o.gl);
  const fs::path job_file = job::job_file_named(o.job, job::shipped_jobs_dir());
  auto loaded = job::load_job_file(job_file);
  // No output may replace the job or a gallery's member job (io/output_paths.hpp).
  io::NamedPaths inputs{{"the job", job_file.string()}};
  if (loaded.gallery)
    for (const auto& member : loaded.gallery->jobs)
      inputs.emplace_back("a job of the gallery", member.file.string());
  io::require_separate_files(inputs, {{"--report-json", o.report_json}, {"--h5", o.h5}});
  if (loaded.bench) {
    if (!o.h5.empty())
      throw io::BadInput("--h5: a bench-figures job has no runs to write; give it a single job");
    if (!o.frames.empty() || !o.format.empty() || o.resume || !o.shard.empty())
      throw io::BadInput(o.job + ": a bench-figures job takes only --out and --gl");
    BenchRequest b;
    b.quick = loaded.bench->quick;
    for (const auto& c : loaded.bench->cases) b.cases += (b.cases.empty() ? "" : ",") + c;
    b.out = o.out.empty() ? loaded.bench->dir.string() : o.out;
    b.gl = o.gl;
    return run_bench(b);
  }
  if (loaded.gallery) return render_gallery(std::move(*loaded.gallery), o, gl);
  return render_single(std::move(*loaded.single), o, gl);
}

}  // namespace

std::function<int()> add_render_command(cli::Command app) {
  auto o = std::make_shared<RenderOptions>();
  cli::Command cmd = app.add_subcommand(
      "render", "Render a job (render_jobs/*.json) to PNG frames, a video, or a gallery");
  cmd.add_option("job", o->job,
                 "render job file (JSON), or the name of a shipped job (see --list-jobs)");
  cmd.add_flag("--list-jobs", o->list_jobs, "list the shipped jobs and exit");
  cmd.add_flag("--help-job", o->help_job,
               "list every key of a job file with its type, default and allowed values, and exit");
  cmd.add_option("--out", o->out, "output directory (overrides the job's output.dir)");
  cmd.add_option("--frames", o->frames, "frame range A:B (inclusive), A:, :B or N");
  cmd.add_option("--width", o->width, "frame width in pixels");
  cmd.add_option("--height", o->height, "frame height in pixels");
  cmd.add_option("--format", o->format,
                 "png|mp4|webm|gif, or svg|pdf: vector stills of --frames (default: the last "
                 "frame)");
  cmd.add_option("--figure-width", o->print.width,
                 "a figure for print, this wide (85mm, 8.5cm, 3.5in, 241pt): its text at "
                 "--font-size, its parts stacked in one column, as tall as they need; PNG "
                 "frames at --dpi");
  cmd.add_option("--font-size", o->print.font,
                 "with --figure-width: the text's size in points (5 to 24; default 8)");
  cmd.add_option("--dpi", o->print.dpi,
                 "with --figure-width: pixels per inch of the PNG frames and of the 3D view "
                 "embedded in an SVG or PDF (72 to 1200; default 300)");
  add_gl_option(cmd, o->gl);
  cmd.add_option("--report-json", o->report_json,
                 "write what was rendered (tolerance chosen, timings) as JSON ('-': standard "
                 "output; the summary lines then go to stderr)");
  cmd.add_option("--shard", o->shard,
                 "I/N: draw only shard I (from 0) of N, a contiguous range of frames (default "
                 "from an array job's environment; epviz merge joins video segments)");
  cmd.add_option("--shard-count", o->shard_count,
                 "N: the number of shards when the environment gives only the index");
  cmd.add_option("--h5", o->h5,
                 "also write the job's runs and its cloud to this HDF5 file: a group per run "
                 "(run0, ...) with simulate's CSV columns, a group cloud with [member, frame] "
                 "datasets; the job and the report as attributes (JSON)");
  cmd.add_flag("--resume", o->resume, "PNG: skip frames already written completely");
  cmd.add_flag("--quiet", o->quiet, "no progress line");
  cmd.add_flag("--progress", o->progress, "progress line even when stderr is not a terminal");
  return [o] { return run_render(*o); };
}

}  // namespace epviz::app
