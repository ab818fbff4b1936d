#include "app/section_command.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <memory>

#include "app/cli_values.hpp"
#include "app/gl_option.hpp"
#include "io/bad_input.hpp"
#include "io/png_writer.hpp"
#include "section/section_chart.hpp"
#include "section/section_csv.hpp"
#include "section/section_run.hpp"
#ifdef EPVIZ_HAVE_RENDER
#include "paint/figure_painter.hpp"
#include "render/gl_choice.hpp"
#include "vector/vector_figure.hpp"
#endif

namespace epviz::app {
namespace {

struct SectionOptions {
  std::string file, jobs, gl;  // the section file, -j, --gl
};

void draw(const section::SectionJob& job, const chart::ChartSpec& spec, const std::string& gl) {
#ifdef EPVIZ_HAVE_RENDER
  const paint::ChartOptions size{.width = 1100, .height = 1000, .font_px = 15.0f};
  if (!job.png.empty()) {
    const auto image = paint::paint_figure(*render::GlChoice(gl).open(), {job.png, spec}, size);
    io::write_png_rgba(job.png, image.width, image.height, image.pixels);
  }
  if (!job.svg.empty())
    vector::write_vector_figure(job.svg, {job.svg, spec}, vector::FigureFormat::svg, size);
#else
  if (!job.png.empty() || !job.svg.empty())
    throw io::BadInput(job.file + ": keys 'png', 'svg': this epviz was built without the renderer");
  (void)spec, (void)gl;
#endif
}

int run_section(const SectionOptions& o) {
  const section::SectionJob job = section::read_section_job(o.file);
  const int threads =
      section::thread_count(o.jobs.empty() ? 0 : parse_integer("-j", o.jobs, 1, 4096));
  section::check_outputs(job);
  const auto starts = section::section_starts(job);
#ifndef EPVIZ_HAVE_RENDER
  draw(job, {}, o.gl);  // refuses pictures before any work
#endif
  const auto start = std::chrono::steady_clock::now();
  const auto results = section::run_section(job, starts, threads);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (const std::string lost = section::lost_orbits_line(results); !lost.empty()) {
    std::fprintf(stderr, "epviz: error: %s: %s (nothing written)\n", o.file.c_str(), lost.c_str());
    return 3;
  }
  section::write_crossings_csv(job, results);
  draw(job, section::section_chart(job, results), o.gl);
  std::fprintf(job.csv == "-" ? stderr : stdout, "%s: %s in %.2f s (%d threads)\n", o.file.c_str(),
               section::summary(job, results).c_str(), seconds, threads);
  return 0;
}

}  // namespace

std::function<int()> add_section_command(CLI::App& app) {
  auto o = std::make_shared<SectionOptions>();
  auto* cmd = app.add_subcommand(
      "section", "Poincare section (SECTION.json): crossings of a surface by orbits on a level");
  cmd->add_option("section", o->file, "section file (JSON; docs/sections.md)")->required();
  cmd->add_option("-j,--jobs", o->jobs, "threads (default: all cores)");
  add_gl_option(*cmd, o->gl, "for the PNG");
  return [o] { return run_section(*o); };
}

}  // namespace epviz::app
