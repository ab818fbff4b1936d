// The words of an atlas: axes named by symbol (and a γ component the runs
// rescaled called what it is), the colour bar's meaning with its unit, and a
// caption naming T, the method, its tol and the FTLE window and separation.
// The rows come from real runs of a small γ sweep.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "physics/cases.hpp"
#include "sweep/atlas.hpp"
#include "sweep/atlas_labels.hpp"
#include "sweep/point_run.hpp"
#include "sweep/sweep_point.hpp"

namespace epviz::sweep {
namespace {

using Json = nlohmann::json;

// A 3 x 2 sweep of gamma[0] and gamma[1] (gamma[2] from the base), each run
// with its gamma rescaled to a unit vector when `normalise`, as
// normalize_gamma does; the base: the generic body, rk4 at tol 1e-7, T = 2.
struct SmallSweep {
  SweepSpec spec;
  std::vector<Json> rows;
};
SmallSweep gamma_sweep(bool normalise) {
  SmallSweep s;
  s.spec = read_sweep(Json::parse(R"({
      "simulation": {"case": "generic", "t_end": 2, "samples": 20, "method": "dop853", "tol": 1e-7},
      "axes": [{"field": "gamma[0]", "values": [0.2, 0.35, 0.5]},
               {"field": "gamma[1]", "values": [0.1, 0.3]}],
      "ftle": {"window": 0.5, "separation": 1e-7}})"),
                      "small.sweep.json");
  for (long i = 0; i < s.spec.point_count(); ++i) {
    const PointFields f = point_fields(s.spec, i);
    sim::RunSpec run = sim::preset_run(physics::Case::generic, sim::Method::dop853,
                                       sim::Formulation::direct, 2.0, 20);
    run.tol = 1e-7;
    run.initial.gamma[0] = f.axis_values.at("gamma[0]").get<double>();
    run.initial.gamma[1] = f.axis_values.at("gamma[1]").get<double>();
    if (normalise)
      run.initial.gamma.normalize();
    else  // a unit vector as given: gamma[2] completes it
      run.initial.gamma[2] = std::sqrt(1.0 - run.initial.gamma[0] * run.initial.gamma[0] -
                                       run.initial.gamma[1] * run.initial.gamma[1]);
    const auto row = run_point(prepared_point(f, run), "h", false, s.spec.ftle, nullptr);
    s.rows.push_back(Json::parse(row.line));
  }
  return s;
}

TEST(AtlasLabels, GammaAxesBySymbolAndACaptionOfTheRuns) {
  const auto s = gamma_sweep(false);
  const auto figs =
      atlas_figures(s.rows, parse_atlas_option("ftle:gamma[0]:gamma[1]"), s.spec.ftle);
  ASSERT_EQ(figs.size(), 1u);
  const auto& h = figs[0].heat_map;
  EXPECT_EQ(h.x_label, "γ₁");
  EXPECT_EQ(h.y_label, "γ₂");
  EXPECT_EQ(h.value_label, "largest FTLE λ (1/time)");
  for (const char* w :
       {"T = 2", "method dop853", "tol = 1e-07", "FTLE window 0.5", "separation 1e-07"})
    EXPECT_NE(h.note.find(w), std::string::npos) << w << " not in: " << h.note;
  // Numeric axes carry their values, x ascending, y from the top (largest) down.
  EXPECT_EQ(h.column_values, (std::vector<double>{0.2, 0.35, 0.5}));
  EXPECT_EQ(h.row_values, (std::vector<double>{0.3, 0.1}));
  EXPECT_EQ(figs[0].file_name, "atlas_ftle_gamma0_gamma1.png");
}

TEST(AtlasLabels, NormalisedGammaIsCalledTheComponentBeforeNormalisation) {
  const auto s = gamma_sweep(true);
  const auto figs =
      atlas_figures(s.rows, parse_atlas_option("ftle:gamma[0]:gamma[1]"), s.spec.ftle);
  ASSERT_EQ(figs.size(), 1u);
  EXPECT_EQ(figs[0].heat_map.x_label, "γ₁ before normalisation");
  EXPECT_EQ(figs[0].heat_map.y_label, "γ₂ before normalisation");
}

TEST(AtlasLabels, WithoutTheSweepsFtleSettingsTheCaptionNamesNoWindow) {
  const auto s = gamma_sweep(false);
  const auto figs = atlas_figures(s.rows, parse_atlas_option("ftle:gamma[0]:gamma[1]"));
  ASSERT_EQ(figs.size(), 1u);
  // It says the window is unknown rather than guess one.
  EXPECT_NE(figs[0].heat_map.note.find("window unknown"), std::string::npos)
      << figs[0].heat_map.note;
  EXPECT_EQ(figs[0].heat_map.note.find("window 0"), std::string::npos) << figs[0].heat_map.note;
  EXPECT_NE(figs[0].heat_map.note.find("T = 2"), std::string::npos) << figs[0].heat_map.note;
}

TEST(AtlasLabels, Symbols) {
  EXPECT_EQ(axis_symbol("gamma[2]"), "γ₃");
  EXPECT_EQ(axis_symbol("omega[0]"), "Ω₁");
  EXPECT_EQ(axis_symbol("energy"), "C₁");
  EXPECT_EQ(axis_symbol("t_end"), "T");
  EXPECT_EQ(axis_symbol("inertia[1]"), "inertia[1]");
  EXPECT_EQ(axis_symbol("gamma"), "gamma");
  EXPECT_EQ(metric_label("max_relative_drift.area"), "largest relative drift of C₀");
  EXPECT_EQ(metric_label("max_relative_drift.energy"), "largest relative drift of C₁");
  EXPECT_EQ(metric_label("largest_stable:step"), "largest stable step");
}

// The range of the fourth integral is named by the symbol of the case the rows
// ran, and in words when they ran several cases, one without a fourth
// integral, or do not say which.
TEST(AtlasLabels, FourthIntegralRangeIsNamedByTheCasesSymbol) {
  auto rows_of = [](std::vector<const char*> cases) {
    std::vector<Json> rows;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      Json r = {{"index", long(i)},
                {"axes", {{"energy", 1.0 + double(i)}, {"area_constant", 0.5}}},
                {"extra_integral_range", 1e-10 * double(i + 1)}};
      if (cases[i]) r["case"] = cases[i];
      rows.push_back(r);
    }
    return rows;
  };
  auto label = [&](std::vector<const char*> cases) {
    const auto figs =
        atlas_figures(rows_of(cases), {"extra_integral_range", "area_constant", "energy"});
    EXPECT_EQ(figs.size(), 1u);
    const auto& h = figs.at(0).heat_map;
    EXPECT_TRUE(h.title.starts_with(h.value_label)) << h.title;
    return h.value_label;
  };
  EXPECT_EQ(label({"kovalevskaya", "kovalevskaya"}), "largest relative range of K over an orbit");
  EXPECT_EQ(label({"lagrange", "lagrange"}), "largest relative range of Ω₃ over an orbit");
  EXPECT_EQ(label({"goryachev-chaplygin", "goryachev-chaplygin"}),
            "largest relative range of G over an orbit");
  const std::string neutral = "largest relative range of the case's fourth integral over an orbit";
  EXPECT_EQ(label({"kovalevskaya", "lagrange"}), neutral);
  EXPECT_EQ(label({"generic", "generic"}), neutral);
  EXPECT_EQ(label({"kovalevskaya", nullptr}), neutral);
  EXPECT_EQ(metric_label("extra_integral_range"), neutral);
}

// A value that varies among the rows (an axis) is not in the caption.
TEST(AtlasLabels, CaptionLeavesOutWhatVaries) {
  const Json a = {{"t_end", 10.0}, {"method", "rk4"}, {"step", 0.1}};
  const Json b = {{"t_end", 10.0}, {"method", "rk4"}, {"step", 0.2}};
  EXPECT_EQ(atlas_caption({&a, &b}, "ftle", FtleSettings{1e-8, 0.0}),
            "T = 10, method rk4; FTLE window the sample spacing, separation 1e-08");
  EXPECT_EQ(atlas_caption({&a}, "steps", FtleSettings{}), "T = 10, method rk4, step = 0.1");
}

}  // namespace
}  // namespace epviz::sweep
