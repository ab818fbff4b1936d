// `epviz sweep` and `epviz merge` checking a sweep's own accuracy: the
// shipped chaos map, cut to an 8 x 8 grid with everything else as shipped,
// passes; the same sweep at tol 1e-8 (in shards) is flagged "not converged"
// and merge exits 3 unless --allow-unconverged. And a sweep whose atlas asks for a
// metric its rows will not have is refused before any point runs.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace epviz::test {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

// render_jobs/chaos_map.sweep.json on an 8 x 8 grid of the same range,
// at `tol` when given (else the shipped one).
Json cut_chaos_map(std::optional<double> tol) {
  std::ifstream in(std::string(EPVIZ_SOURCE_DIR) + "/render_jobs/chaos_map.sweep.json");
  Json s = Json::parse(in);
  for (auto& axis : s["axes"])
    if (axis.contains("count")) axis["count"] = 8;
  if (tol) s["simulation"]["tol"] = *tol;
  return s;
}

struct Merged {
  CliResult merge;
  Json check;  // the self-check JSON beside the merged rows; null when none
};

// Runs `sweep` as `shards` shards into dir/rows and merges them (with `merge_args`).
Merged sweep_and_merge(const TempDir& dir, const Json& sweep, int shards = 1,
                       const std::string& merge_args = "") {
  const auto file = dir.write("chaos.sweep.json", sweep.dump());
  fs::create_directories(dir / "rows");
  for (int i = 0; i < shards; ++i) {
    const auto s = run_epviz("sweep " + file.string() + " --out " +
                                 (dir / "rows/chaos.jsonl").string() + " --shard " +
                                 std::to_string(i) + "/" + std::to_string(shards) + " --quiet -j 2",
                             dir);
    EXPECT_EQ(s.exit_code, 0) << s.err;
  }
  Merged m{run_epviz("merge " + (dir / "rows").string() + " --format svg " + merge_args, dir),
           nullptr};
  const auto json = dir / "rows/chaos.self_check.json";
  if (fs::exists(json)) m.check = Json::parse(slurp(json));
  return m;
}

TEST(SelfCheckCommand, TheShippedChaosMapPasses) {
  TempDir dir;
  const auto m = sweep_and_merge(dir, cut_chaos_map(std::nullopt));
  EXPECT_EQ(m.merge.exit_code, 0) << m.merge.out << m.merge.err;
  ASSERT_TRUE(m.check.is_object()) << m.merge.out;
  EXPECT_EQ(m.check["sampled_points"], 16);
  EXPECT_EQ(m.check["converged"], true) << m.check["metrics"].dump();
  EXPECT_EQ(m.check["metrics"]["ftle"]["compared"], 16);
  EXPECT_EQ(m.check["metrics"]["ftle"]["limit"], 0.05 * 0.3);
  EXPECT_NE(m.merge.out.find("self-check ftle"), std::string::npos) << m.merge.out;
  EXPECT_TRUE(fs::exists(dir / "rows/atlas_ftle_gamma0_gamma1.svg"));
}

TEST(SelfCheckCommand, TheChaosMapAtTol1e8IsNotConverged) {
  // In 3 shards: the check is the merge's, whatever the shards.
  TempDir dir;
  const auto m = sweep_and_merge(dir, cut_chaos_map(1e-8), 3);
  EXPECT_EQ(m.merge.exit_code, 3) << m.merge.out << m.merge.err;
  EXPECT_NE(m.merge.err.find("--allow-unconverged"), std::string::npos) << m.merge.err;
  ASSERT_TRUE(m.check.is_object()) << m.merge.out;
  EXPECT_EQ(m.check["converged"], false);
  EXPECT_GT(m.check["metrics"]["ftle"]["largest_change"].get<double>(), 0.05 * 0.3);
  // The figure is drawn all the same, saying so; and with the flag merge accepts it.
  EXPECT_TRUE(fs::exists(dir / "rows/atlas_ftle_gamma0_gamma1.svg"));
  const auto allowed =
      run_epviz("merge " + (dir / "rows").string() + " --format svg --allow-unconverged", dir);
  EXPECT_EQ(allowed.exit_code, 0) << allowed.err;
  EXPECT_NE(allowed.out.find("NOT CONVERGED"), std::string::npos) << allowed.out;
}

TEST(SelfCheckCommand, AThresholdKeyLoosensTheCheck) {
  // tol 1e-8 moves the FTLE by several hundredths: within half the colour bar.
  TempDir dir;
  Json s = cut_chaos_map(1e-8);
  s["self_check"] = {{"threshold", 0.5}};
  const auto m = sweep_and_merge(dir, s);
  EXPECT_EQ(m.merge.exit_code, 0) << m.merge.out << m.merge.err;
  EXPECT_EQ(m.check["threshold"], 0.5);
  // A share outside 1e-6 to 1 is refused before any work.
  s["self_check"]["threshold"] = 2;
  const auto file = dir.write("bad.sweep.json", s.dump());
  expect_bad_input(
      run_epviz("sweep " + file.string() + " --out " + (dir / "bad.jsonl").string() + " --quiet",
                dir),
      "key 'self_check.threshold'");
  EXPECT_FALSE(fs::exists(dir / "bad.jsonl"));
}

TEST(SelfCheckCommand, AnAtlasMetricNoRowWillHaveIsRefusedBeforeAnyWork) {
  TempDir dir;
  Json s = cut_chaos_map(std::nullopt);
  s["atlas"][0]["metric"] = "drift";
  const auto file = dir.write("chaos.sweep.json", s.dump());
  const auto rows = dir / "chaos.jsonl";
  const auto r = run_epviz("sweep " + file.string() + " --out " + rows.string() + " --quiet", dir);
  expect_bad_input(r, "key 'atlas[0].metric'");
  EXPECT_NE(r.err.find(file.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("allowed: ftle"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(rows)) << "points ran before the check";
  // So is an FTLE atlas of a sweep that computes none.
  s["atlas"][0]["metric"] = "ftle";
  s.erase("ftle");
  const auto no_ftle = dir.write("chaos.sweep.json", s.dump());
  expect_bad_input(
      run_epviz("sweep " + no_ftle.string() + " --out " + rows.string() + " --quiet", dir),
      "'ftle' is not in this sweep's rows");
  EXPECT_FALSE(fs::exists(rows));
}

}  // namespace
}  // namespace epviz::test
