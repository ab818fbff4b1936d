// The line `epviz render` prints after a job: what was drawn, how fast, by
// which method and accuracy, and where to.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "job/job_plan.hpp"
#include "job/render_report.hpp"
#include "sim/run_spec.hpp"

namespace epviz::job {
namespace {

TEST(RenderSummary, NamesTheJobFramesSizeRateMethodAccuracyAndOutput) {
  const auto d = read_job(nlohmann::json{{"simulation", {{"case", "euler"}, {"method", "rk4"}}},
                                         {"width", 320},
                                         {"height", 240},
                                         {"output", {{"dir", "frames"}}}},
                          "jobs/euler.json");
  const RenderJob job{"jobs/euler.json", d.simulation, d.runs, d.scene, d.output};
  const auto plan = plan_job(job);
  EXPECT_EQ(render_summary(job, plan, {6, 0, 2.0, std::nullopt}),
            "jobs/euler.json: 6 frames 320x240 in 2.00 s (3.0 frames/s), rk4 " +
                plan.accuracy_note + ", " + std::string(sim::name(plan.run.formulation)) +
                " -> frames\n");
  // Nothing drawn (all skipped): no rate to divide by.
  EXPECT_NE(render_summary(job, plan, {0, 6, 0.0, std::nullopt}).find("(0.0 frames/s)"),
            std::string::npos);
}

}  // namespace
}  // namespace epviz::job
