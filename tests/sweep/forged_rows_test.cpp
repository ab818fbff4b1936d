// Rows of a sweep's shards come from files anyone may edit: `epviz merge`
// of rows whose `ftle_curve` is not [[T, λ], ...] is refused with exit 2 and
// one line naming the file, the line and the key, never the JSON library's
// text; a lawful curve with a λ that was not finite (null) still merges.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "shard/manifest.hpp"
#include "support/cli.hpp"
#include "support/tiny_sweep.hpp"
#include "sweep/ftle_curves.hpp"

namespace epviz::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// One shard (0 of 1) of a two-point sweep in dir/shards, its first row given
// `curve` as its ftle_curve and its manifest made to match (size, checksum),
// as a forger would.
fs::path forged_shard(const TempDir& dir, const Json& curve) {
  const fs::path shards = dir / "shards";
  const fs::path manifest = run_tiny_sweep_shard(dir, shards);
  if (manifest.empty()) return shards;
  shard::Manifest m = shard::read_manifest(manifest);
  const fs::path rows = shards / m.files.at(0).path;
  std::ifstream in(rows);
  std::string text, line;
  for (int n = 0; std::getline(in, line); ++n) {
    Json row = Json::parse(line);
    if (n == 0) row["ftle_curve"] = curve;
    text += row.dump() + "\n";
  }
  in.close();
  std::ofstream(rows, std::ios::trunc) << text;
  m.files.clear();
  shard::add_file(m, shards, rows);
  shard::write_manifest(manifest, m);
  return shards;
}

TEST(ForgedRows, AForgedFtleCurveIsRefusedNamingTheFileLineAndKey) {
  for (const Json& curve : {Json("x"), Json{{1, "x"}}, Json{{1}}, Json{Json::array({-1, 0.5})},
                            Json{Json::array({1, 0.5, 2})}, Json{nullptr}}) {
    SCOPED_TRACE(curve.dump());
    TempDir dir;
    const auto shards = forged_shard(dir, curve);
    const auto r = run_epviz("merge " + shards.string(), dir);
    expect_bad_input(r, "key 'ftle_curve'");
    EXPECT_NE(r.err.find(".jsonl: line 1: "), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(shards / "rows.jsonl")) << "merged despite exit 2";
  }
}

TEST(ForgedRows, ALambdaThatWasNotFiniteIsLeftOutOfTheChart) {
  const Json rows = Json::array({{{"ftle_curve", {{0.5, 0.2}, {1, nullptr}, {2, 0.1}}}}});
  EXPECT_EQ(sweep::ftle_curve_problem(rows[0]), "");
  const auto figure = sweep::ftle_curve_figure({rows[0]}, std::nullopt);
  ASSERT_TRUE(figure);
  EXPECT_EQ(std::get<chart::ChartSpec>(figure->content).series.at(0).points.size(), 2u);
}

}  // namespace
}  // namespace epviz::test
