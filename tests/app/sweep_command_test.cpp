// `epviz sweep` and `epviz merge` as a user runs them: rows equal the reports
// of single `epviz simulate` runs, interrupted sweeps resume to the same rows,
// shards merge to the unsharded rows, and bad input stops before any work.
#include <gtest/gtest.h>

#include <signal.h>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "io/subprocess.hpp"
#include "support/cli.hpp"
#include "support/eventually.hpp"
#include "support/peak_rss.hpp"
#include "sweep/rows_by_index.hpp"

namespace epviz::test {
namespace {

using Json = nlohmann::json;
using epviz::testing::rows_by_index;
namespace fs = std::filesystem;

const char* kSmallSweep = R"({
  "simulation": {"case": "generic", "t_end": 20, "samples": 20},
  "axes": [{"field": "method", "values": ["rk4", "gauss4"]},
           {"field": "step", "values": [0.05, 1.0]},
           {"field": "energy", "values": [1.5, 3.0]}]})";

TEST(SweepCommand, RowsEqualTheReportsOfSingleSimulateRuns) {
  TempDir d;
  std::ofstream(d / "s.sweep.json") << kSmallSweep;
  auto r = run_epviz(
      "sweep " + (d / "s.sweep.json").string() + " --out " + (d / "rows.jsonl").string() + " -j 2",
      d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = rows_by_index(d / "rows.jsonl");
  ASSERT_EQ(rows.size(), 8u);
  int failed = 0;
  for (const auto& [i, row] : rows) {
    const auto& w = row["initial"]["omega"];
    char omega[128];
    std::snprintf(omega, sizeof omega, "%.17g,%.17g,%.17g", w[0].get<double>(), w[1].get<double>(),
                  w[2].get<double>());
    const auto report = d / "report.json", csv = d / "samples.csv";
    auto s = run_epviz("simulate --case generic --t-end 20 --samples 20 --method " +
                           row["axes"]["method"].get<std::string>() + " --step " +
                           row["axes"]["step"].dump() + " --omega " + omega + " --report-json " +
                           report.string() + " --csv " + csv.string(),
                       d);
    ASSERT_TRUE(s.exit_code == 0 || s.exit_code == 3) << s.err;
    const auto rep = Json::parse(slurp(report));
    for (const char* key : {"steps", "rhs_evals", "rejected_steps", "samples_written",
                            "max_relative_drift", "failure_kind", "effective_step"})
      EXPECT_EQ(row[key], rep[key]) << "point " << i << " key " << key;
    if (rep["failure"].is_null()) {
      EXPECT_TRUE(row["failure"].is_null());
    } else {
      ++failed;
      EXPECT_EQ(row["failure"]["t"], rep["failure"]["t"]) << "point " << i;
    }
    // The energy the axis asked for is the run's energy (simulate's first CSV row).
    std::ifstream in(csv);
    std::string header, first, line, last;
    std::getline(in, header);
    std::getline(in, first);
    last = first;
    while (std::getline(in, line)) last = line;
    auto field = [](const std::string& csv_line, int k) {
      std::stringstream ss(csv_line);
      std::string cell;
      for (int j = 0; j <= k; ++j) std::getline(ss, cell, ',');
      return std::stod(cell);
    };
    EXPECT_NEAR(field(first, 9), row["axes"]["energy"].get<double>(), 1e-12);
    // The final state is simulate's last sample.
    EXPECT_EQ(field(last, 0), row["final"]["t"].get<double>());
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(field(last, 1 + k), row["final"]["omega"][k].get<double>());
      EXPECT_EQ(field(last, 4 + k), row["final"]["gamma"][k].get<double>());
    }
  }
  // The grid crosses the stability limit: some points fail (gauss4 at step 1), others do not.
  EXPECT_GT(failed, 0);
  EXPECT_LT(failed, 8);
}

const char* kSlowSweep = R"({
  "simulation": {"case": "kovalevskaya", "t_end": 1000, "samples": 10, "tol": 1e-12},
  "axes": [{"field": "omega[0]", "from": 0.5, "to": 1.5, "count": 200}]})";

TEST(SweepCommand, AKilledSweepResumesToTheSameRows) {
  TempDir d;
  std::ofstream(d / "s.sweep.json") << kSlowSweep;
  auto whole = run_epviz(
      "sweep " + (d / "s.sweep.json").string() + " --out " + (d / "whole.jsonl").string(), d);
  ASSERT_EQ(whole.exit_code, 0) << whole.err;

  const auto part = d / "part.jsonl";
  {
    io::Subprocess::Options o;
    o.in = o.out = o.err = io::Subprocess::Stream::null;
    io::Subprocess child(
        {EPVIZ_BINARY, "sweep", (d / "s.sweep.json").string(), "--out", part.string(), "-j", "1"},
        o);
    eventually([&] { return line_count(slurp(part)) >= 5; }, std::chrono::seconds(60));
    child.kill(SIGKILL);
    EXPECT_TRUE(child.wait().signalled());
  }
  const auto kept = long(line_count(slurp(part)));
  ASSERT_GE(kept, 5);
  ASSERT_LT(kept, 200) << "the sweep finished before it could be killed";
  // A row cut short, as a kill during a write would leave it.
  std::ofstream(part, std::ios::app) << R"({"index":199,"sweep":"0)";

  auto resumed = run_epviz("sweep " + (d / "s.sweep.json").string() + " --out " + part.string(), d);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find(std::to_string(kept) + " already in"), std::string::npos)
      << resumed.out;
  EXPECT_NE(resumed.out.find("torn last line dropped"), std::string::npos) << resumed.out;
  EXPECT_EQ(rows_by_index(part), rows_by_index(d / "whole.jsonl"));
  EXPECT_EQ(line_count(slurp(part)), 200u);
}

TEST(SweepCommand, ShardsMergeToTheUnshardedRows) {
  TempDir d;
  std::ofstream(d / "s.sweep.json") << kSmallSweep;
  const std::string sweep = (d / "s.sweep.json").string();
  ASSERT_EQ(run_epviz("sweep " + sweep + " --out " + (d / "whole.jsonl").string(), d).exit_code, 0);
  fs::create_directories(d / "shards");
  const std::string out = (d / "shards" / "rows.jsonl").string();
  ASSERT_EQ(run_epviz("sweep " + sweep + " --out " + out + " --shard 0/3", d).exit_code, 0);
  // Shard 1 from a Slurm array numbered from 1 (--array=1-3): task 2 is shard 1.
  const std::string env =
      "env SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=3 ";
  const int rc = std::system(
      (env + EPVIZ_BINARY + " sweep " + sweep + " --out " + out + " --quiet >/dev/null 2>&1")
          .c_str());
  ASSERT_EQ(rc, 0);
  ASSERT_TRUE(fs::exists(d / "shards" / "rows.shard-1-of-3.jsonl"));
  ASSERT_EQ(run_epviz("sweep " + sweep + " --out " + out + " --shard 2/3", d).exit_code, 0);
  auto m = run_epviz("merge " + (d / "shards").string(), d);
  ASSERT_EQ(m.exit_code, 0) << m.err;
  EXPECT_EQ(rows_by_index(d / "shards" / "rows.jsonl"), rows_by_index(d / "whole.jsonl"));
  // Merged rows are in point order.
  std::ifstream in(d / "shards" / "rows.jsonl");
  std::string line;
  long expect = 0;
  while (std::getline(in, line)) EXPECT_EQ(Json::parse(line)["index"], expect++);
}

// A value no point may take stops every shard before any work; a point
// whose values meet badly (an energy its state cannot reach) stops the shard
// that holds it, whose own points are resolved in full.
TEST(SweepCommand, ABadValueStopsEveryShardABadPointItsOwn) {
  TempDir d;
  const auto sweep = d.write("s.sweep.json", R"({
    "simulation": {"case": "generic", "t_end": 0.1, "samples": 1, "method": "rk4", "step": 0.1},
    "axes": [{"field": "energy", "values": [3.0, -100.0]}]})");
  const std::string out = (d / "rows.jsonl").string();
  EXPECT_EQ(
      run_epviz("sweep " + sweep.string() + " --out " + out + " --shard 0/2 --quiet", d).exit_code,
      0);
  expect_bad_input(
      run_epviz("sweep " + sweep.string() + " --out " + out + " --shard 1/2 --quiet", d), "energy");

  const auto bad_value = d.write("v.sweep.json", R"({
    "simulation": {"case": "generic", "t_end": 0.1, "samples": 1, "method": "dop853"},
    "axes": [{"field": "tol", "values": [1e-8, 0.5]}]})");
  for (const char* s : {"0/2", "1/2"})
    expect_bad_input(run_epviz("sweep " + bad_value.string() + " --out " +
                                   (d / "v.jsonl").string() + " --shard " + s + " --quiet",
                               d),
                     "tol");
}

// Stands in for Slurm's sbatch in PATH: runs a job array's --wrap command
// once per index of its --array list (with SLURM_ARRAY_TASK_ID set), and any
// other job's at once; logs its options and prints a job id, as --parsable does.
const char* kFakeSbatch = R"(#!/bin/bash
array= wrap= options=()
while [ $# -gt 0 ]; do
  case "$1" in
    --array=*) array=${1#--array=} ;;
    --wrap) wrap=$2; shift ;;
  esac
  options+=("$1"); shift
done
echo "${options[*]}" >> "$SBATCH_LOG"
if [ -n "$array" ]; then
  IFS=, read -ra parts <<< "$array"
  for p in "${parts[@]}"; do
    for ((i = ${p%-*}; i <= ${p#*-}; i++)); do SLURM_ARRAY_TASK_ID=$i bash -c "$wrap" >/dev/null 2>&1; done
  done
else
  bash -c "$wrap" >"$SBATCH_LOG.merge" 2>&1
fi
echo 4242
)";

TEST(MergeCommand, ResubmitWritesAScriptThatRedoesOnlyTheFailedShardsThenTheMerge) {
  TempDir d;
  std::ofstream(d / "s.sweep.json") << kSmallSweep;
  const std::string sweep = (d / "s.sweep.json").string();
  const std::string out = (d / "rows.jsonl").string();
  ASSERT_EQ(run_epviz("sweep " + sweep + " --out " + (d / "whole.jsonl").string(), d).exit_code, 0);
  fs::create_directories(d / "shards");
  const std::string shards = (d / "shards" / "rows.jsonl").string();
  // Of four shards, 0 and 3 finished; 1 never ran and 2 was killed.
  for (const char* s : {"0/4", "3/4", "2/4"})
    ASSERT_EQ(run_epviz("sweep " + sweep + " --out " + shards + " --shard " + s, d).exit_code, 0);
  fs::remove(d / "shards" / "rows.shard-2-of-4.jsonl");
  const auto script = d / "resubmit.sh";
  auto m = run_epviz("merge " + (d / "shards").string() + " --resubmit " + script.string(), d);
  ASSERT_EQ(m.exit_code, 4) << m.err;
  EXPECT_NE(m.err.find("bash " + script.string()), std::string::npos) << m.err;
  const std::string text = slurp(script);
  EXPECT_NE(text.find("--array=1-2 "), std::string::npos) << text;

  // Run it with the stand-in sbatch: the two shards are redone and the merge,
  // after them, joins all four to the rows of the unsharded sweep.
  fs::create_directories(d / "bin");
  std::ofstream(d / "bin" / "sbatch") << kFakeSbatch;
  fs::permissions(d / "bin" / "sbatch", fs::perms::owner_all);
  fs::create_symlink(EPVIZ_BINARY, d / "bin" / "epviz");
  const auto log = d / "sbatch.log";
  const std::string run = "cd " + d.path().string() + " && PATH=" + (d / "bin").string() +
                          ":$PATH SBATCH_LOG=" + log.string() + " bash " + script.string() +
                          " >/dev/null 2>&1";
  ASSERT_EQ(std::system(run.c_str()), 0) << slurp(log) << slurp(d / "sbatch.log.merge");
  const std::string calls = slurp(log);
  EXPECT_NE(calls.find("--dependency=afterany:4242"), std::string::npos) << calls;
  EXPECT_EQ(line_count(calls), 2u) << calls;
  EXPECT_EQ(rows_by_index(d / "shards" / "rows.jsonl"), rows_by_index(d / "whole.jsonl"))
      << slurp(d / "sbatch.log.merge");
}

// A sweep of `side` x `side` x 2 points, each a one-step run.
std::string square_sweep(int side) {
  return R"({"simulation": {"case": "generic", "t_end": 0.1, "samples": 1, "method": "rk4",
      "step": 0.1, "gamma": [0, 0, 1], "normalize_gamma": true, "omega": [1.0, 0.8, 0.6]},
    "axes": [{"field": "gamma[1]", "from": -0.95, "to": 0.95, "count": )" +
         std::to_string(side) + R"(},
             {"field": "gamma[0]", "from": -0.95, "to": 0.95, "count": )" +
         std::to_string(side) + R"(},
             {"field": "energy", "values": [3.0, 4.0]}]})";
}

TEST(SweepCommand, AShardsMemoryIsInProportionToItsOwnRange) {
  TempDir d;
  // 200,000 and 2,000 points, cut so that shard 0 runs 200 points of each.
  std::ofstream(d / "large.sweep.json") << square_sweep(316);
  std::ofstream(d / "small.sweep.json") << square_sweep(32);
  const long small =
      peak_rss_kb({"sweep", "small.sweep.json", "--shard", "0/10", "--quiet"}, d.path().string());
  const long large =
      peak_rss_kb({"sweep", "large.sweep.json", "--shard", "0/1000", "--quiet"}, d.path().string());
  ASSERT_GT(small, 0);
  ASSERT_GT(large, 0);
  // Every point prepared and kept would take about 70 MB more for the large sweep.
  EXPECT_LT(large - small, 16 * 1024)
      << "peak RSS " << small << " kB for a shard of 2,000 points, " << large << " kB of 200,000";
}

TEST(MergeCommand, NamesAMissingOrDamagedShardAndTheCommandThatRedoesIt) {
  TempDir d;
  std::ofstream(d / "s.sweep.json") << kSmallSweep;
  const std::string sweep = (d / "s.sweep.json").string();
  const std::string out = (d / "rows.jsonl").string();
  ASSERT_EQ(run_epviz("sweep " + sweep + " --out " + out + " --shard 0/3", d).exit_code, 0);
  ASSERT_EQ(run_epviz("sweep " + sweep + " --out " + out + " --shard 2/3", d).exit_code, 0);
  auto m = run_epviz("merge " + d.path().string(), d);
  EXPECT_EQ(m.exit_code, 4);
  EXPECT_NE(m.err.find("shard 1/3: missing"), std::string::npos) << m.err;
  const auto at = m.err.find("run: epviz sweep ");
  ASSERT_NE(at, std::string::npos) << m.err;
  const std::string command = m.err.substr(at + 5, m.err.find('\n', at) - at - 5);
  EXPECT_NE(command.find("--shard 1/3"), std::string::npos) << command;
  EXPECT_FALSE(fs::exists(out)) << "merged despite a missing shard";
  // The command as printed redoes the shard, and the merge then succeeds.
  ASSERT_EQ(run_epviz(command.substr(std::string("epviz ").size()), d).exit_code, 0);
  EXPECT_EQ(run_epviz("merge " + d.path().string(), d).exit_code, 0);
  EXPECT_EQ(line_count(slurp(out)), 8u);

  // A shard file changed after its manifest was written is named too.
  std::ofstream(d / "rows.shard-2-of-3.jsonl", std::ios::app) << "{}\n";
  m = run_epviz("merge " + d.path().string(), d);
  EXPECT_EQ(m.exit_code, 4);
  EXPECT_NE(m.err.find("shard 2/3: "), std::string::npos) << m.err;
  EXPECT_NE(m.err.find("bytes, the manifest says"), std::string::npos) << m.err;
}

TEST(SweepCommand, BadSweepFilesExitTwoWithOneLineNamingTheKey) {
  TempDir d;
  struct Case {
    const char* text;
    const char* says;
  };
  for (
      const auto& c : std::vector<Case>{
          {R"({"axes": [{"field": "stepsize", "values": [0.1]}]})", "key 'axes[0].field'"},
          {R"({"axes": [{"field": "method", "values": ["rk4", "rk5"]}]})",
           "key 'axes[0]' (method = \"rk5\"): unknown method"},
          {R"({"simulation": {"case": "generic"}, "axes": [{"field": "energy", "values": [0.1]}]})",
           "key 'axes[0]' (energy = 0.1): below the potential energy"},
          {R"({"axes": [{"field": "inertia[0]", "values": [5.0]}]})",
           "key 'axes[0]' (inertia[0] = 5.0)"},
          {R"({"axes": [{"field": "step", "values": [0.1]}], "simulation": {"method": "rk4", "tol": 1e-6}})",
           "key 'simulation.tol'"},
          {R"({"axes": "step"})", "key 'axes'"},
          {R"({"axes": [{"field": "t_end", "values": [2]}], "ftle": {"window": 1e-300}})",
           "key 'ftle.window': expected a window from t_end / 1e9"},
          {R"({"simulation": {"case": "generic"}, "axes": [{"field": "energy", "values": [1e308]}]})",
           "): gives an omega past omega's range (expected three numbers from -1e6 to 1e6)"},
      }) {
    std::ofstream(d / "bad.sweep.json") << c.text;
    auto r = run_epviz(
        "sweep " + (d / "bad.sweep.json").string() + " --out " + (d / "rows.jsonl").string(), d);
    SCOPED_TRACE(c.text);
    expect_bad_input(r, c.says);
    EXPECT_NE(r.err.find("bad.sweep.json"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(d / "rows.jsonl")) << "wrote rows despite " << c.text;
  }
  std::ofstream(d / "good.sweep.json") << kSmallSweep;
  auto r = run_epviz("sweep " + (d / "good.sweep.json").string() + " --shard 3/3", d);
  expect_bad_input(r, "--shard: expected I/N");
}

}  // namespace
}  // namespace epviz::test
