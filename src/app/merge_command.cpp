#include "app/merge_command.hpp"

#include <cstdio>
#include <filesystem>
#include <optional>
#include <thread>

#include "app/gl_option.hpp"
#include "app/h5_output.hpp"
#include "app/print_options.hpp"
#include "app/section_command.hpp"
#include "h5/columns_file.hpp"
#include "h5/json_rows.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/json_reader.hpp"
#include "io/json_text.hpp"
#include "io/output_paths.hpp"
#include "io/shell_quote.hpp"
#include "io/video_join.hpp"
#include "shard/batch.hpp"
#include "shard/merged_rows.hpp"
#include "shard/resubmit.hpp"
#include "sweep/atlas.hpp"
#include "sweep/ftle_curves.hpp"
#include "sweep/self_check.hpp"
#include "sweep/sweep_spec.hpp"
#ifdef EPVIZ_HAVE_RENDER
#include "render/gl_choice.hpp"
#include "vector/figure_files.hpp"
#include "vector/figure_format.hpp"
#endif

namespace epviz::app {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

struct MergeOptions {
  std::string dir, out, gl, format, resubmit;
  std::vector<std::string> atlases;
  io::PrintSizeText print;  // --figure-width, --font-size, --dpi
  bool allow_unconverged = false;
  bool h5 = false;
};

// "stability_atlas.jsonl" -> "stability_atlas.h5": the HDF5 file written
// beside a merged file (--h5).
fs::path h5_beside(const fs::path& merged) {
  fs::path p = merged;
  return p.replace_extension(".h5");
}

// This merge as a command line with absolute paths, run again by the
// resubmit script once the failed shards are redone.
std::vector<std::string> merge_command_line(const MergeOptions& o) {
  const auto absolute = [](const std::string& p) {
    return fs::absolute(p).lexically_normal().string();
  };
  std::vector<std::string> c{"epviz", "merge", absolute(o.dir)};
  if (!o.out.empty()) c.insert(c.end(), {"--out", absolute(o.out)});
  for (const auto& a : o.atlases) c.insert(c.end(), {"--atlas", a});
  if (!o.format.empty()) c.insert(c.end(), {"--format", o.format});
  if (!o.print.width.empty()) c.insert(c.end(), {"--figure-width", o.print.width});
  if (!o.print.font.empty()) c.insert(c.end(), {"--font-size", o.print.font});
  if (!o.print.dpi.empty()) c.insert(c.end(), {"--dpi", o.print.dpi});
  if (!o.gl.empty()) c.insert(c.end(), {"--gl", o.gl});
  if (o.allow_unconverged) c.push_back("--allow-unconverged");
  if (o.h5) c.push_back("--h5");
  c.insert(c.end(), {"--resubmit", absolute(o.resubmit)});
  return c;
}

// Writes a sweep's figures in --format, each named on a line after `what`.
void write_sweep_figures(const std::vector<chart::Figure>& figures, const char* what,
                         const fs::path& out_dir, const MergeOptions& o) {
  if (figures.empty()) return;
#ifdef EPVIZ_HAVE_RENDER
  // At a printed size a heat map is the width asked and as tall as its rows'
  // labels need, not this aspect's height.
  const paint::ChartOptions options =
      chart_options({.width = 1280, .height = 900}, io::parse_print_size(o.print));
  for (const auto& path : vector::write_figures(
           figures, out_dir, vector::parse_figure_format(o.format), o.gl, options))
    std::printf("  %s %s\n", what, path.string().c_str());
#else
  (void)what;
  (void)out_dir;
  (void)o;
  throw io::BadInput("--atlas: this epviz was built without the renderer (EPVIZ_BUILD_RENDER=OFF)");
#endif
}

// `ftle`: the sweep's FTLE settings, named in the captions; nullopt when unknown.
void draw_atlases(const std::vector<Json>& rows, const std::vector<sweep::AtlasRequest>& requests,
                  const std::optional<sweep::FtleSettings>& ftle, const sweep::SelfCheck* check,
                  const fs::path& out_dir, const MergeOptions& o) {
  // As figures: no taller than the grid needs (a few rows leave no blank band).
  std::vector<chart::Figure> figures;
  // One set: every map of the sweep gets the same plot rectangle.
  for (auto& f : sweep::atlas_figure_set(rows, requests, ftle, check))
    figures.push_back({std::move(f.file_name), std::move(f.heat_map)});
  write_sweep_figures(figures, "atlas", out_dir, o);
}

// The sweep file, when it is still there and unchanged (its atlases and FTLE
// settings are then those of the rows); else nullopt.
std::optional<sweep::SweepSpec> saved_sweep(const shard::Manifest& m, const std::string& hash) {
  try {
    auto spec = sweep::read_sweep_file(m.source);
    if (spec.hash == hash) return spec;
  } catch (const std::exception&) {
    // Gone or edited since: only --atlas figures, without the FTLE settings.
  }
  return std::nullopt;
}

// The atlases to draw of a sweep: --atlas, else those of its sweep file.
std::vector<sweep::AtlasRequest> atlas_requests(const std::optional<sweep::SweepSpec>& saved,
                                                const MergeOptions& o) {
  std::vector<sweep::AtlasRequest> requests;
  for (const auto& a : o.atlases) requests.push_back(sweep::parse_atlas_option(a));
  if (o.atlases.empty() && saved) requests = saved->atlases;
  return requests;
}

// Returns false when the sweep's self-check found it not converged.
bool merge_sweep(const shard::Batch& b, const std::vector<Json>& rows, const fs::path& out_dir,
                 const MergeOptions& o) {
  std::string text;
  for (const auto& r : rows) text += io::json_text(r) + "\n";
  const auto& any = b.shards.begin()->second;
  const fs::path out = out_dir / any.output;
  io::write_file_atomically(out, text);
  std::printf("%s: %zu rows -> %s\n", shard::batch_name(b).c_str(), rows.size(),
              out.string().c_str());
  if (o.h5) {
    // The rows as sweep --h5 writes them (merged rows are in point order).
    h5::ColumnsFile file(h5_beside(out), {});
    h5::write_json_rows(file, rows);
    write_provenance(file);
    std::error_code ec;
    if (fs::is_regular_file(any.source, ec))
      file.set_attribute("job", io::read_json_file(any.source).dump());
    long failed = 0;
    for (const auto& r : rows) failed += r.contains("failure_kind") && !r["failure_kind"].is_null();
    file.set_attribute("report", Json{{"points", rows.size()},
                                      {"rows", rows.size()},
                                      {"failed_points", failed},
                                      {"rows_file", out.string()}}
                                     .dump());
    file.set_attribute("failed", 0L);
    file.commit();
    std::printf("%s: rows -> %s\n", shard::batch_name(b).c_str(), h5_beside(out).string().c_str());
  }
  const auto saved = saved_sweep(any, b.hash);
  const auto requests = atlas_requests(saved, o);
  // The sample is rerun here, where every row and the sweep file are at hand
  // (docs/cluster.md, "Atlases check themselves").
  std::optional<sweep::SelfCheck> check;
  if (saved && !sweep::checked_metrics(*saved).empty()) {
    check = sweep::run_self_check(*saved, rows, requests,
                                  int(std::max(1u, std::thread::hardware_concurrency())));
    const fs::path file = out_dir / sweep::self_check_file_name(any.output);
    io::write_file_atomically(file, io::json_text(sweep::self_check_json(*check), 1) + "\n");
    for (const auto& line : sweep::self_check_lines(*check)) std::printf("  %s\n", line.c_str());
  } else if (!saved &&
             (rows.front().contains("ftle") || rows.front().contains("reference_error"))) {
    std::printf("  no self-check: the sweep file %s is gone or changed\n", any.source.c_str());
  }
  const auto ftle = saved ? saved->ftle : std::nullopt;
  draw_atlases(rows, requests, ftle, check ? &*check : nullptr, out_dir, o);
  if (auto curves = sweep::ftle_curve_figure(rows, ftle))
    write_sweep_figures({std::move(*curves)}, "λ(T)", out_dir, o);
  return !check || check->converged();
}

void merge_render(const shard::Batch& b, const fs::path& dir, const fs::path& out_dir) {
  const auto& any = b.shards.begin()->second;
  if (any.output.empty()) {
    long frames = 0;
    for (const auto& [i, m] : b.shards) frames += long(m.files.size());
    std::printf("%s: %ld PNG frames complete in %s\n", shard::batch_name(b).c_str(), frames,
                dir.string().c_str());
    return;
  }
  std::vector<fs::path> segments;
  for (const auto& [i, m] : b.shards)
    for (const auto& f : m.files) segments.push_back(dir / f.path);
  io::join_video_segments(segments, out_dir / any.output);
  std::printf("%s: %zu segments joined -> %s\n", shard::batch_name(b).c_str(), b.shards.size(),
              (out_dir / any.output).string().c_str());
}

// What the merge reads (each shard's manifest, lock and files, each batch's
// sweep or section file) and writes (--resubmit, the merged files), for the
// one check that no output replaces an input or another output
// (io/output_paths.hpp). `sections`: the sections' pictures, once their
// files are read (empty before).
void require_separate_merge_files(
    const std::vector<shard::Batch>& batches, const fs::path& dir, const fs::path& out_dir,
    const MergeOptions& o,
    const std::vector<std::optional<section::MergedSection>>& sections = {}) {
  io::NamedPaths inputs, outputs{{"--resubmit", o.resubmit}};
  for (std::size_t i = 0; i < batches.size(); ++i) {
    const auto& b = batches[i];
    const std::string name = shard::batch_name(b);
    for (const auto& [index, m] : b.shards) {
      const std::string shard_name =
          "shard " + std::to_string(index) + "/" + std::to_string(b.count) + " of " + name;
      inputs.emplace_back("the manifest of " + shard_name,
                          (dir / shard::manifest_name(b.stem, m.shard)).string());
      inputs.emplace_back("the lock of " + shard_name,
                          (dir / shard::lock_name(b.stem, m.shard)).string());
      for (const auto& f : m.files)
        inputs.emplace_back("a file of " + shard_name, (dir / f.path).string());
    }
    const auto& any = b.shards.begin()->second;
    inputs.emplace_back("the " + b.kind + " file of " + name, any.source);
    if (any.output.empty()) continue;
    const fs::path merged = out_dir / any.output;
    outputs.emplace_back("the merged output of " + name, merged.string());
    if (o.h5 && b.kind != "render")
      outputs.emplace_back("the --h5 file of " + name, h5_beside(merged).string());
    if (b.kind == "sweep")
      outputs.emplace_back("the self-check of " + name,
                           (out_dir / sweep::self_check_file_name(any.output)).string());
    if (i < sections.size() && sections[i]) {
      outputs.emplace_back("the PNG of " + name, sections[i]->job.png);
      outputs.emplace_back("the SVG of " + name, sections[i]->job.svg);
      outputs.emplace_back("the PDF of " + name, sections[i]->job.pdf);
    }
  }
  io::require_separate_files(inputs, outputs);
}

int run_merge(const MergeOptions& o) {
#ifdef EPVIZ_HAVE_RENDER
  (void)render::GlChoice(o.gl);  // an unknown backend is refused before anything is merged
  (void)vector::parse_figure_format(o.format);
#endif
  for (const auto& a : o.atlases) (void)sweep::parse_atlas_option(a);
  (void)io::parse_print_size(o.print);
  const fs::path dir = o.dir;
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw io::BadInput("DIR: '" + o.dir +
                       "' is not a directory (give the directory the shards wrote to)");
  const fs::path out_dir = o.out.empty() ? dir : fs::path(o.out);
  io::check_output_dir("--out", out_dir);
  if (!o.resubmit.empty()) io::check_output_file("--resubmit", o.resubmit);
  auto batches = shard::read_batches(dir);
  if (batches.empty())
    throw io::BadInput("DIR: no shard manifests (*" + std::string(shard::manifest_suffix) +
                       ") in " + o.dir +
                       "; run epviz sweep or render with --shard I/N there first");
  require_separate_merge_files(batches, dir, out_dir, o);
  int incomplete = 0, to_redo = 0;
  for (auto& b : batches) {
    shard::check_batch(b, dir);
    const auto report = shard::batch_report(b);
    for (const auto& line : report) std::fprintf(stderr, "epviz: %s\n", line.c_str());
    incomplete += !report.empty();
    to_redo += !b.incomplete.empty();
  }
  if (incomplete) {
    std::fprintf(stderr, "epviz: error: %d of %zu batches in %s are incomplete; nothing merged\n",
                 incomplete, batches.size(), o.dir.c_str());
    if (!o.resubmit.empty() && to_redo) {  // shards still running are not redone
      io::write_file_atomically(o.resubmit,
                                shard::slurm_resubmit_script(batches, merge_command_line(o)));
      std::fprintf(stderr, "epviz: to redo only those shards on Slurm, then this merge: bash %s\n",
                   io::shell_quote(o.resubmit).c_str());
    }
    return 4;
  }
  // The merged files are written inside the output folder, never through a
  // link (which could lead anywhere).
  for (const auto& b : batches)
    if (const auto& name = b.shards.begin()->second.output; !name.empty())
      if (const auto link = shard::link_within(out_dir, name); !link.empty())
        throw io::BadInput(link.string() + ": is a symbolic link; merge writes " + name +
                           " only as a regular file in " + out_dir.string());
  // Every sweep's rows are read and checked before anything is written.
  std::vector<std::vector<Json>> rows(batches.size());
  std::vector<std::optional<section::MergedSection>> sections(batches.size());
  for (std::size_t i = 0; i < batches.size(); ++i)
    if (batches[i].kind == "sweep")
      rows[i] = shard::merged_rows(batches[i], dir, sweep::ftle_curve_problem);
    else if (batches[i].kind == "section")
      sections[i] = section::read_section_shards(batches[i], dir, out_dir);
  require_separate_merge_files(batches, dir, out_dir, o, sections);
  for (const auto& s : sections)
    if (s) check_merged_section(*s, o.print);  // with the section files' own sizes
  // Every atlas is checked against its rows before anything is written.
  for (std::size_t i = 0; i < batches.size(); ++i)
    if (batches[i].kind == "sweep")
      for (const auto& q :
           atlas_requests(saved_sweep(batches[i].shards.begin()->second, batches[i].hash), o))
        sweep::check_atlas_request(rows[i], q);
  fs::create_directories(out_dir);
  int unconverged = 0;
  for (std::size_t i = 0; i < batches.size(); ++i) {
    if (batches[i].kind == "sweep")
      unconverged += !merge_sweep(batches[i], rows[i], out_dir, o);
    else if (sections[i])
      write_merged_section(*sections[i], o.gl,
                           o.h5 ? h5_beside(sections[i]->job.csv).string() : std::string(),
                           o.print);
    else
      merge_render(batches[i], dir, out_dir);
  }
  if (unconverged && !o.allow_unconverged) {
    std::fprintf(stderr,
                 "epviz: %d sweep(s) not converged: their metrics change at a 100x tighter "
                 "tolerance (see the self-check lines); tighten tol, or pass "
                 "--allow-unconverged\n",
                 unconverged);
    return 3;
  }
  return 0;
}

}  // namespace

std::function<int()> add_merge_command(cli::Command app) {
  auto o = std::make_shared<MergeOptions>();
  cli::Command cmd = app.add_subcommand(
      "merge",
      "Check the shards in DIR (by their manifests) and join them: sweep rows, video "
      "segments, atlas figures");
  cmd.add_option("dir", o->dir, "directory the shards wrote to").required();
  cmd.add_option("--out", o->out, "directory for the merged files (default DIR)");
  cmd.add_option("--atlas", o->atlases,
                 "METRIC:XAXIS:YAXIS: draw this heat map of a sweep (repeatable; default: the "
                 "sweep file's \"atlas\" list)")
      .take_all();
  add_gl_option(cmd, o->gl, "for atlases");
  cmd.add_option("--format", o->format,
                 "the atlases' files: png (GL), svg or pdf (cairo, vector; no GL needed) "
                 "(default png)");
  add_print_options(cmd, o->print);  // the atlases', and over a section file's keys
  cmd.add_flag("--h5", o->h5,
               "also write each merged sweep's rows and section's crossings as HDF5 beside "
               "them (NAME.jsonl, NAME.csv -> NAME.h5), as sweep and section --h5 do");
  cmd.add_option("--resubmit", o->resubmit,
                 "FILE: when shards are missing or incomplete, write a script that submits only "
                 "those again as Slurm job arrays, then this merge (docs/cluster.md)");
  cmd.add_flag("--allow-unconverged", o->allow_unconverged,
               "exit 0 even when a sweep's self-check finds its FTLE or reference error "
               "not converged (the figures still say so)");
  return [o] { return run_merge(*o); };
}

}  // namespace epviz::app
