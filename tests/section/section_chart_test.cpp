// The section's chart: one point per crossing at the chosen coordinates,
// coloured by its orbit, never joined to another by a line: one scatter
// series of small dots per orbit.
#include <gtest/gtest.h>

#include "section/section_chart.hpp"

namespace epviz::section {
namespace {

TEST(SectionChart, EachOrbitIsAScatterColouredByItsOrbit) {
  SectionJob job;
  job.case_id = physics::Case::generic;
  job.coords = {sim::StateComponent::omega2, sim::StateComponent::gamma1};
  std::vector<OrbitResult> orbits(3);
  for (int i = 0; i < 3; ++i) {
    orbits[i].orbit = i + 1;
    for (int k = 1; k <= 2; ++k)
      orbits[i].crossings.push_back(
          {k, 1.0, physics::Vector3d(0.1, 10.0 * i + k, 0.3), physics::Vector3d(-i - k, 0, 0)});
  }
  orbits[1].failure = numerics::Failure{};  // lost: not drawn
  const auto spec = section_charts(job, orbits).at(0);
  EXPECT_EQ(spec.x_label, "Ω₂");  // symbols, as the atlases write them
  EXPECT_EQ(spec.y_label, "γ₁");
  ASSERT_EQ(spec.series.size(), 2u);  // orbits 1 and 3
  const std::vector<std::vector<std::pair<double, double>>> expected{{{1, -1}, {2, -2}},
                                                                     {{21, -3}, {22, -4}}};
  for (std::size_t s = 0; s < 2; ++s) {
    const auto& series = spec.series[s];
    EXPECT_EQ(series.style, chart::SeriesStyle::markers);  // a marker at each point, no line
    EXPECT_EQ(series.marker_size, chart::MarkerSize::dot);
    EXPECT_EQ(series.colour_key, s == 0 ? 0 : 2);
    ASSERT_EQ(series.points.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_EQ(series.points[k].x, expected[s][k].first);
      EXPECT_EQ(series.points[k].y, expected[s][k].second);
    }
  }
  // One legend row for all orbits.
  ASSERT_EQ(spec.marker_legend.size(), 1u);
  EXPECT_NE(spec.marker_legend[0].name.find("(3 orbits)"), std::string::npos);
}

TEST(SectionChart, TheTitleNamesTheSettingTheMethodUses) {
  SectionJob job;
  job.case_id = physics::Case::lagrange;
  job.methods[0].tol = 1e-11;
  job.methods[0].step = 0.125;
  job.methods[0].method = sim::Method::dopri5;
  EXPECT_NE(section_charts(job, {}).at(0).title.find("dopri5, tol 1e-11"), std::string::npos);
  job.methods[0].method = sim::Method::gauss4;
  EXPECT_NE(section_charts(job, {}).at(0).title.find("gauss4, step 0.125"), std::string::npos);
}

}  // namespace
}  // namespace epviz::section

namespace epviz::section {
namespace {

// Several methods: a chart each, of that method's crossings only, titled by
// its setting; all take in every crossing, so their axes are the same.
TEST(SectionChart, EachMethodHasItsChartOnSharedAxes) {
  SectionJob job;
  job.case_id = physics::Case::kovalevskaya;
  job.methods = {{sim::Method::rk4, 1e-10, 0.1}, {sim::Method::dop853, 1e-10, 0.01}};
  std::vector<OrbitResult> orbits(4);
  for (std::size_t r = 0; r < 4; ++r) {
    orbits[r].orbit = int(r % 2) + 1;
    orbits[r].method = r / 2;
    const double x = r < 2 ? 5.0 + double(r) : -1.0 - double(r);  // rk4 right, dop853 left
    orbits[r].crossings.push_back(
        {1, 1.0, physics::Vector3d(0, 0, 2.0 * x), physics::Vector3d(x, 0, 0)});
  }
  const auto charts = section_charts(job, orbits);
  ASSERT_EQ(charts.size(), 2u);
  EXPECT_NE(charts[0].title.find("rk4, step 0.1"), std::string::npos) << charts[0].title;
  EXPECT_NE(charts[1].title.find("dop853, tol 1e-10"), std::string::npos) << charts[1].title;
  for (std::size_t m = 0; m < 2; ++m) {
    ASSERT_EQ(charts[m].series.size(), 2u);  // a series per orbit
    for (const auto& s : charts[m].series) EXPECT_EQ(s.points[0].x > 0.0, m == 0);
    ASSERT_EQ(charts[m].axis_extent.size(), 4u);  // every crossing of both
    EXPECT_NE(charts[m].marker_legend.at(0).name.find("(2 orbits)"), std::string::npos);
  }
}

}  // namespace
}  // namespace epviz::section
