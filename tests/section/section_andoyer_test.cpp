// Sections in Andoyer–Deprit variables (docs/sections.md, "Andoyer–Deprit
// variables"): the shipped Kovalevskaya section g = 0 at (l, L/G) keeps
// every crossing on its level (C0, C1 and K written here from the state), on
// the surface in the asked direction (g from the nodes, written here), and
// its chart does not fold (pairs close in the plot are close in state,
// checked pair by pair here), where (l, G) folds and says so; the CSV's
// Andoyer columns; the singular set left out of the picture and empty in
// the CSV; bad keys refused.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "physics/direct.hpp"
#include "section/section_chart.hpp"
#include "section/section_csv.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"
#include "section/sheet_fold.hpp"
#include "support/cli.hpp"

namespace epviz::section {
namespace {

using physics::Vector3d;

SectionJob shipped(int crossings) {
  auto job = read_section_job(std::string(EPVIZ_SOURCE_DIR) +
                              "/render_jobs/kovalevskaya_andoyer.section.json");
  job.crossings = crossings;
  return job;
}

// sin g and cos g from the nodes n1 = γ × M (horizontal plane ∩ invariant
// plane) and n2 = M × e3 (invariant plane ∩ body equator), g from n1 to n2
// about M (docs/math.md §1.6).
std::pair<double, double> sin_cos_g(const physics::Body& body, const Vector3d& omega,
                                    const Vector3d& gamma) {
  const Vector3d m = body.inertia.cwiseProduct(omega);
  const Vector3d n1 = gamma.cross(m).normalized();
  const Vector3d n2 = m.cross(Vector3d::UnitZ()).normalized();
  return {n1.cross(n2).dot(m.normalized()), n1.dot(n2)};
}

TEST(AndoyerSection, ShippedFileNamesAnAngleSurfaceAndAndoyerAxes) {
  const auto job = shipped(400);
  ASSERT_TRUE(job.surface.angle);
  EXPECT_EQ(*job.surface.angle, physics::AndoyerAngle::g);
  EXPECT_EQ(job.coords[0], PlotCoord(AndoyerCoord::l));
  EXPECT_EQ(job.coords[1], PlotCoord(AndoyerCoord::L_over_G));
  EXPECT_FALSE(job.sheet) << "the chart does not fold: no sheets needed (below)";
}

TEST(AndoyerSection, EveryCrossingIsOnTheLevelAndTheSurfaceUpward) {
  const auto job = shipped(150);
  const auto results = run_section(job, section_starts(job), 2);
  const auto& b = job.body;
  const double k = b.weight * b.com.x() / b.inertia.z();
  const physics::DirectSystem sys(b);
  std::size_t n = 0;
  double worst_c0 = 0, worst_c1 = 0, worst_k = 0, worst_sin = 0;
  for (const auto& r : results) {
    ASSERT_FALSE(r.failure);
    const auto kov = [&](const Vector3d& w, const Vector3d& g) {
      return std::pow(w.x() * w.x() - w.y() * w.y() - k * g.x(), 2) +
             std::pow(2 * w.x() * w.y() - k * g.y(), 2);
    };
    const double k0 = kov(r.start.omega, r.start.gamma);
    for (const auto& c : r.crossings) {
      const Vector3d m = b.inertia.cwiseProduct(c.omega);
      const double c0 = m.dot(c.gamma);
      const double c1 = 0.5 * m.dot(c.omega) + b.weight * b.com.dot(c.gamma);
      worst_c0 = std::max(worst_c0, std::abs(c0 - job.level->area));
      worst_c1 = std::max(worst_c1, std::abs(c1 - job.level->energy));
      worst_k = std::max(worst_k, std::abs(kov(c.omega, c.gamma) - k0) / (1 + k0));
      const auto [s, co] = sin_cos_g(b, c.omega, c.gamma);
      worst_sin = std::max(worst_sin, std::abs(s));
      EXPECT_GT(co, 0.0) << "a crossing at g = π, not g = 0";
      // Upward: sin g grows along the flow.
      physics::DirectSystem::State x, dx;
      x << c.omega, c.gamma;
      sys.rhs(0.0, x, dx);
      const double dt = 1e-7;
      const auto ahead = sin_cos_g(b, c.omega + dt * dx.head<3>(), c.gamma + dt * dx.tail<3>());
      EXPECT_GT(ahead.first, s) << "orbit " << r.orbit << " crossing " << c.number;
      ++n;
    }
  }
  std::printf("%zu crossings: |C0 - 0.5| %.2g, |C1 - 2| %.2g, K %.2g, |sin g| %.2g\n", n, worst_c0,
              worst_c1, worst_k, worst_sin);
  EXPECT_EQ(n, 16u * 150u);
  EXPECT_LE(worst_c0, 1e-8);
  EXPECT_LE(worst_c1, 1e-8);
  EXPECT_LE(worst_k, 1e-7);
  EXPECT_LE(worst_sin, 1e-12);
}

// Pairs of crossings within 1/500 of the axes' ranges in the plot, and the
// largest distance of their states (Ω and γ, each as is).
struct CloseInPlot {
  long pairs = 0;
  double widest_state_gap = 0.0;
};

CloseInPlot close_pairs(const SectionJob& job, const std::vector<OrbitResult>& results) {
  std::vector<std::array<double, 8>> pts;  // x, y, Ω, γ
  for (const auto& r : results)
    for (const auto& c : r.crossings) {
      const auto x = value_of(job.coords[0], job.body, c.omega, c.gamma);
      const auto y = value_of(job.coords[1], job.body, c.omega, c.gamma);
      if (x && y)
        pts.push_back(
            {*x, *y, c.omega.x(), c.omega.y(), c.omega.z(), c.gamma.x(), c.gamma.y(), c.gamma.z()});
    }
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const auto& p : pts)
    for (int i = 0; i < 2; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  CloseInPlot out;
  for (std::size_t a = 0; a < pts.size(); ++a)
    for (std::size_t b = a + 1; b < pts.size(); ++b) {
      if (std::abs(pts[a][0] - pts[b][0]) > 0.002 * (hi[0] - lo[0]) ||
          std::abs(pts[a][1] - pts[b][1]) > 0.002 * (hi[1] - lo[1]))
        continue;
      ++out.pairs;
      double d2 = 0;
      for (int k = 2; k < 8; ++k) d2 += std::pow(pts[a][k] - pts[b][k], 2);
      out.widest_state_gap = std::max(out.widest_state_gap, std::sqrt(d2));
    }
  return out;
}

TEST(AndoyerSection, ChartDoesNotFoldWhereGFolds) {
  auto job = shipped(150);
  const auto results = run_section(job, section_starts(job), 2);
  const CloseInPlot lg = close_pairs(job, results);
  std::printf("(l, L/G): %ld close pairs, widest state gap %.3g\n", lg.pairs, lg.widest_state_gap);
  EXPECT_GT(lg.pairs, 500);              // enough to tell
  EXPECT_LT(lg.widest_state_gap, 0.05);  // Ω and γ are of size 1 here
  EXPECT_TRUE(fold_warnings(job, results).empty());
  // (l, G) on the same crossings covers the surface twice: pairs close in
  // the plot far apart in state, which the fold check reports too.
  job.coords = {AndoyerCoord::l, AndoyerCoord::G};
  const CloseInPlot g = close_pairs(job, results);
  std::printf("(l, G): %ld close pairs, widest state gap %.3g\n", g.pairs, g.widest_state_gap);
  EXPECT_GT(g.widest_state_gap, 0.5);
  const auto warnings = fold_warnings(job, results);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("folds two sheets"), std::string::npos);
}

TEST(AndoyerSection, CsvHasThePlottedVariablesAndReadsBack) {
  const auto job = shipped(5);
  const auto results = run_section(job, section_starts(job), 2);
  const std::string csv = crossings_csv(job, results);
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header,
            "orbit,crossing,t,omega1,omega2,omega3,gamma1,gamma2,gamma3,energy,area,"
            "gamma_norm_error,extra_integral,andoyer_l,andoyer_L_over_G");
  // The first row's last two fields: l and L/G from M = I Ω, written here.
  const std::size_t start = header.size() + 1;
  const std::string row = csv.substr(start, csv.find('\n', start) - start);
  const auto last = row.rfind(',');
  const auto before = row.rfind(',', last - 1);
  const double l = std::stod(row.substr(before + 1, last - before - 1));
  const double l_over_g = std::stod(row.substr(last + 1));
  const auto& c = results[0].crossings[0];
  const Vector3d m = job.body.inertia.cwiseProduct(c.omega);
  EXPECT_NEAR(l, std::atan2(m.x(), m.y()), 1e-15);
  EXPECT_NEAR(l_over_g, m.z() / m.norm(), 1e-15);
  // Read back (a shard merge), the same crossings.
  const auto back = crossings_from_csv(job, csv, "k.csv");
  ASSERT_EQ(back.size(), results.size());
  for (std::size_t i = 0; i < back.size(); ++i)
    for (std::size_t j = 0; j < back[i].crossings.size(); ++j)
      EXPECT_EQ(back[i].crossings[j].omega, results[i].crossings[j].omega);
  const auto columns = crossing_columns(job);
  EXPECT_EQ(columns.back(), "andoyer_L_over_G");
  std::size_t rows = 0;
  for_each_crossing_row(job, results, [&](std::span<const double> r) {
    EXPECT_EQ(r.size(), columns.size());
    ++rows;
  });
  EXPECT_EQ(rows, 16u * 5u);
}

TEST(AndoyerSection, TheSingularSetIsNotDrawnAndEmptyInTheCsv) {
  auto job = shipped(1);
  OrbitResult r;
  r.orbit = 1;
  sim::Crossing on_axis;  // spinning about e3: L = G, no l
  on_axis.number = 1;
  on_axis.omega = {0.0, 0.0, 2.0};
  on_axis.gamma = {1.0, 0.0, 0.0};
  sim::Crossing off = on_axis;
  off.number = 2;
  off.omega = {0.3, -0.2, 2.0};
  r.crossings = {on_axis, off};
  const std::vector<OrbitResult> results{r};
  const std::string csv = crossings_csv(job, results);
  const auto first_row = csv.substr(csv.find('\n') + 1);
  const std::string line = first_row.substr(0, first_row.find('\n'));
  // l empty, L/G = 1.
  EXPECT_EQ(line.substr(line.size() - 3), ",,1") << line;
  const auto charts = section_charts(job, results);
  ASSERT_EQ(charts.size(), 1u);
  ASSERT_EQ(charts[0].series.size(), 1u);
  EXPECT_EQ(charts[0].series[0].points.size(), 1u);
  EXPECT_NE(charts[0].marker_legend[0].name.find("1 on the Andoyer variables' singular set"),
            std::string::npos)
      << charts[0].marker_legend[0].name;
  // And read back: an empty Andoyer field is no error.
  EXPECT_EQ(crossings_from_csv(job, csv, "k.csv")[0].crossings.size(), 2u);
}

TEST(AndoyerSection, AnLSurfaceAndTheScalarPathFindCrossingsOnIt) {
  // l = 1 downward with RK4 (the scalar search on its Hermite interpolant),
  // against DOP853 at tol 1e-12 (the batch's): the same crossings. Orbits
  // whose l librates about −π/2 never reach it.
  auto job = shipped(20);
  job.surface = {sim::StateComponent::gamma3, 1.0, sim::CrossingDirection::downward,
                 physics::AndoyerAngle::l};
  job.t_end = 300;
  auto tight = job;
  job.methods = {SectionMethod{sim::Method::rk4, 1e-10, 0.002}};
  tight.methods = {SectionMethod{sim::Method::dop853, 1e-12, 0.01}};
  const auto starts = section_starts(job);
  const auto rk4 = run_section(job, starts, 2), dop = run_section(tight, starts, 2);
  std::size_t n = 0, circulating = 0;
  for (std::size_t i = 0; i < rk4.size(); ++i) {
    ASSERT_FALSE(rk4[i].failure);
    ASSERT_EQ(rk4[i].crossings.size(), dop[i].crossings.size()) << "orbit " << i + 1;
    circulating += rk4[i].crossings.empty() ? 0 : 1;
    for (std::size_t j = 0; j < rk4[i].crossings.size(); ++j) {
      const auto& c = rk4[i].crossings[j];
      const Vector3d m = job.body.inertia.cwiseProduct(c.omega);
      EXPECT_NEAR(std::atan2(m.x(), m.y()), 1.0, 1e-12);
      EXPECT_NEAR(c.t, dop[i].crossings[j].t, 1e-6);
      ++n;
    }
  }
  EXPECT_GE(circulating, 4u);
  std::printf("l = 1: %zu of %zu orbits reach it, %zu crossings\n", circulating, rk4.size(), n);
}

TEST(AndoyerSection, BothDirectionsAreTheTwoAndNeverTheOppositeAngle) {
  // g = 0.5 both ways: the upward and the downward crossings together, and
  // none at g = 0.5 + π, where r sin(g − 0.5) passes through zero too (as
  // often as at g = 0.5 on an orbit whose g circulates).
  auto job = shipped(60);
  job.surface.value = 0.5;
  std::size_t counts[3] = {};
  std::vector<OrbitResult> both;
  for (auto d : {sim::CrossingDirection::upward, sim::CrossingDirection::downward,
                 sim::CrossingDirection::both}) {
    job.surface.direction = d;
    job.crossings = d == sim::CrossingDirection::both ? 120 : 60;
    job.t_end = 200;
    const auto results = run_section(job, section_starts(job), 2);
    for (const auto& r : results) counts[std::size_t(d)] += r.crossings.size();
    if (d == sim::CrossingDirection::both) both = results;
  }
  EXPECT_GT(counts[0], 16u);
  EXPECT_EQ(counts[2], counts[0] + counts[1]);
  for (const auto& r : both)
    for (const auto& c : r.crossings) {
      const auto [s, co] = sin_cos_g(job.body, c.omega, c.gamma);
      EXPECT_NEAR(std::atan2(s, co), 0.5, 1e-12);
    }
}

TEST(AndoyerSection, RunsByItsNameAndIsListed) {
  test::TempDir d;
  const std::string in_d = "cd " + d.path().string() + " &&";
  const auto r = test::run_epviz("section kovalevskaya_andoyer -j 2", d, in_d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("folds"), std::string::npos) << r.err;
  EXPECT_EQ(test::line_count(test::slurp(d / "kovalevskaya_andoyer.section.csv")), 1u + 16u * 400u);
  EXPECT_EQ(test::slurp(d / "kovalevskaya_andoyer.section.png").substr(1, 3), "PNG");
  const auto list = test::run_epviz("render --list-jobs", d);
  EXPECT_NE(list.out.find("kovalevskaya_andoyer"), std::string::npos) << list.out;
}

TEST(AndoyerSection, BadKeysAreRefusedNamingWhatIsAllowed) {
  const std::string head = R"({"case": "kovalevskaya", "level": {"energy": 2, "area": 0.5},
      "orbits": 2, "csv": "x.csv", )";
  struct BadFile {
    const char* name;
    std::string text;
    const char* must_name;
  };
  const std::vector<BadFile> cases{
      {"unknown function", head + R"("section": {"function": "andoyer_h"}})", "andoyer_g"},
      {"unknown coordinate", head + R"("coords": ["andoyer_l", "andoyer_LG"]})",
       "andoyer_L_over_G"},
      {"sheet that is plotted", head + R"("section": {"function": "andoyer_g"},
        "coords": ["andoyer_l", "gamma2"], "sheets": "gamma2"})",
       "'sheets'"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    test::TempDir d;
    std::ofstream(d / "s.section.json") << c.text;
    test::expect_bad_input(test::run_epviz("section " + (d / "s.section.json").string(), d),
                           c.must_name);
  }
}

}  // namespace
}  // namespace epviz::section
