// `epviz render` and `epviz simulate` report the same two drifts of a run with
// the same settings: "step_drift" at the integrator's steps and
// "max_relative_drift" over the samples drawn or written. The output times
// here fall between the steps (fixed step 0.1, samples every 0.07) or come
// from dense output (dop853 at a loose tolerance), where the two differ.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

// 14 frames (5 per second for 2.8 s) draw (14 - 1) * 8 samples
// (scene::ScenePlan): 104 over 7.28 time units, one every 0.07. Only the last
// frame is written; the frames before it are integrated through all the same.
constexpr int kLastFrame = 13;
constexpr int kSamples = 104;
constexpr double kTEnd = 7.28;

struct Settings {
  std::string method;
  double accuracy;  // the step of a fixed-step method, the tolerance of an adaptive one
  bool fixed() const { return method == "midpoint"; }
};

struct Reports {
  nlohmann::json render, simulate;  // render's first run, simulate's one run
};

Reports run_both(const Settings& s, const test::TempDir& dir) {
  nlohmann::json sim = {{"case", "kovalevskaya"}, {"t_end", kTEnd}, {"method", s.method}};
  sim[s.fixed() ? "step" : "tol"] = s.accuracy;
  const nlohmann::json job = {
      {"simulation", sim}, {"width", 160},
      {"height", 120},     {"fps", 5},
      {"duration", 2.8},   {"output", {{"dir", (dir / "frames").string()}, {"format", "png"}}}};
  std::ofstream(dir / "job.json") << job.dump();
  auto r = test::run_epviz("render " + (dir / "job.json").string() + " --frames " +
                               std::to_string(kLastFrame) + " --quiet --report-json " +
                               (dir / "render.json").string(),
                           dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  char args[256];
  std::snprintf(args, sizeof args,
                "simulate --case kovalevskaya --method %s --%s %.17g --t-end %.17g --samples %d "
                "--report-json %s",
                s.method.c_str(), s.fixed() ? "step" : "tol", s.accuracy, kTEnd, kSamples,
                (dir / "simulate.json").c_str());
  r = test::run_epviz(args, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // Both figures are in simulate's text too, under the report's names.
  EXPECT_NE(r.out.find("max relative drift"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("step drift"), std::string::npos) << r.out;
  Reports out;
  out.render = nlohmann::json::parse(test::slurp(dir / "render.json"))["runs"][0];
  out.simulate = nlohmann::json::parse(test::slurp(dir / "simulate.json"));
  return out;
}

// The same run (same steps, same output times) in both: the same numbers.
void expect_same_drifts(const Reports& r) {
  ASSERT_EQ(r.render["formulation"], r.simulate["formulation"]);
  ASSERT_EQ(r.render["steps"], r.simulate["steps"]);
  for (const char* figure : {"step_drift", "max_relative_drift"})
    for (const char* k : {"gamma_norm2", "area", "energy", "extra_integral"}) {
      ASSERT_TRUE(r.render[figure][k].is_number()) << figure << " " << k << r.render.dump(2);
      ASSERT_TRUE(r.simulate[figure][k].is_number()) << figure << " " << k;
      EXPECT_EQ(r.render[figure][k].get<double>(), r.simulate[figure][k].get<double>())
          << figure << " " << k;
    }
}

TEST(DriftAgreement, MidpointBetweenItsSteps) {
  test::TempDir dir;
  const auto r = run_both({"midpoint", 0.1}, dir);
  expect_same_drifts(r);
  // Implicit midpoint keeps every quadratic invariant (|gamma|^2, C0, C1) at
  // its steps, to round-off and the solver's tolerance; the cubic drawn
  // between two steps does not keep them.
  for (const auto* report : {&r.render, &r.simulate})
    for (const char* k : {"gamma_norm2", "area", "energy"}) {
      EXPECT_LT((*report)["step_drift"][k].get<double>(), 1e-12) << k;
      EXPECT_GT((*report)["max_relative_drift"][k].get<double>(), 1e-9) << k;
    }
}

TEST(DriftAgreement, Dop853ByDenseOutput) {
  test::TempDir dir;
  const auto r = run_both({"dop853", 1e-5}, dir);
  expect_same_drifts(r);
  // Dense output between the steps is a different approximation from the
  // steps': the two figures are two facts.
  EXPECT_NE(r.simulate["step_drift"]["area"], r.simulate["max_relative_drift"]["area"]);
}

}  // namespace
}  // namespace epviz
