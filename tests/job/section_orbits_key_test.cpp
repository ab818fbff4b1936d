// A render job's "section": "orbits": further orbits (the live panel's
// clicked ones) read, written back, refused with one line naming the key when
// bad, and drawn by a render: the panel's list of each is the crossings that
// sim::section_crossings finds for the same start on its own steps.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "job/job_plan.hpp"
#include "job/schema.hpp"
#include "scene/frame_source.hpp"
#include "section_refusal.hpp"
#include "sim/section.hpp"
#include "support/cli.hpp"

namespace epviz {
namespace {

using test::TempDir;

// A state on gamma3 = 0 crossing it upward (gamma1 Omega2 - gamma2 Omega1 > 0).
const nlohmann::json kOrbit = {{"omega", {-0.4, 0.9, 0.3}}, {"gamma", {0.6, 0.8, 0.0}}};

nlohmann::json job_with(const nlohmann::json& section) {
  return {{"simulation",
           {{"case", "kovalevskaya"},
            {"t_end", 60},
            {"method", "dop853"},
            {"tol", 1e-10},
            {"omega", {1.0, 0.8, 0.6}},
            {"gamma", {0.6, 0.0, 0.8}}}},
          {"section", section},
          {"width", 320},
          {"height", 180},
          {"fps", 10},
          {"duration", 2}};
}

TEST(SectionOrbitsKey, ReadAndWrittenBack) {
  const auto d = job::read_job(job_with({{"orbits", {kOrbit}}}), "job.json");
  ASSERT_TRUE(d.scene.section);
  ASSERT_EQ(d.scene.section->orbits.size(), 1u);
  EXPECT_EQ(d.scene.section->orbits[0].omega, Eigen::Vector3d(-0.4, 0.9, 0.3));
  EXPECT_EQ(d.scene.section->orbits[0].gamma, Eigen::Vector3d(0.6, 0.8, 0.0));
  const auto written = job::write_job(d);
  ASSERT_EQ(written["section"]["orbits"].size(), 1u);
  EXPECT_EQ(written["section"]["orbits"][0]["omega"][1], 0.9);
  // Without orbits the key is left out.
  const auto plain = job::write_job(job::read_job(job_with(nlohmann::json::object()), "job.json"));
  EXPECT_FALSE(plain["section"].contains("orbits"));
}

TEST(SectionOrbitsKey, BadOrbitsExitTwoNamingTheKey) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"orbits": 3})", "key 'section.orbits'"},
      {R"({"orbits": [3]})", "key 'section.orbits'"},
      {R"({"orbits": [{"omega": [0, 1, 0]}]})", "needs both"},
      {R"({"orbits": [{"omega": [0, 1, 0], "gamma": [0.6, 0.8, 0], "t": 1}]})",
       "section.orbits[0]"},
      {R"({"orbits": [{"omega": [0, 1, 0], "gamma": [0.6, 0.9, 0]}]})", "gamma"},
      {R"({"orbits": [{"omega": [0, 1, 0], "gamma": [0.6, 0, 0.8]}]})", "on the surface"},
      {R"({"orbits": [{"omega":[0,1,0],"gamma":[1,0,0]},{"omega":[0,1,0],"gamma":[1,0,0]},
          {"omega":[0,1,0],"gamma":[1,0,0]},{"omega":[0,1,0],"gamma":[1,0,0]},
          {"omega":[0,1,0],"gamma":[1,0,0]},{"omega":[0,1,0],"gamma":[1,0,0]},
          {"omega":[0,1,0],"gamma":[1,0,0]},{"omega":[0,1,0],"gamma":[1,0,0]},
          {"omega":[0,1,0],"gamma":[1,0,0]}]})",
       "up to 8"},
  };
  for (const auto& [section, named] : cases) test::expect_section_refused(section, named);
}

TEST(SectionOrbitsKey, ARenderDrawsEachOrbitsCrossingsInItsOwnColour) {
  const auto d = job::read_job(job_with({{"orbits", {kOrbit}}}), "job.json");
  const job::RenderJob job{"job.json", d.simulation, d.runs, d.scene, d.output};
  const auto plan = job::plan_job(job);
  scene::FrameSource source(plan, job.scene);
  const scene::Frame last = source.frame(source.frame_count() - 1);
  ASSERT_TRUE(last.section);
  ASSERT_EQ(last.section->runs.size(), 2u);
  EXPECT_NE(last.section->colours[1], last.section->colours[0]);
  // The oracle: the section code's own integration of the same start.
  sim::RunSpec spec = plan.run;
  spec.initial = d.scene.section->orbits[0];
  const auto expected = sim::section_crossings(spec, d.scene.section->surface, 1000000);
  const auto& dots = last.section->runs[1];
  // The start first (it lies on the surface), then every crossing after it.
  ASSERT_EQ(dots.size(), expected.size() + 1);
  ASSERT_GT(expected.size(), 5u);
  EXPECT_EQ(dots[0], Eigen::Vector2d(0.6, 0.3));
  for (std::size_t k = 0; k < expected.size(); ++k) {
    SCOPED_TRACE(k);
    EXPECT_NEAR(dots[k + 1].x(), expected[k].gamma.x(), 1e-9);
    EXPECT_NEAR(dots[k + 1].y(), expected[k].omega.z(), 1e-9);
  }
}

}  // namespace
}  // namespace epviz
