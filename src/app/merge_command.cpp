#include "app/merge_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "app/output_paths.hpp"
#include "app/usage_error.hpp"
#include "io/atomic_file.hpp"
#include "io/json_reader.hpp"
#include "io/png_writer.hpp"
#include "io/subprocess.hpp"
#include "io/temp_registry.hpp"
#include "shard/manifest.hpp"
#include "sweep/atlas.hpp"
#include "sweep/sweep_spec.hpp"
#ifdef EPVIZ_HAVE_RENDER
#include "paint/figure_painter.hpp"
#include "render/gl_context.hpp"
#endif

namespace epviz::app {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

struct MergeOptions {
  std::string dir, out, gl;
  std::vector<std::string> atlases;
};

// The shards of one batch (same kind and hash), by shard index.
struct Batch {
  std::string kind, hash;
  long count = 0;
  std::map<long, shard::Manifest> shards;
  std::vector<std::string> problems;  // one line each, with the command that redoes the shard
};

std::string batch_name(const Batch& b) {
  const auto& m = b.shards.begin()->second;
  return m.kind + " " + m.source + " (" + std::to_string(b.count) + " shards)";
}

std::vector<Batch> read_batches(const fs::path& dir) {
  std::map<std::string, Batch> by_key;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (e.is_regular_file() && n.ends_with(shard::manifest_suffix)) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    shard::Manifest m;
    try {
      m = shard::read_manifest(f);
    } catch (const io::JobError& e) {
      throw UsageError(e.what());
    }
    auto& b = by_key[m.kind + "/" + m.hash];
    b.kind = m.kind;
    b.hash = m.hash;
    if (b.count && b.count != m.shard.count)
      throw UsageError(f.string() + ": shard of " + std::to_string(m.shard.count) +
                       " while other shards of the same batch say " + std::to_string(b.count) +
                       "; remove the manifests of the old split");
    b.count = m.shard.count;
    b.shards[m.shard.index] = std::move(m);
  }
  std::vector<Batch> out;
  for (auto& [key, b] : by_key) out.push_back(std::move(b));
  return out;
}

void check_batch(Batch& b, const fs::path& dir) {
  const auto& any = b.shards.begin()->second;
  for (long i = 0; i < b.count; ++i) {
    const std::string tag = "shard " + std::to_string(i) + "/" + std::to_string(b.count);
    auto it = b.shards.find(i);
    if (it == b.shards.end()) {
      b.problems.push_back(tag + ": missing (no manifest in " + dir.string() +
                           "); run: " + shard::rerun_command(any, i));
      continue;
    }
    if (!it->second.completed) {
      b.problems.push_back(tag + ": not completed (killed, failed or still running); run: " +
                           shard::rerun_command(any, i));
      continue;
    }
    for (const auto& p : shard::file_problems(it->second, dir))
      b.problems.push_back(tag + ": " + p + "; run: " + shard::rerun_command(any, i));
  }
}

std::vector<Json> read_rows(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<Json> rows;
  std::string line;
  long n = 0;
  while (std::getline(in, line)) {
    ++n;
    try {
      rows.push_back(Json::parse(line));
    } catch (const Json::exception&) {
      throw UsageError(file.string() + ": line " + std::to_string(n) + " is not a JSON row");
    }
  }
  return rows;
}

void draw_atlases(const std::vector<Json>& rows, const std::vector<sweep::AtlasRequest>& requests,
                  const fs::path& out_dir, const std::string& gl) {
  if (requests.empty()) return;
  std::vector<sweep::AtlasFigure> figures;
  for (const auto& q : requests) {
    try {
      for (auto& f : sweep::atlas_figures(rows, q)) figures.push_back(std::move(f));
    } catch (const sweep::AtlasError& e) {
      throw UsageError(e.what());
    }
  }
#ifdef EPVIZ_HAVE_RENDER
  std::unique_ptr<render::GlContext> context;
  try {
    context =
        render::make_gl_context(gl.empty() ? render::gl_backend_from_environment() : gl, 16, 16);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string(gl.empty() ? "EPVIZ_GL" : "--gl") + ": " + e.what());
  }
  for (const auto& f : figures) {
    paint::ChartOptions options;
    options.width = 1280;
    options.height = 900;
    // As a figure: no taller than the grid needs (a few rows leave no blank band).
    const auto image = paint::paint_figure(*context, {f.file_name, f.heat_map}, options);
    const fs::path path = out_dir / f.file_name;
    io::write_png_rgba(path, image.width, image.height, image.pixels);
    std::printf("  atlas %s\n", path.string().c_str());
  }
#else
  (void)out_dir;
  (void)gl;
  throw UsageError("--atlas: this epviz was built without the renderer (EPVIZ_BUILD_RENDER=OFF)");
#endif
}

void merge_sweep(const Batch& b, const fs::path& dir, const fs::path& out_dir,
                 const MergeOptions& o) {
  std::vector<Json> rows;
  std::set<long> seen;
  for (const auto& [i, m] : b.shards) {
    for (const auto& f : m.files) {
      for (auto& r : read_rows(dir / f.path)) {
        const long index = r.value("index", -1L);
        if (index < m.items.first || index >= m.items.end || r.value("sweep", "") != b.hash)
          throw UsageError((dir / f.path).string() + ": a row (index " + std::to_string(index) +
                           ") that is not one of shard " + std::to_string(i) + "'s points");
        if (!seen.insert(index).second)
          throw UsageError((dir / f.path).string() + ": point " + std::to_string(index) + " twice");
        rows.push_back(std::move(r));
      }
    }
    if (long(seen.size()) < m.items.end) {
      for (long k = m.items.first; k < m.items.end; ++k)
        if (!seen.count(k))
          throw UsageError("shard " + std::to_string(i) + "/" + std::to_string(b.count) +
                           ": point " + std::to_string(k) +
                           " has no row; run: " + shard::rerun_command(m, i));
    }
  }
  std::sort(rows.begin(), rows.end(), [](const Json& a, const Json& c) {
    return a["index"].get<long>() < c["index"].get<long>();
  });
  std::string text;
  for (const auto& r : rows) text += r.dump() + "\n";
  const auto& any = b.shards.begin()->second;
  const fs::path out = out_dir / any.output;
  io::write_file_atomically(out, text);
  std::printf("%s: %zu rows -> %s\n", batch_name(b).c_str(), rows.size(), out.string().c_str());

  std::vector<sweep::AtlasRequest> requests;
  for (const auto& a : o.atlases) {
    try {
      requests.push_back(sweep::parse_atlas_option(a));
    } catch (const sweep::AtlasError& e) {
      throw UsageError(e.what());
    }
  }
  // The sweep file's own atlases, when it is still there and unchanged.
  if (o.atlases.empty()) {
    try {
      const auto spec = sweep::read_sweep_file(any.source);
      if (spec.hash == b.hash) requests = spec.atlases;
    } catch (const std::exception&) {
      // Gone or edited since: only --atlas figures.
    }
  }
  draw_atlases(rows, requests, out_dir, o.gl);
}

void merge_render(const Batch& b, const fs::path& dir, const fs::path& out_dir) {
  const auto& any = b.shards.begin()->second;
  if (any.output.empty()) {
    long frames = 0;
    for (const auto& [i, m] : b.shards) frames += long(m.files.size());
    std::printf("%s: %ld PNG frames complete in %s\n", batch_name(b).c_str(), frames,
                dir.string().c_str());
    return;
  }
  // ffmpeg's concat demuxer joins the segments without re-encoding (each
  // segment starts with a key frame, so the stream copy is exact).
  const fs::path out = out_dir / any.output;
  const fs::path list = out_dir / (any.output + ".segments.txt");
  std::string text;
  for (const auto& [i, m] : b.shards)
    for (const auto& f : m.files) {
      std::string p = fs::absolute(dir / f.path).string(), q;
      for (char c : p) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
      text += "file '" + q + "'\n";
    }
  io::write_file_atomically(list, text);
  const fs::path tmp = out_dir / (".merging-" + any.output);
  const auto r =
      io::run_process({"ffmpeg", "-hide_banner", "-loglevel", "error", "-nostdin", "-y", "-f",
                       "concat", "-safe", "0", "-i", list.string(), "-c", "copy", tmp.string()});
  fs::remove(list);
  if (!r.status.success()) {
    fs::remove(tmp);
    throw std::runtime_error("ffmpeg could not join the segments of " + batch_name(b) + ": " +
                             r.status.describe() + ": " + r.err.substr(0, 300));
  }
  fs::rename(tmp, out);
  std::printf("%s: %zu segments joined -> %s\n", batch_name(b).c_str(), b.shards.size(),
              out.string().c_str());
}

int run_merge(const MergeOptions& o) {
  const fs::path dir = o.dir;
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw UsageError("DIR: '" + o.dir +
                     "' is not a directory (give the directory the shards wrote to)");
  const fs::path out_dir = o.out.empty() ? dir : fs::path(o.out);
  check_output_dir("--out", out_dir);
  auto batches = read_batches(dir);
  if (batches.empty())
    throw UsageError("DIR: no shard manifests (*" + std::string(shard::manifest_suffix) + ") in " +
                     o.dir + "; run epviz sweep or render with --shard I/N there first");
  int incomplete = 0;
  for (auto& b : batches) {
    check_batch(b, dir);
    for (const auto& p : b.problems)
      std::fprintf(stderr, "epviz: %s: %s\n", batch_name(b).c_str(), p.c_str());
    incomplete += !b.problems.empty();
  }
  if (incomplete) {
    std::fprintf(stderr, "epviz: error: %d of %zu batches in %s are incomplete; nothing merged\n",
                 incomplete, batches.size(), o.dir.c_str());
    return 4;
  }
  fs::create_directories(out_dir);
  for (const auto& b : batches) {
    if (b.kind == "sweep")
      merge_sweep(b, dir, out_dir, o);
    else
      merge_render(b, dir, out_dir);
  }
  return 0;
}

}  // namespace

std::function<int()> add_merge_command(CLI::App& app) {
  auto o = std::make_shared<MergeOptions>();
  auto* cmd = app.add_subcommand(
      "merge",
      "Check the shards in DIR (by their manifests) and join them: sweep rows, video "
      "segments, atlas figures");
  cmd->add_option("dir", o->dir, "directory the shards wrote to")->required();
  cmd->add_option("--out", o->out, "directory for the merged files (default DIR)");
  cmd->add_option("--atlas", o->atlases,
                  "METRIC:XAXIS:YAXIS: draw this heat map of a sweep (repeatable; default: the "
                  "sweep file's \"atlas\" list)")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--gl", o->gl, "offscreen GL backend for atlases: auto, egl or osmesa");
  return [o] { return run_merge(*o); };
}

}  // namespace epviz::app
