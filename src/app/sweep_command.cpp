#include "app/sweep_command.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <thread>

#include "app/cli_values.hpp"
#include "app/h5_output.hpp"
#include "h5/columns_file.hpp"
#include "h5/json_rows.hpp"
#include "io/bad_input.hpp"
#include "io/json_reader.hpp"
#include "io/output_paths.hpp"
#include "io/progress.hpp"
#include "job/shipped_jobs.hpp"
#include "shard/rows_shard.hpp"
#include "shard/shard_lock.hpp"
#include "shard/shard_spec.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_spec.hpp"

namespace epviz::app {
namespace {

namespace fs = std::filesystem;

struct SweepOptions {
  std::string file, out, jobs, shard, shard_count, h5;
  bool quiet = false;
};

// "stability_atlas.sweep.json" -> "stability_atlas".
std::string sweep_stem(const fs::path& file) {
  std::string s = file.filename().string();
  for (const char* ext : {".sweep.json", ".json"})
    if (s.size() > std::string(ext).size() && s.ends_with(ext))
      return s.substr(0, s.size() - std::string(ext).size());
  return s;
}

// The rows of the file `rows` (every point of the sweep, resumed ones too),
// in the order of their points, as HDF5 columns (h5/json_rows.hpp), with the
// sweep file and a report as attributes.
void write_sweep_h5(const SweepOptions& o, const fs::path& rows_file, long total, double seconds) {
  std::vector<nlohmann::json> rows;
  std::ifstream in(rows_file);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) rows.push_back(io::parse_json_text(line, rows_file.string()));
  std::stable_sort(rows.begin(), rows.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    return a.value("index", 0L) < b.value("index", 0L);
  });
  long failed = 0;
  for (const auto& r : rows) failed += r.contains("failure_kind") && !r["failure_kind"].is_null();
  h5::ColumnsFile file(o.h5, {});
  h5::write_json_rows(file, rows);
  write_provenance(file);
  file.set_attribute("job", io::read_json_file(o.file).dump());
  const nlohmann::json report{{"points", total},
                              {"rows", rows.size()},
                              {"failed_points", failed},
                              {"rows_file", rows_file.string()},
                              {"seconds", seconds}};
  file.set_attribute("report", report.dump());
  file.set_attribute("failed", 0L);
  file.commit();
}

int run_sweep(const SweepOptions& o) {
  const sweep::SweepSpec spec = sweep::read_sweep_file(o.file);
  const int threads = o.jobs.empty() ? int(std::max(1u, std::thread::hardware_concurrency()))
                                     : int(parse_integer("-j", o.jobs, 1, 4096));
  const auto shard = shard::shard_from_options(o.shard, o.shard_count);

  const long total = spec.point_count();
  const fs::path out_given =
      o.out.empty() ? fs::path(sweep_stem(o.file) + ".jsonl") : fs::path(o.out);
  if (o.out == "-") throw io::BadInput("--out: rows are appended to a file, not standard output");
  io::check_output_file("--out", out_given.string());
  h5::check_h5_output("--h5", o.h5);
  io::require_separate_files({{"the sweep file", o.file}},
                             {{"--out", out_given.string()}, {"--h5", o.h5}});
  if (shard && !o.h5.empty())
    throw io::BadInput(
        "--h5: a shard writes only its rows; `epviz merge --h5` writes the merged sweep's");
  std::optional<shard::RowsShard> rows_shard;
  if (shard) {
    shard::RowsBatch batch{
        {fs::absolute(o.file).lexically_normal().string(), spec.hash, {}}, out_given, total};
    auto& command = batch.origin.command;
    command = {"epviz", "sweep", batch.origin.source, "--out",
               fs::absolute(out_given).lexically_normal().string()};
    if (!o.jobs.empty()) command.insert(command.end(), {"-j", o.jobs});
    rows_shard = shard::plan_rows_shard(batch, *shard);
  }
  const fs::path out = rows_shard ? rows_shard->rows : out_given;
  const shard::ItemRange range = rows_shard ? rows_shard->points : shard::ItemRange{0, total};

  // Held to the end, so that a second copy of this run refuses (shard/shard_lock.hpp).
  const shard::ShardLock lock(rows_shard ? rows_shard->lock_path
                                         : fs::path(out.string() + ".lock"));
  const sweep::ExistingRows existing = sweep::resume_rows(out, spec.hash, total, range);
  const auto pending = sweep::pending_points(spec, range, existing);

  if (rows_shard) shard::start_rows_shard(*rows_shard);  // "completed": false until the end

  io::ProgressOptions po;
  po.mode = o.quiet ? io::ProgressMode::off : io::ProgressMode::automatic;
  po.label = "sweep " + sweep_stem(o.file);
  po.unit = "points";
  po.already_done = int(range.size() - long(pending.size()));
  io::ProgressLine progress(int(range.size()), po);
  progress.update(po.already_done);
  const auto start = std::chrono::steady_clock::now();
  sweep::SweepTotals totals;
  {
    sweep::RowAppender rows(out);
    totals = sweep::run_points(spec, pending, threads, rows, [&] { progress.advance(); });
    rows.flush();
  }
  progress.finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (rows_shard) shard::finish_rows_shard(*rows_shard);
  if (!o.h5.empty()) write_sweep_h5(o, out, total, seconds);
  std::printf(
      "%s: %ld points%s, %zu already in %s%s, ran %ld in %.2f s (%.1f points/s, %d threads), %ld "
      "failed\n",
      o.file.c_str(), total,
      shard
          ? (" (shard " + std::to_string(shard->index) + "/" + std::to_string(shard->count) +
             ": points " + std::to_string(range.first) + ".." + std::to_string(range.end - 1) + ")")
                .c_str()
          : "",
      existing.indices.size(), out.string().c_str(), sweep::repairs_note(existing).c_str(),
      totals.points, seconds, seconds > 0 ? double(totals.points) / seconds : 0.0, threads,
      totals.failures);
  return 0;
}

}  // namespace

std::function<int()> add_sweep_command(cli::Command app) {
  auto o = std::make_shared<SweepOptions>();
  cli::Command cmd = app.add_subcommand(
      "sweep", "Run every point of a parameter sweep (SWEEP.json) and write one JSON row each");
  cmd.add_option("sweep", o->file,
                 "sweep file (JSON: simulation, axes; docs/cluster.md), or the name of a "
                 "shipped sweep (epviz render --list-jobs lists them)")
      .required();
  cmd.add_option("--out", o->out,
                 "rows file (JSON Lines, appended; default <sweep>.jsonl); rows already in it "
                 "are kept and their points skipped");
  cmd.add_option("-j,--jobs", o->jobs, "threads (default: all cores)");
  cmd.add_option("--shard", o->shard,
                 "I/N: run only shard I (from 0) of N, a contiguous range of points; default "
                 "from SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX or AWS_BATCH_JOB_ARRAY_INDEX");
  cmd.add_option("--shard-count", o->shard_count,
                 "N: the number of shards when the environment gives only the index");
  cmd.add_flag("--quiet", o->quiet, "no progress line");
  cmd.add_option("--h5", o->h5,
                 "also write the rows, in the order of their points, to this HDF5 file: a "
                 "dataset per value (\"max_relative_drift.energy\", \"initial.omega[0]\"), "
                 "the sweep file and a report as attributes (JSON)");
  return [o] {
    o->file = job::job_file_named(o->file, job::shipped_jobs_dir(), job::ShippedKind::sweep);
    return run_sweep(*o);
  };
}

}  // namespace epviz::app
