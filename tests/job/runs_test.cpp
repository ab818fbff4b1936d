// A job's "runs" (comparison scenes): read strictly, written back so that
// what is written reads the same.
#include <gtest/gtest.h>

#include "io/json_reader.hpp"
#include "job/schema.hpp"

namespace epviz {
namespace {

nlohmann::json comparison_job() {
  return nlohmann::json::parse(R"({
    "simulation": {"case": "kovalevskaya", "t_end": 40, "method": "dop853", "tol": "auto"},
    "runs": [
      {"label": "reference"},
      {"label": "coarse", "method": "rk4", "step": 0.25},
      {"method": "dop853", "tol": 1e-6, "formulation": "spinor", "omega": [0.5, 0.3, 1.6]},
      {"tol": "auto", "method": "dopri5"}
    ]
  })");
}

std::string error_of(const nlohmann::json& j) {
  try {
    job::read_job(j, "job.json");
  } catch (const io::BadInput& e) {
    return e.what();
  }
  return "";
}

TEST(JobRuns, ReadsEachRunOverTheSimulation) {
  const auto d = job::read_job(comparison_job(), "job.json");
  ASSERT_EQ(d.runs.size(), 4u);
  EXPECT_EQ(d.runs[0].label, "reference");
  EXPECT_FALSE(d.runs[0].simulation.method);
  EXPECT_EQ(*d.runs[1].simulation.method, "rk4");
  EXPECT_EQ(*d.runs[1].simulation.step, 0.25);
  EXPECT_EQ(d.runs[1].simulation.step.origin, "job.json: key 'runs[1].step'");
  EXPECT_EQ(*d.runs[2].simulation.tol, 1e-6);
  EXPECT_EQ(*d.runs[2].simulation.formulation, "spinor");
  EXPECT_EQ((*d.runs[2].simulation.omega)[2], 1.6);
  EXPECT_FALSE(d.runs[2].auto_tolerance);
  EXPECT_TRUE(d.runs[3].auto_tolerance);
  EXPECT_TRUE(d.runs[3].label.empty());
}

TEST(JobRuns, WritesWhatItReads) {
  const auto d = job::read_job(comparison_job(), "job.json");
  const auto written = job::write_job(d);
  ASSERT_TRUE(written.contains("runs"));
  const auto again = job::read_job(nlohmann::json::parse(written.dump()), "again.json");
  EXPECT_EQ(nlohmann::json::parse(job::write_job(again).dump()),
            nlohmann::json::parse(written.dump()));
  ASSERT_EQ(again.runs.size(), d.runs.size());
  EXPECT_EQ(again.runs[1].label, "coarse");
  EXPECT_EQ(*again.runs[1].simulation.step, 0.25);
  EXPECT_TRUE(again.runs[3].auto_tolerance);
  // A job without runs writes none.
  auto single = comparison_job();
  single.erase("runs");
  EXPECT_FALSE(job::write_job(job::read_job(single, "job.json")).contains("runs"));
}

TEST(JobRuns, NamesAnUnknownKeyInARun) {
  auto j = comparison_job();
  j["runs"][1]["stepp"] = 0.1;
  EXPECT_NE(error_of(j).find("runs[1].stepp"), std::string::npos) << error_of(j);
}

TEST(JobRuns, RefusesWhatARunCannotHave) {
  auto j = comparison_job();
  j["runs"][2]["t_end"] = 10;
  EXPECT_NE(error_of(j).find("runs[2].t_end"), std::string::npos) << error_of(j);
  j = comparison_job();
  j["runs"][0]["step"] = -1;
  EXPECT_NE(error_of(j).find("runs[0].step"), std::string::npos) << error_of(j);
  for (const char* bad : {R"([])", R"({"method": "rk4"})", R"([1, 2])"}) {
    j = comparison_job();
    j["runs"] = nlohmann::json::parse(bad);
    EXPECT_NE(error_of(j).find("'runs'"), std::string::npos) << bad << ": " << error_of(j);
  }
  j = comparison_job();
  for (int i = 0; i < 4; ++i) j["runs"].push_back({{"label", "more"}});
  EXPECT_NE(error_of(j).find("1 to 6"), std::string::npos) << error_of(j);
}

TEST(JobRuns, AreListedAmongTheKeys) {
  bool found = false;
  for (const auto& k : job::render_job_keys()) found |= k.path == "runs";
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace epviz
