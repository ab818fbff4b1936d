// `epviz bench --job`: the study runs on the job's body, initial state and
// final time, the peers with it, and it ends with a recommendation whose
// numbers the JSON itself confirms; --json may name a file in the --out
// folder that the run makes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace epviz {
namespace {

using test::run_epviz;
using test::TempDir;

// The body of a comparison figure of one's own (inertia 3, 2, 1.2; centre of
// mass 0.3, 0.1, 0.5), to t = 30.
constexpr const char* kRenderJob = R"({"simulation": {"inertia": [3, 2, 1.2],
    "com": [0.3, 0.1, 0.5], "omega": [0.4, -0.8, 1.1], "gamma": [0, 0.6, 0.8],
    "t_end": 30, "method": "rk4", "step": 0.2}})";

TEST(BenchJob, RecommendsAMethodForTheJobWithItsEvidence) {
  TempDir dir;
  std::ofstream(dir / "mine.json") << kRenderJob;
  const auto json_path = dir / "bench.json";
  const auto r = run_epviz("bench --quick --target-error 1e-7 --job " +
                               (dir / "mine.json").string() + " --json " + json_path.string(),
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(test::slurp(json_path));

  // Every work-precision row, epviz's and the peers', runs to the job's t_end.
  std::map<std::string, int> by_impl;
  for (const auto& row : doc.at("rows")) {
    if (row.at("study") != "work_precision") continue;
    EXPECT_EQ(row.at("case"), "custom") << row.dump();
    EXPECT_EQ(row.at("t_end").get<double>(), 30.0) << row.dump();
    ++by_impl[row.at("impl").get<std::string>()];
  }
  EXPECT_GT(by_impl["epviz"], 10);
  EXPECT_GT(by_impl["boost-odeint"], 0) << "no peer ran on the job";

  // The recommendation: within the target by the JSON's own numbers, one of
  // the rows, and no epviz run meeting the target took less CPU time.
  ASSERT_TRUE(doc.contains("recommendation")) << doc.dump().substr(0, 400);
  const auto& rec = doc.at("recommendation");
  EXPECT_EQ(rec.at("t_end").get<double>(), 30.0);
  const double target = rec.at("target_error").get<double>();
  EXPECT_EQ(target, 1e-7);
  ASSERT_TRUE(rec.at("met").get<bool>()) << rec.dump();
  const auto& choice = rec.at("choice");
  const double error = choice.at("error").get<double>();
  const double cpu = choice.at("cpu_ms").get<double>();
  EXPECT_LE(error, target);
  EXPECT_GE(choice.at("drift").get<double>(), 0.0);
  EXPECT_GT(choice.at("drift_steps").get<int>(), 0);
  int same = 0;
  for (const auto& row : doc.at("rows")) {
    if (row.at("study") != "work_precision" || row.at("impl") != "epviz" ||
        row.at("status") != "ok")
      continue;
    if (row.at("error").get<double>() <= target) {
      EXPECT_GE(row.at("cpu_ms").get<double>(), cpu);
    }
    same += row.at("method") == choice.at("method") &&
            row.at("formulation") == choice.at("formulation") &&
            row.at("error").get<double>() == error;
  }
  EXPECT_EQ(same, 1) << choice.dump();
  const auto& peer = rec.at("fastest_peer");
  if (!peer.is_null()) {
    EXPECT_LE(peer.at("error").get<double>(), target);
  }

  // The same paragraph on stdout as in the JSON.
  const std::string text = rec.at("text");
  EXPECT_NE(r.out.find(text), std::string::npos) << r.out.substr(r.out.size() - 600);
  EXPECT_NE(text.find(choice.at("method").get<std::string>()), std::string::npos) << text;
}

// A simulate job (its fields at the top level) gives the body and t_end too.
TEST(BenchJob, SimulateJobGivesItsFinalTime) {
  TempDir dir;
  std::ofstream(dir / "sim.json") << R"({"inertia": [1, 1.7, 2.3], "com": [0.2, -0.1, 0.4],
      "omega": [0.5, 1.2, -0.3], "gamma": [0, 0.6, 0.8], "t_end": 4})";
  const auto json_path = dir / "bench.json";
  const auto r = run_epviz(
      "bench --quick --job " + (dir / "sim.json").string() + " --json " + json_path.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(test::slurp(json_path));
  int rows = 0;
  for (const auto& row : doc.at("rows"))
    if (row.at("study") == "work_precision") {
      EXPECT_EQ(row.at("t_end").get<double>(), 4.0) << row.dump();
      ++rows;
    }
  EXPECT_GT(rows, 10);
  EXPECT_EQ(doc.at("recommendation").at("t_end").get<double>(), 4.0);
}

// --json in the folder --out makes: the folder is made first.
TEST(BenchJob, JsonInTheOutFolderThatIsMade) {
  TempDir dir;
  std::ofstream(dir / "sim.json") << R"({"case": "euler", "t_end": 2})";
  const auto out = dir / "out";
  const auto r =
      run_epviz("bench --quick --job " + (dir / "sim.json").string() + " --json " +
                    (out / "x.json").string() + " --out " + out.string() + " --format svg",
                dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(std::filesystem::exists(out / "x.json"));
  EXPECT_EQ(test::slurp(out / "x.json"), test::slurp(out / "bench.json"));
  // Elsewhere a missing folder is still refused, and nothing is made.
  const auto other =
      run_epviz("bench --quick --job " + (dir / "sim.json").string() + " --json " +
                    (dir / "elsewhere/x.json").string() + " --out " + (dir / "out2").string(),
                dir);
  expect_bad_input(other, "--json");
  EXPECT_FALSE(std::filesystem::exists(dir / "out2"));
}

TEST(BenchJob, TargetErrorMistakesAreUsageErrors) {
  TempDir dir;
  std::ofstream(dir / "sim.json") << R"({"case": "euler", "t_end": 2})";
  const std::string job = " --job " + (dir / "sim.json").string();
  expect_bad_input(run_epviz("bench --quick --target-error 1e-8", dir), "--target-error");
  expect_bad_input(run_epviz("bench --quick --target-error 0" + job, dir), "--target-error");
  expect_bad_input(run_epviz("bench --quick --target-error 1e-20" + job, dir), "--target-error");
  expect_bad_input(run_epviz("bench --quick --target-error tiny" + job, dir), "--target-error");
  EXPECT_EQ(dir.file_count(), 1u);  // only the job: nothing written
}

}  // namespace
}  // namespace epviz
