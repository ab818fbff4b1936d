#include "app/diagram_command.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli_values.hpp"
#include "app/diagram_figure.hpp"
#include "app/diagram_regions.hpp"
#include "app/diagram_sections.hpp"
#include "app/gl_option.hpp"
#include "app/print_options.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/output_paths.hpp"
#include "physics/cases.hpp"
#include "physics/critical_values.hpp"
#include "section/section_csv.hpp"
#include "section/section_run.hpp"
#ifdef EPVIZ_HAVE_RENDER
#include "io/png_writer.hpp"
#include "paint/figure_painter.hpp"
#include "render/gl_choice.hpp"
#include "vector/vector_figure.hpp"
#endif

namespace epviz::app {
namespace {

namespace fs = std::filesystem;

struct DiagramOptions {
  std::string case_name, area, energy_max, inertia, com, weight, samples, out = ".", format, gl;
  std::string sections, section_crossings;  // --sections ORBITS, --section-crossings
  io::PrintSizeText print;                  // --figure-width, --font-size, --dpi
};

// The option a physics::InvalidInput's field came from.
std::string diagram_option(const std::string& field) {
  if (field == "body") return "--inertia, --com, --weight";
  if (field == "energy_max") return "--energy-max";
  return "--" + field;
}

physics::DiagramRequest diagram_request(const DiagramOptions& o) {
  physics::DiagramRequest r;
  const auto c = physics::case_from_name(o.case_name);
  if (!c || (*c != physics::Case::kovalevskaya && *c != physics::Case::lagrange))
    throw io::BadInput("--case: '" + o.case_name +
                       "' has no bifurcation diagram (allowed: kovalevskaya, lagrange)");
  r.case_id = *c;
  r.body = physics::preset(*c).body;
  r.area = parse_number("--area", o.area);
  if (!o.energy_max.empty()) r.energy_max = parse_number("--energy-max", o.energy_max);
  const auto vec = [](const std::array<double, 3>& v) { return Eigen::Vector3d(v[0], v[1], v[2]); };
  if (!o.inertia.empty()) r.body.inertia = vec(parse_vec3("--inertia", o.inertia));
  if (!o.com.empty()) r.body.com = vec(parse_vec3("--com", o.com));
  if (!o.weight.empty()) r.body.weight = parse_number("--weight", o.weight);
  if (!o.samples.empty()) r.samples = int(parse_integer("--samples", o.samples, 0, 1000000));
  return r;
}

// --sections: orbits per region (0: no sections); --section-crossings: per orbit.
struct SectionsRequest {
  int orbits = 0;
  int crossings = 200;
};

// The regions are found from the sampled states: fewer than this leave thin
// regions without a sample (docs/diagram.md).
constexpr int kSectionsMinSamples = 2000;

SectionsRequest sections_request(const DiagramOptions& o, const physics::DiagramRequest& r) {
  SectionsRequest s;
  if (!o.sections.empty()) s.orbits = int(parse_integer("--sections", o.sections, 1, 64));
  if (!o.section_crossings.empty()) {
    if (o.sections.empty())
      throw io::BadInput("--section-crossings: only with --sections (orbits per region)");
    s.crossings = int(parse_integer("--section-crossings", o.section_crossings, 1, 100000));
  }
  if (s.orbits > 0 && r.samples < kSectionsMinSamples)
    throw io::BadInput(
        "--samples: --sections finds the regions from the sampled states; give at "
        "least " +
        std::to_string(kSectionsMinSamples) + " (default 20000)");
  return s;
}

// A file to write, its bytes made first: the figure is drawn in memory so that
// nothing is written when drawing fails.
struct OutputFile {
  fs::path path;
  std::string bytes;
};

#ifdef EPVIZ_HAVE_RENDER
OutputFile draw_diagram(const chart::Figure& figure, const DiagramOptions& o,
                        const std::optional<io::PrintSize>& print, int panels = 1) {
  const auto format = vector::parse_figure_format(o.format);
  // A section's two sheets side by side, each about the diagram's height.
  const paint::ChartOptions size =
      panels == 1 ? chart_options({.width = 1200, .height = 900, .font_px = 15.0f}, print)
                  : chart_options({.width = 700 * panels, .height = 760, .font_px = 14.0f}, print);
  OutputFile file{fs::path(o.out) / vector::figure_file_name(figure.file_name, format), {}};
  if (format == vector::FigureFormat::png) {
    const auto image = paint::paint_figure(*render::GlChoice(o.gl).open(), figure, size);
    const auto png = io::encode_png_rgba(image.width, image.height, image.pixels);
    file.bytes.assign(png.begin(), png.end());
  } else {
    file.bytes = vector::vector_figure_bytes(figure, format, size);
  }
  return file;
}
#endif

int run_diagram(const DiagramOptions& o) {
  // Every option is checked before the searches, which take seconds.
  physics::DiagramRequest request = diagram_request(o);
  const SectionsRequest sections = sections_request(o, request);
  const auto print = io::parse_print_size(o.print);
#ifdef EPVIZ_HAVE_RENDER
  (void)vector::parse_figure_format(o.format);
  (void)render::GlChoice(o.gl);
#endif
  io::check_output_dir("--out", o.out);
  try {
    (void)physics::check_diagram_request(request);
  } catch (const physics::InvalidInput& e) {
    throw io::BadInput(diagram_option(e.field()) + ": " + e.what());
  }
  io::make_output_folder("--out", o.out);

  const physics::BifurcationDiagram diagram = physics::bifurcation_diagram(request);
  const fs::path out(o.out);
  std::vector<OutputFile> files{{out / "diagram.csv", critical_curves_csv(diagram)},
                                {out / "sampled.csv", sampled_values_csv(diagram)}};
  std::vector<DiagramRegion> regions;
  std::vector<std::string> region_lines;
  if (sections.orbits > 0) {
    regions = diagram_regions(diagram);
    files.push_back({out / "regions.csv", regions_csv(regions)});
    for (const auto& region : regions) {
      const auto starts = region_starts(request, region.point, sections.orbits);
      if (starts.empty()) {
        std::fprintf(stderr,
                     "epviz: error: --sections: region %s at (%.6g, %.6g): no state of the level "
                     "was moved onto that value of the integral (nothing written)\n",
                     region.label.c_str(), region.point.energy, region.point.integral);
        return 3;
      }
      const fs::path csv = out / ("section_" + region.label + ".csv");
      const int threads = section::thread_count(0);
      const section::SectionJob job =
          region_section_job(request, starts, sections.crossings, csv.string(),
                             region_surface(request, starts, threads));
      const auto results = section::run_section(job, starts, threads);
      if (const std::string lost = section::lost_orbits_line(job, results); !lost.empty()) {
        std::fprintf(stderr, "epviz: error: --sections: region %s: %s (nothing written)\n",
                     region.label.c_str(), lost.c_str());
        return 3;
      }
      files.push_back({csv, section::crossings_csv(job, results)});
#ifdef EPVIZ_HAVE_RENDER
      const auto figure = region_section_figure(request, region, job, results);
      files.push_back(draw_diagram(figure, o, print,
                                   int(std::get<chart::ChartSpec>(figure.content).panels.size())));
#endif
      char line[200];
      std::snprintf(line, sizeof line, "region %s at (%.6g, %.6g), %zu sampled states: %s",
                    region.label.c_str(), region.point.energy, region.point.integral,
                    region.samples, section::summary(job, starts.size(), results).c_str());
      region_lines.push_back(line);
    }
  }
#ifdef EPVIZ_HAVE_RENDER
  files.push_back(draw_diagram(diagram_figure(request, diagram, regions), o, print));
#else
  (void)print;
  std::fprintf(stderr, "epviz diagram: no figure (this epviz was built without the renderer)\n");
#endif
  for (const auto& f : files) io::write_file_atomically(f.path, f.bytes);

  std::size_t drawn = 0, points = 0;
  for (const auto& c : diagram.curves) {
    drawn += !c.points.empty();
    for (const auto& p : c.points) points += std::isfinite(p.energy);
  }
  std::printf(
      "diagram of the %s at C0 = %g, C1 from %.6g to %.6g: %zu critical curves (%zu points), "
      "%zu sampled states ->",
      physics::case_name(request.case_id).c_str(), request.area, diagram.energy_min,
      diagram.energy_max, drawn, points, diagram.sampled.size());
  for (const auto& f : files) std::printf(" %s", f.path.c_str());
  std::printf("\n");
  if (sections.orbits > 0)
    std::printf("%zu region%s\n", regions.size(), regions.size() == 1 ? "" : "s");
  for (const auto& l : region_lines) std::printf("%s\n", l.c_str());
  return 0;
}

}  // namespace

std::function<int()> add_diagram_command(cli::Command app) {
  auto o = std::make_shared<DiagramOptions>();
  cli::Command cmd = app.add_subcommand(
      "diagram",
      "Bifurcation diagram of an integrable top at a fixed area C0: the critical values of (C1, "
      "fourth integral) that real states attain, over the sampled image of the level");
  cmd.add_option("--case", o->case_name, "kovalevskaya or lagrange").required();
  cmd.add_option("--area", o->area, "the area constant C0 of the level").required();
  cmd.add_option("--energy-max", o->energy_max,
                 "the largest energy C1 shown (default: past the diagram's last feature)");
  cmd.add_option("--inertia", o->inertia, "I1,I2,I3 (default: the case's preset body)");
  cmd.add_option("--com", o->com, "a0,b0,c0, the centre of mass (default: the preset's)");
  cmd.add_option("--weight", o->weight, "P (default: the preset's)");
  cmd.add_option("--samples", o->samples,
                 "states of the level sampled for the admissible region (default 20000)");
  cmd.add_option("--out", o->out,
                 "folder for diagram.csv, sampled.csv and the figure (default: the current one)");
  cmd.add_option("--format", o->format,
                 "the figure's file: png (GL), svg or pdf (cairo, vector; no GL needed) "
                 "(default png)");
  cmd.add_option("--sections", o->sections,
                 "ORBITS (1 to 64): for each region the critical curves cut the level's image "
                 "into, a Poincare section (gamma3 = 0 upward) of this many orbits on the value "
                 "(C1, integral) of a point inside it: section_<region>.csv and a figure; the "
                 "points are marked on the diagram");
  cmd.add_option("--section-crossings", o->section_crossings,
                 "crossings per orbit of --sections (1 to 100000, default 200)");
  add_gl_option(cmd, o->gl, "for the PNG");
  add_print_options(cmd, o->print);
  return [o] { return run_diagram(*o); };
}

}  // namespace epviz::app
