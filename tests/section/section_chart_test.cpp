// The section's chart: one point per crossing at the chosen coordinates,
// coloured by its orbit, never joined to another by a line.
#include <gtest/gtest.h>

#include "section/section_chart.hpp"

namespace epviz::section {
namespace {

TEST(SectionChart, EachCrossingIsOnePointColouredByItsOrbit) {
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
  const auto spec = section_chart(job, orbits);
  EXPECT_EQ(spec.x_label, "Ω₂");  // symbols, as the atlases write them
  EXPECT_EQ(spec.y_label, "γ₁");
  ASSERT_EQ(spec.series.size(), 4u);
  const std::vector<std::pair<double, double>> expected{{1, -1}, {2, -2}, {21, -3}, {22, -4}};
  for (std::size_t s = 0; s < 4; ++s) {
    ASSERT_EQ(spec.series[s].points.size(), 1u);  // a series of one point draws no line
    EXPECT_EQ(spec.series[s].points[0].x, expected[s].first);
    EXPECT_EQ(spec.series[s].points[0].y, expected[s].second);
    EXPECT_EQ(spec.series[s].colour_key, s < 2 ? 0 : 2);
  }
}

TEST(SectionChart, TheTitleNamesTheSettingTheMethodUses) {
  SectionJob job;
  job.case_id = physics::Case::lagrange;
  job.tol = 1e-11;
  job.step = 0.125;
  job.method = sim::Method::dopri5;
  EXPECT_NE(section_chart(job, {}).title.find("dopri5, tol 1e-11"), std::string::npos);
  job.method = sim::Method::gauss4;
  EXPECT_NE(section_chart(job, {}).title.find("gauss4, step 0.125"), std::string::npos);
}

}  // namespace
}  // namespace epviz::section
