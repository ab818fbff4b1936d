#include "app/section_command.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <utility>

#include "app/cli_values.hpp"
#include "app/gl_option.hpp"
#include "app/h5_output.hpp"
#include "app/print_options.hpp"
#include "h5/columns_file.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/json_reader.hpp"
#include "io/png_writer.hpp"
#include "io/temp_registry.hpp"
#include "job/shipped_jobs.hpp"
#include "section/section_chart.hpp"
#include "section/section_csv.hpp"
#include "section/section_run.hpp"
#include "section/section_shard.hpp"
#include "shard/shard_lock.hpp"
#include "shard/shard_spec.hpp"
#ifdef EPVIZ_HAVE_RENDER
#include "paint/figure_painter.hpp"
#include "paint/figure_panels.hpp"
#include "render/gl_choice.hpp"
#include "vector/vector_figure.hpp"
#endif

namespace epviz::app {
namespace {

struct SectionOptions {
  std::string file, out, jobs, gl, shard, shard_count, h5;  // the section file, --out, -j, ...
  io::PrintSizeText print;                                  // --figure-width, --font-size, --dpi
};

// The pictures' printed size: the command line's options over the file's keys.
std::optional<io::PrintSize> section_print_size(const section::SectionJob& job,
                                                const io::PrintSizeText& command_line) {
  return print_size_over(command_line, job.print, section::print_key_names(job));
}

// One chart per method, side by side on the same axes when there are several;
// the charts are built only when the file asks for a picture.
void draw(const section::SectionJob& job, const std::vector<section::OrbitResult>& results,
          const std::string& gl, const std::optional<io::PrintSize>& print) {
  if (job.png.empty() && job.svg.empty() && job.pdf.empty()) return;
  for (const auto& w : section::fold_warnings(job, results))
    std::fprintf(stderr, "%s\n", w.c_str());
#ifdef EPVIZ_HAVE_RENDER
  auto charts = section::section_charts(job, results);
  const bool one = charts.size() == 1;
  // At a printed size a row of panels is the width asked, as many panels to
  // a row as are wide enough to read.
  const int gap = panel_gap(16, print);
  const int columns = panel_columns(int(charts.size()), print, gap);
  const paint::ChartOptions size = chart_options(
      {.width = one ? 1100 : 760, .height = one ? 1000 : 720, .font_px = one ? 15.0f : 13.0f},
      print, columns, gap);
  std::vector<chart::Figure> panels;
  for (auto& c : charts) panels.push_back({job.png, std::move(c)});
  if (!job.png.empty()) {
    const auto image =
        paint::paint_drawing(*render::GlChoice(gl).open(), size, [&](const paint::ChartFont& font) {
          std::vector<paint::FigureDrawing> drawings;
          for (const auto& p : panels) drawings.push_back(paint::draw_figure(p, size, font));
          return paint::panel_grid(drawings, columns, gap);
        });
    io::write_png_rgba(job.png, image.width, image.height, image.pixels);
  }
  if (!job.svg.empty())
    vector::write_vector_panels(job.svg, panels, vector::FigureFormat::svg, size, gap, columns);
  if (!job.pdf.empty())
    vector::write_vector_panels(job.pdf, panels, vector::FigureFormat::pdf, size, gap, columns);
#else
  (void)results, (void)gl, (void)print;
  throw io::BadInput(job.file +
                     ": keys 'png', 'svg', 'pdf': this epviz was built without the renderer");
#endif
}

// The crossings as the CSV's columns (section::crossing_columns), the section
// file (when it can still be read) and a short report as attributes.
void write_section_h5(const std::string& path, const section::SectionJob& job,
                      const std::vector<section::OrbitResult>& results, nlohmann::json report) {
  h5::ColumnsFile file(path, section::crossing_columns(job));
  long crossings = 0;
  section::for_each_crossing_row(job, results, [&](std::span<const double> row) {
    file.append(row);
    ++crossings;
  });
  write_provenance(file);
  std::error_code ec;
  if (std::filesystem::is_regular_file(job.file, ec))
    file.set_attribute("job", io::read_json_file(job.file).dump());
  nlohmann::json methods = nlohmann::json::array();
  for (const auto& m : job.methods) methods.push_back(section::method_label(m));
  file.set_attribute("methods", methods.dump());
  report["runs"] = results.size();
  report["crossings"] = crossings;
  report["methods"] = methods;
  file.set_attribute("report", report.dump());
  file.set_attribute("failed", 0L);
  file.commit();
}

int run_section(const SectionOptions& o) {
  section::SectionJob job = section::read_section_job(o.file);
  const int threads =
      section::thread_count(o.jobs.empty() ? 0 : parse_integer("-j", o.jobs, 1, 4096));
  const auto shard = shard::shard_from_options(o.shard, o.shard_count);
#ifdef EPVIZ_HAVE_RENDER
  (void)render::GlChoice(o.gl);  // an unknown backend is refused before the CSV is written
#endif
  if (!o.out.empty()) job.csv = o.out;
  const auto print = section_print_size(job, o.print);
  h5::check_h5_output("--h5", o.h5);
  section::check_outputs(job, o.out.empty() ? "" : "--out", {{"--h5", o.h5}});
  const auto starts = section::section_starts(job);
  const long runs = section::run_count(job, starts.size());
  std::optional<shard::RowsShard> part;
  if (shard && job.csv == "-")
    throw io::BadInput(
        "--shard: a shard writes its crossings beside the CSV; give \"csv\" (or --out) a file, not "
        "standard output");
  if (shard && !o.h5.empty())
    throw io::BadInput(
        "--h5: a shard writes only its crossings' CSV; give --h5 to the whole section instead");
  if (shard) part = section::plan_section_shard(job, runs, *shard, o.jobs);
#ifndef EPVIZ_HAVE_RENDER
  if (!part) draw(job, {}, o.gl, print);  // refuses pictures before any work
#endif
  // As simulate and render: SIGINT and SIGTERM remove the temporaries being
  // written, and those a run killed with SIGKILL left are removed now.
  io::install_temporary_cleanup();
  for (const auto& path : {job.csv, job.png, job.svg, job.pdf, o.h5})
    io::remove_stale_temporaries_beside(path);
  // Held to the end, so that a second copy of this shard refuses (shard/shard_lock.hpp).
  std::optional<shard::ShardLock> lock;
  if (part) {
    lock.emplace(part->lock_path);
    shard::start_rows_shard(*part);  // "completed": false until the end
  }
  const auto start = std::chrono::steady_clock::now();
  const auto results =
      section::run_section(job, starts, threads, part ? std::optional(part->points) : std::nullopt);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (const std::string lost = section::lost_orbits_line(job, results); !lost.empty()) {
    std::fprintf(stderr, "epviz: error: %s: %s (nothing written)\n", o.file.c_str(), lost.c_str());
    return 3;
  }
  std::string done = section::summary(job, starts.size(), results);
  if (part) {
    // The shard's crossings only; `epviz merge` joins them and draws the pictures.
    job.csv = part->rows.string();
    section::write_crossings_csv(job, results);
    shard::finish_rows_shard(*part);
    // The crossings are the shard's, the orbits the whole section's.
    std::string which = "shard ";
    which += std::to_string(shard->index);
    which += "/";
    which += std::to_string(shard->count);
    which += ", runs ";
    which += std::to_string(part->points.first);
    which += "..";
    which += std::to_string(part->points.end - 1);
    which += " of ";
    done = which + done;
  } else {
    section::write_crossings_csv(job, results);
    if (!o.h5.empty())
      write_section_h5(o.h5, job, results, {{"summary", done}, {"seconds", seconds}});
    draw(job, results, o.gl, print);
  }
  std::fprintf(job.csv == "-" ? stderr : stdout, "%s: %s in %.2f s (%d threads)\n", o.file.c_str(),
               done.c_str(), seconds, threads);
  return 0;
}

}  // namespace

void check_merged_section(const section::MergedSection& merged, const io::PrintSizeText& print) {
  (void)section_print_size(merged.job, print);
}

void write_merged_section(const section::MergedSection& merged, const std::string& gl,
                          const std::string& h5, const io::PrintSizeText& print) {
  io::write_file_atomically(merged.job.csv, merged.csv_text);
  if (!h5.empty()) {
    write_section_h5(h5, merged.job, merged.results, nlohmann::json::object());
    std::printf("section %s: crossings -> %s\n", merged.job.file.c_str(), h5.c_str());
  }
  draw(merged.job, merged.results, gl, section_print_size(merged.job, print));
  std::printf("section %s: %zu runs -> %s\n", merged.job.file.c_str(), merged.results.size(),
              merged.job.csv.c_str());
}

std::function<int()> add_section_command(cli::Command app) {
  auto o = std::make_shared<SectionOptions>();
  cli::Command cmd = app.add_subcommand(
      "section", "Poincare section (SECTION.json): crossings of a surface by orbits on a level");
  cmd.add_option("section", o->file,
                 "section file (JSON; docs/sections.md), or the name of a shipped section "
                 "(epviz render --list-jobs lists them)")
      .required();
  cmd.add_option("--out", o->out, "the crossings' CSV (default: the file's \"csv\")");
  cmd.add_option("-j,--jobs", o->jobs, "threads (default: all cores)");
  add_gl_option(cmd, o->gl, "for the PNG");
  cmd.add_option("--h5", o->h5,
                 "also write the crossings to this HDF5 file: a float64 dataset per CSV column "
                 "(the method as its index into the attribute \"methods\"), the section file "
                 "and a report as attributes (JSON)");
  cmd.add_option("--shard", o->shard,
                 "I/N: run only shard I (from 0) of N, a contiguous range of the orbits; default "
                 "from SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX or AWS_BATCH_JOB_ARRAY_INDEX; "
                 "`epviz merge` joins the shards and draws the pictures");
  cmd.add_option("--shard-count", o->shard_count,
                 "N: the number of shards when the environment gives only the index");
  add_print_options(cmd, o->print);  // over the file's "figure_width", "font_size", "dpi"
  return [o] {
    o->file = job::job_file_named(o->file, job::shipped_jobs_dir(), job::ShippedKind::section);
    return run_section(*o);
  };
}

}  // namespace epviz::app
