// The shipped job render_jobs/compare_formulations.json shows what its title
// says: the motion goes through the south pole, where the Riccati
// coordinates (a, b) are infinite. The direct, spinor and Riccati-with-chart-
// switch runs agree there to the picture's accuracy, and a Riccati run
// without the switch fails at the pole (a render stops with exit 3,
// chart_pole). The job's numbers are read from the file itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "numerics/failure.hpp"
#include "scene/frame_source.hpp"

namespace epviz {
namespace {

Eigen::Vector3d vec3(const nlohmann::json& j) {
  return Eigen::Vector3d(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>());
}

struct FormulationsJob {
  nlohmann::json file;
  sim::RunSpec base;
  scene::SceneSettings settings;
};

FormulationsJob load() {
  std::ifstream in(std::string(EPVIZ_SOURCE_DIR) + "/render_jobs/compare_formulations.json");
  FormulationsJob job;
  job.file = nlohmann::json::parse(in);
  const auto& s = job.file.at("simulation");
  auto& r = job.base;
  r.case_id = physics::Case::custom;
  r.body = {vec3(s.at("inertia")), vec3(s.at("com")), s.at("weight").get<double>()};
  r.initial = {vec3(s.at("omega")), vec3(s.at("gamma"))};
  r.t_end = s.at("t_end");
  r.method = sim::Method::dop853;
  job.settings.width = job.file.at("width");
  job.settings.height = job.file.at("height");
  job.settings.fps = job.file.at("fps");
  job.settings.duration = job.file.at("duration");
  return job;
}

sim::RunSpec in(const sim::RunSpec& base, sim::Formulation f, bool chart_switch = true) {
  sim::RunSpec r = base;
  r.formulation = f;
  r.chart_switch = chart_switch;
  return r;
}

TEST(FormulationsJob, GoesThroughTheSouthPoleWhereTheThreeFormulationsAgree) {
  const auto job = load();
  ASSERT_EQ(job.file.at("runs").size(), 3u);
  const auto plan =
      scene::plan_scene({{in(job.base, sim::Formulation::direct), "direct", true, true},
                         {in(job.base, sim::Formulation::riccati), "riccati", true, true},
                         {in(job.base, sim::Formulation::spinor), "spinor", true, true}},
                        job.settings);
  scene::FrameSource src(plan, job.settings);
  const auto last = src.frame(src.frame_count() - 1);
  ASSERT_TRUE(last.comparison);
  // Each run's trail (the whole run) passes through the pole S on the sphere:
  // within a thousandth of the radius, a third of a pixel.
  auto nearest_to_pole = [](const std::vector<scene::TrailPoint>& trail) {
    const Eigen::Vector3f s(0, 0, -1);
    float nearest = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i + 1 < trail.size(); ++i) {
      const Eigen::Vector3f a = trail[i].p, d = trail[i + 1].p - a;
      const float u =
          d.squaredNorm() > 0 ? std::clamp((s - a).dot(d) / d.squaredNorm(), 0.f, 1.f) : 0.f;
      nearest = std::min(nearest, (a + u * d - s).norm());
    }
    return nearest;
  };
  EXPECT_LT(nearest_to_pole(last.trail), 1e-3f);
  for (const auto& run : last.comparison->others) EXPECT_LT(nearest_to_pole(run.trail), 1e-3f);
  // And (a, b) passes through infinity in each run.
  auto through = [](const std::vector<scene::PlaneMark>& marks) {
    return std::count_if(marks.begin(), marks.end(), [](const scene::PlaneMark& m) {
      return m.kind == scene::PlaneMark::Kind::through_infinity;
    });
  };
  EXPECT_GE(through(last.plane_marks), 1);
  for (const auto& run : last.comparison->others) EXPECT_GE(through(run.plane_marks), 1);
  // They agree to within half a pixel of the sphere all the way.
  const double half_pixel = 0.5 / plan.layout.sphere_px_per_unit;
  for (const auto& run : last.comparison->others) {
    ASSERT_FALSE(run.separation.empty());
    for (const auto& p : run.separation) EXPECT_LT(p.y(), half_pixel) << "at t = " << p.x();
  }
}

// Without the switch, a pole is reported only once |(a, b)| > 1e6, within
// 2e-6 of the pole in angle: the failure shows that the motion goes through it.
TEST(FormulationsJob, ARiccatiRunWithoutTheChartSwitchFailsAtThePole) {
  const auto job = load();
  const auto plan =
      scene::plan_scene({{in(job.base, sim::Formulation::direct), "direct", true, true},
                         {in(job.base, sim::Formulation::riccati, false), "no switch", true, true}},
                        job.settings);
  scene::FrameSource src(plan, job.settings);
  try {
    for (int frame = 0; frame < src.frame_count(); ++frame) src.frame(frame);
    FAIL() << "the run without chart switch went through the pole";
  } catch (const numerics::IntegrationError& e) {
    EXPECT_EQ(e.failure().kind, numerics::FailureKind::chart_pole) << e.what();
  }
}

}  // namespace
}  // namespace epviz
