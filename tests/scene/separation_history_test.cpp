// The separation chart's history: bounded however long the run, and thinned
// without hiding the largest or the smallest separation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "physics/cases.hpp"
#include "scene/frame_source.hpp"
#include "scene/separation_history.hpp"
#include "sim/simulate.hpp"

namespace epviz {
namespace {

using scene::SeparationHistory;

float largest(const std::vector<Eigen::Vector2f>& points) {
  float m = -1.0f;
  for (const auto& p : points) m = std::max(m, p.y());
  return m;
}

TEST(SeparationHistory, KeepsEverySampleWhileThereAreFew) {
  SeparationHistory h;
  for (std::size_t i = 0; i < SeparationHistory::kBuckets; ++i)
    h.add(float(i) * 0.5f, std::sin(float(i)));
  const auto pts = h.points();
  ASSERT_EQ(pts.size(), SeparationHistory::kBuckets);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_EQ(pts[i].x(), float(i) * 0.5f);
    EXPECT_EQ(pts[i].y(), std::sin(float(i)));
  }
}

TEST(SeparationHistory, StaysBoundedAndShowsEverySpikeAndDipAtItsTime) {
  // A slowly growing, wavering separation with spikes and dips, each a single
  // sample, among a million: a thousand samples to a pixel of a wide chart.
  // They lie at times that fall in the earlier and in the later of the two
  // stretches merged, merge after merge.
  const long n = 1'000'003;
  const std::vector<std::pair<long, float>> spikes{
      {3'001, 0.5f}, {77'777, 0.6f}, {523'457, 0.75f}, {999'000, 0.4f}};
  const std::vector<std::pair<long, float>> dips{{91'001, 1e-12f}, {412'345, 1e-11f}};
  SeparationHistory h;
  std::size_t most_points = 0;
  for (long i = 0; i < n; ++i) {
    float s = 1e-6f * (1.0f + float(i) * 1e-4f) * (1.0f + 0.5f * std::sin(float(i) * 0.01f));
    for (const auto& [at, value] : spikes)
      if (i == at) s = value;
    for (const auto& [at, value] : dips)
      if (i == at) s = value;
    h.add(float(i) * 0.01f, s);
    ASSERT_LE(h.buckets(), SeparationHistory::kBuckets) << "after " << i + 1 << " samples";
    if (i % 4099 == 0 || i == n - 1) most_points = std::max(most_points, h.points().size());
  }
  EXPECT_EQ(h.samples(), n);
  EXPECT_GT(h.stride(), 512);  // merged many times over
  EXPECT_LE(most_points, SeparationHistory::kMaxPoints);

  const auto pts = h.points();
  EXPECT_GT(pts.size(), SeparationHistory::kBuckets);
  EXPECT_LE(pts.size(), SeparationHistory::kMaxPoints);
  for (std::size_t i = 1; i < pts.size(); ++i) ASSERT_LT(pts[i - 1].x(), pts[i].x()) << i;
  auto shown = [&](long at, float value) {
    return std::any_of(pts.begin(), pts.end(), [&](const Eigen::Vector2f& p) {
      return p.x() == float(at) * 0.01f && p.y() == value;
    });
  };
  for (const auto& [at, value] : spikes) EXPECT_TRUE(shown(at, value)) << "spike at " << at;
  for (const auto& [at, value] : dips) EXPECT_TRUE(shown(at, value)) << "dip at " << at;
  EXPECT_EQ(largest(pts), 0.75f);
  // The chart still spans the run: to within a stretch of its first and its last sample.
  EXPECT_LT(pts.front().x(), float(h.stride()) * 0.01f);
  EXPECT_GT(pts.back().x(), float(n - 1 - h.stride()) * 0.01f);
}

TEST(SeparationHistory, ASeparationThatIsNotANumberIsNeverThinnedAway) {
  SeparationHistory h;
  for (int i = 0; i < 100'000; ++i) h.add(float(i), i == 777 ? NAN : 1e-3f);
  const auto pts = h.points();
  EXPECT_TRUE(std::any_of(pts.begin(), pts.end(), [](const auto& p) { return std::isnan(p.y()); }));
}

// A render's comparison: every frame carries at most the chart's points,
// however many samples the runs have, and the largest separation of the
// runs (found here from the two runs simulated on their own) is among them.
TEST(SeparationHistory, AComparisonRenderCopiesABoundedChartIntoEachFrame) {
  scene::SceneSettings s;
  s.width = 640, s.height = 360, s.fps = 10, s.duration = 60;
  const auto ref = sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853,
                                   sim::Formulation::direct, 30.0, 1);
  auto coarse = sim::preset_run(physics::Case::kovalevskaya, sim::Method::rk4,
                                sim::Formulation::direct, 30.0, 1);
  coarse.step = 0.25;
  const auto plan = scene::plan_scene({{ref, "a", false, true}, {coarse, "b", false, true}}, s);
  ASSERT_GT(long(plan.run.samples), 2 * long(SeparationHistory::kMaxPoints));

  scene::FrameSource src(plan, s);
  for (int i = 0; i < src.frame_count(); i += 37) {
    const auto f = src.frame(i);
    ASSERT_TRUE(f.comparison);
    EXPECT_LE(f.comparison->others[0].separation.size(), SeparationHistory::kMaxPoints);
  }
  const auto f = src.frame(src.frame_count() - 1);
  const auto& shown = f.comparison->others[0].separation;
  EXPECT_GT(shown.size(), SeparationHistory::kBuckets);
  EXPECT_LE(shown.size(), SeparationHistory::kMaxPoints);

  const auto a = sim::simulate(plan.run), b = sim::simulate(plan.others[0].run);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  ASSERT_GT(a.samples.size(), 2 * SeparationHistory::kMaxPoints);
  float truth = 0.0f;
  for (std::size_t i = 1; i < a.samples.size(); ++i)
    truth = std::max(truth, float((a.samples[i].gamma - b.samples[i].gamma).norm()));
  ASSERT_GT(truth, 1e-3f);  // the runs part: a largest worth showing
  EXPECT_NEAR(largest(shown), truth, 1e-5f * truth);
}

}  // namespace
}  // namespace epviz
