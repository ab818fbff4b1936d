// Energy-momentum maps: sweeps whose points are levels (C1, C0) of the two
// integrals, each measured by the FTLE of orbits that start on it. The
// oracles are independent of the level-set construction: a level below the
// least potential energy -P|r| can hold no state (the kinetic energy is not
// negative), and integrability against chaos (Kovalevskaya's orbits keep an
// FTLE near 0 and its fourth integral K; the generic body has a chaotic level).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "physics/cases.hpp"
#include "sim/run_spec.hpp"
#include "support/cli.hpp"
#include "sweep/atlas.hpp"
#include "sweep/level_point.hpp"

namespace epviz::test {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

Json shipped(const std::string& name) {
  std::ifstream in(std::string(EPVIZ_SOURCE_DIR) + "/render_jobs/" + name);
  return Json::parse(in);
}

// The shipped map cut to `count` values per axis (C0 from `area_from`) and
// `orbits` orbits per level, everything else as shipped.
Json cut(const std::string& name, int count, int orbits, double area_from = 0.0) {
  Json s = shipped(name);
  for (auto& axis : s["axes"]) {
    axis["count"] = count;
    if (axis["field"] == "area_constant") axis["from"] = area_from;
  }
  s["level_orbits"] = orbits;
  return s;
}

std::vector<Json> sweep_rows(const TempDir& dir, const std::string& name, const Json& sweep) {
  const auto file = dir.write(name + ".sweep.json", sweep.dump());
  const auto rows = dir / (name + ".jsonl");
  const auto r =
      run_epviz("sweep " + file.string() + " --out " + rows.string() + " --quiet -j 2", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::vector<Json> out;
  std::ifstream in(rows);
  for (std::string line; std::getline(in, line);) out.push_back(Json::parse(line));
  return out;
}

TEST(EnergyMomentum, ALevelBelowTheLeastPotentialIsInadmissibleNotAFailure) {
  const sim::RunSpec run = sim::preset_run(physics::Case::generic, sim::Method::dop853,
                                           sim::Formulation::direct, 5.0, 10);
  const double least_potential = -run.body.weight * run.body.com.norm();
  const sweep::FtleSettings ftle{1e-8, 0.5};
  const auto below = sweep::level_metrics(run, {least_potential - 0.1, 0.3}, 4, ftle);
  EXPECT_FALSE(below.admissible);
  EXPECT_EQ(below.orbits, 0);
  EXPECT_FALSE(below.largest_ftle);
  EXPECT_LE(below.minimum_energy, least_potential - 0.1 + 1.0);  // reported, and finite
  // Well above the energy of the state hanging on the third axis with this C0.
  const double i3 = run.body.inertia[2];
  const double hanging = -run.body.weight * run.body.com[2] + 0.3 * 0.3 / (2.0 * i3);
  const auto above = sweep::level_metrics(run, {std::abs(hanging) + 1.0, 0.3}, 4, ftle);
  EXPECT_TRUE(above.admissible);
  EXPECT_GT(above.orbits, 0);
  EXPECT_TRUE(above.largest_ftle);

  // The row says so, with no failure, and the atlas hatches the cell as
  // inadmissible rather than leaving it grey.
  sweep::PreparedPoint p;
  p.index = 0;
  p.axes = R"({"energy":-9,"area_constant":0.3})";
  p.run = run;
  const Json row = Json::parse(sweep::level_row(p, "h", below).line);
  EXPECT_EQ(row["admissible"], false);
  EXPECT_TRUE(row["failure"].is_null());
  Json other = Json::parse(sweep::level_row(p, "h", above).line);
  other["index"] = 1;
  other["axes"]["energy"] = 9;
  const auto figures =
      sweep::atlas_figures({row, other}, {"ftle", "area_constant", "energy", 0.0, 0.3});
  ASSERT_EQ(figures.size(), 1u);
  const auto& h = figures[0].heat_map;
  ASSERT_EQ(h.rows.size(), 2u);  // energy upwards: 9 in the first row
  ASSERT_FALSE(h.undecided.empty());
  EXPECT_TRUE(h.undecided[1][0]);
  EXPECT_FALSE(h.undecided[0][0]);
  EXPECT_NE(h.undecided_label.find("inadmissible"), std::string::npos);
}

// C0 from 0.5: at C0 = 0 one of the generator's Kovalevskaya orbits lies near
// a hyperbolic set of the integrable top (FTLE 0.3 to 0.6 with K kept to
// 1e-10; docs/cluster.md).
// A colour bar fixed from 0 stays linear however far the values spread (the
// two shipped FTLE maps compare by colour); values all below 1e-3, such as a
// drift of K, are drawn in log10, where linear ticks would all read 0.
TEST(EnergyMomentum, AtlasScaleFollowsTheFixedRangeAndTinyValues) {
  std::vector<Json> rows;
  for (int i = 0; i < 2; ++i) {
    Json r = {{"index", i},
              {"axes", {{"energy", 1.0 + i}, {"area_constant", 0.5}}},
              {"ftle", i == 0 ? 1e-4 : 0.2},
              {"extra_integral_range", i == 0 ? 1e-11 : 5e-11},
              {"failure", nullptr}};
    rows.push_back(r);
  }
  const auto ftle = sweep::atlas_figures(rows, {"ftle", "area_constant", "energy", 0.0, 0.3});
  EXPECT_FALSE(ftle.at(0).heat_map.log_scale);
  const auto free_ftle = sweep::atlas_figures(rows, {"ftle", "area_constant", "energy"});
  EXPECT_TRUE(free_ftle.at(0).heat_map.log_scale);  // 1e-4 to 0.2, no range given
  const auto k = sweep::atlas_figures(rows, {"extra_integral_range", "area_constant", "energy"});
  EXPECT_TRUE(k.at(0).heat_map.log_scale);
}

TEST(EnergyMomentum, KovalevskayaStaysNearZeroFtleWhileTheGenericBodyHasChaos) {
  TempDir dir;
  const auto kov =
      sweep_rows(dir, "kovalevskaya", cut("energy_momentum_kovalevskaya.sweep.json", 3, 4, 0.5));
  ASSERT_EQ(kov.size(), 9u);
  int admissible = 0;
  for (const auto& r : kov) {
    if (r["admissible"] == false) continue;
    ++admissible;
    ASSERT_TRUE(r["ftle"].is_number()) << r.dump();
    EXPECT_LT(r["ftle"].get<double>(), sweep::kChaoticFtle) << r.dump();
    EXPECT_EQ(r["chaotic_share"].get<double>(), 0.0) << r.dump();
    EXPECT_LT(r["extra_integral_range"].get<double>(), 1e-6) << r.dump();
  }
  EXPECT_GE(admissible, 3);

  const auto generic =
      sweep_rows(dir, "generic", cut("energy_momentum_generic.sweep.json", 3, 4, 0.5));
  ASSERT_EQ(generic.size(), 9u);
  double largest = 0.0;
  for (const auto& r : generic) {
    if (r["ftle"].is_number()) largest = std::max(largest, r["ftle"].get<double>());
    EXPECT_TRUE(r["extra_integral_range"].is_null()) << "the generic body has no K";
  }
  EXPECT_GT(largest, sweep::kChaoticFtle);
}

TEST(EnergyMomentum, BadLevelKeysAreRefusedWithOneLine) {
  TempDir dir;
  const auto rows = dir / "em.jsonl";
  auto refused = [&](const Json& s, const std::string& names) {
    const auto file = dir.write("em.sweep.json", s.dump());
    expect_bad_input(
        run_epviz("sweep " + file.string() + " --out " + rows.string() + " --quiet", dir), names);
    EXPECT_FALSE(fs::exists(rows));
  };
  const Json good = cut("energy_momentum_generic.sweep.json", 2, 2);
  Json s = good;
  s.erase("level_orbits");
  refused(s, "'area_constant' makes a level");
  s = good;
  s["level_orbits"] = 0;
  refused(s, "key 'level_orbits'");
  s = good;
  s["axes"].erase(0);  // the energy axis
  s["atlas"] = Json::array();
  refused(s, "an 'energy' axis (C1) and an 'area_constant' axis (C0)");
  s = good;
  s.erase("ftle");
  s["atlas"] = Json::array();
  refused(s, "needs \"ftle\"");
  s = good;
  s["axes"].push_back({{"field", "gamma[0]"}, {"values", {0.1}}});
  refused(s, "the level gives the initial states");
  s = good;
  s["atlas"][0]["metric"] = "steps";
  refused(s, "allowed: ftle, chaotic_share");
}

}  // namespace
}  // namespace epviz::test
