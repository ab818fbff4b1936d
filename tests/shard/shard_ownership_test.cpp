// A shard is owned while it runs, as a user of `epviz sweep --shard` and
// `epviz merge` meets it: a second copy refuses, naming the first, and writes
// nothing; merge tells the running shard from the one to redo; a shard killed
// with SIGKILL leaves its lock to the next run, which resumes it to the rows
// of an unsharded run.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/subprocess.hpp"
#include "support/cli.hpp"
#include "support/eventually.hpp"
#include "sweep/rows_by_index.hpp"

namespace epviz::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using epviz::testing::rows_by_index;

// Points slow enough (a long run at a tight tolerance) that a shard is still
// running when the test looks; 2 shards of 12 points. The spinor formulation
// keeps them off the SIMD batch path, whose lanes run a shard's points side
// by side and end them together: here rows must come one after another, so
// that a kill lands between two of them. About 0.3 s a point here, so that
// the kill has a second and more after the second row even on a busy machine
// (at 0.08 s a point, one full run of the suite saw the shard end first).
const char* kSlowSweep = R"({
  "simulation": {"case": "kovalevskaya", "formulation": "spinor", "t_end": 150000,
                 "samples": 10, "tol": 1e-12},
  "axes": [{"field": "omega[0]", "from": 0.5, "to": 1.5, "count": 24}]})";

struct Shard0 {
  std::string sweep, out;
  std::vector<std::string> argv() const {
    return {EPVIZ_BINARY, "sweep", sweep, "--out", out, "--shard", "0/2", "-j", "1", "--quiet"};
  }
  std::string args() const {  // the arguments after the binary, as shell words
    const auto words = argv();
    std::string a;
    for (std::size_t i = 1; i < words.size(); ++i) a += words[i] + " ";
    return a;
  }
};

io::Subprocess start(const std::vector<std::string>& argv) {
  io::Subprocess::Options o;
  o.in = o.out = o.err = io::Subprocess::Stream::null;
  return io::Subprocess(argv, o);
}

TEST(ShardOwnership, ASecondCopyOfARunningShardRefusesNamingTheFirstAndMergeWaitsForIt) {
  TempDir d;
  const Shard0 shard{d.write("s.sweep.json", kSlowSweep).string(), (d / "rows.jsonl").string()};
  auto first = start(shard.argv());
  const std::string pid = std::to_string(first.pid());
  // Its manifest is written once its points are ready, just before they run.
  ASSERT_TRUE(eventually([&] { return fs::exists(d / "rows.shard-0-of-2.manifest.json"); }, 60s));

  expect_bad_input(run_epviz(shard.args(), d), ", pid " + pid + ", since ");

  // Merge calls the shard running and offers to redo only the one that never ran.
  const auto script = d / "resubmit.sh";
  const auto m = run_epviz("merge " + d.path().string() + " --resubmit " + script.string(), d);
  EXPECT_EQ(m.exit_code, 4) << m.err;
  EXPECT_NE(m.err.find("shard 0/2: running (host "), std::string::npos) << m.err;
  EXPECT_EQ(m.err.find("--shard 0/2"), std::string::npos) << "a rerun of a running shard\n"
                                                          << m.err;
  EXPECT_NE(m.err.find("shard 1/2: missing"), std::string::npos) << m.err;
  EXPECT_NE(m.err.find("0 complete, 1 running, 0 dead, 1 missing"), std::string::npos) << m.err;
  EXPECT_NE(slurp(script).find(" --array=1 "), std::string::npos) << slurp(script);

  const auto ended = first.wait();
  ASSERT_TRUE(ended.success()) << ended.describe();
  EXPECT_EQ(rows_by_index(d / "rows.shard-0-of-2.jsonl").size(), 12u);  // each point once
  EXPECT_FALSE(fs::exists(d / "rows.shard-0-of-2.lock")) << "the lock outlived its shard";
}

TEST(ShardOwnership, AShardKilledMidwayIsTakenOverAndResumedToTheUnshardedRows) {
  TempDir d;
  const Shard0 shard{d.write("s.sweep.json", kSlowSweep).string(), (d / "rows.jsonl").string()};
  ASSERT_EQ(
      run_epviz("sweep " + shard.sweep + " --out " + (d / "whole.jsonl").string(), d).exit_code, 0);

  const auto rows = d / "rows.shard-0-of-2.jsonl";
  const auto lock = d / "rows.shard-0-of-2.lock";
  {
    auto child = start(shard.argv());
    ASSERT_TRUE(eventually([&] { return line_count(slurp(rows)) >= 2; }, 60s));
    child.kill(SIGKILL);
    EXPECT_TRUE(child.wait().signalled());
  }
  ASSERT_LT(line_count(slurp(rows)), 12u) << "the shard finished before it could be killed";
  ASSERT_TRUE(fs::exists(lock)) << "a kill leaves the lock of a pid that is gone";
  std::ofstream(rows, std::ios::app) << R"({"index":11,"sweep":"0)";  // a row cut short

  const auto m = run_epviz("merge " + d.path().string(), d);
  EXPECT_NE(m.err.find("shard 0/2: dead (its lock was left by host "), std::string::npos) << m.err;

  const auto resumed = run_epviz(shard.args(), d);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("(a torn last line dropped)"), std::string::npos) << resumed.out;
  EXPECT_FALSE(fs::exists(lock));
  ASSERT_EQ(run_epviz("sweep " + shard.sweep + " --out " + shard.out + " --shard 1/2", d).exit_code,
            0);
  const auto merged = run_epviz("merge " + d.path().string(), d);
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_EQ(rows_by_index(shard.out), rows_by_index(d / "whole.jsonl"));
}

}  // namespace
}  // namespace epviz::test
