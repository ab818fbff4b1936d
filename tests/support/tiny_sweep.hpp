#pragma once
// A sweep of two points, small enough to run through the epviz command in a
// test, run as the one shard (0 of 1) of a batch: what the merge tests start
// from before they edit a shard's rows or manifest as a forger would.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli.hpp"
#include "support/temp_dir.hpp"

namespace epviz::test {

inline constexpr const char* kTinySweep = R"({
  "simulation": {"case": "generic", "t_end": 1, "samples": 2},
  "axes": [{"field": "energy", "values": [1.5, 3.0]}]})";

// Writes dir/s.sweep.json, runs it as shard 0 of 1 with its rows named
// shards/rows.jsonl, and returns the shard's manifest; empty, with the
// failure added to the test, when the run did not succeed.
inline std::filesystem::path run_tiny_sweep_shard(const TempDir& dir,
                                                  const std::filesystem::path& shards) {
  const auto sweep = dir.write("s.sweep.json", kTinySweep);
  std::filesystem::create_directories(shards);
  const auto r = run_epviz(
      "sweep " + sweep.string() + " --out " + (shards / "rows.jsonl").string() + " --shard 0/1",
      dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return {};
  for (const auto& e : std::filesystem::directory_iterator(shards))
    if (e.path().string().ends_with(".manifest.json")) return e.path();
  ADD_FAILURE() << "the shard wrote no manifest in " << shards;
  return {};
}

}  // namespace epviz::test
