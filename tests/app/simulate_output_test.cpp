// What `epviz simulate` writes: the CSV header and rows, the report's fields,
// and a numerical failure reported with time and method (exit code 3).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "support/cli.hpp"

namespace epviz {
namespace {

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::string f;
  std::stringstream in(line);
  while (std::getline(in, f, ',')) out.push_back(f);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

TEST(SimulateCsv, HeaderRowsAndInvariants) {
  test::TempDir dir;
  const auto r =
      test::run_epviz("simulate --case kovalevskaya --t-end 5 --samples 50 --tol 1e-11 --csv " +
                          (dir / "k.csv").string() + " --report-json " + (dir / "k.json").string(),
                      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = lines(test::slurp(dir / "k.csv"));
  ASSERT_EQ(rows.size(), 52u);
  EXPECT_EQ(rows[0],
            "t,omega1,omega2,omega3,gamma1,gamma2,gamma3,a,b,energy,area,gamma_norm_error,extra_"
            "integral");
  const auto first = fields(rows[1]), last = fields(rows.back());
  ASSERT_EQ(first.size(), 13u);
  ASSERT_EQ(last.size(), 13u);
  EXPECT_DOUBLE_EQ(std::stod(first[0]), 0.0);
  EXPECT_DOUBLE_EQ(std::stod(last[0]), 5.0);
  // a, b are the stereographic coordinates of gamma: gamma1 = -2a / (1 + a^2 + b^2).
  const double a = std::stod(last[7]), b = std::stod(last[8]);
  EXPECT_NEAR(std::stod(last[4]), -2 * a / (1 + a * a + b * b), 1e-12);
  EXPECT_NEAR(std::stod(last[6]), (1 - a * a - b * b) / (1 + a * a + b * b), 1e-12);
  // Energy and the Kovalevskaya integral are constant along the CSV.
  EXPECT_NEAR(std::stod(first[9]), std::stod(last[9]), 1e-8);
  EXPECT_NEAR(std::stod(first[12]), std::stod(last[12]), 1e-8);

  const auto report = nlohmann::json::parse(test::slurp(dir / "k.json"));
  for (const char* key :
       {"steps", "rhs_evals", "rejected_steps", "cpu_seconds", "max_relative_drift", "failure"})
    EXPECT_TRUE(report.contains(key)) << key;
  EXPECT_TRUE(report["failure"].is_null());
  EXPECT_GT(report["steps"].get<long>(), 0);
  EXPECT_GE(report["rhs_evals"].get<long>(),
            12 * report["steps"].get<long>());  // DOP853: 12 stages per step
  EXPECT_LT(report["max_relative_drift"]["extra_integral"].get<double>(), 1e-8);
}

TEST(SimulateCsv, GenericHasEmptyExtraIntegral) {
  test::TempDir dir;
  const auto r = test::run_epviz(
      "simulate --case generic --t-end 1 --samples 4 --csv " + (dir / "g.csv").string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = lines(test::slurp(dir / "g.csv"));
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(fields(rows[1]).back(), "");
}

TEST(SimulateCsv, AllCasesPrintsEveryPreset) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --case all --t-end 2", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* c :
       {"euler", "lagrange", "kovalevskaya", "goryachev-chaplygin", "hess", "generic"})
    EXPECT_NE(r.out.find(c), std::string::npos) << c;
}

TEST(SimulateFailure, ReportedWithTimeAndMethod) {
  // A steady rotation about axis 1 carries gamma through the south pole exactly
  // (b = tan(...) has a true pole): the north Riccati chart alone cannot follow it.
  test::TempDir dir;
  const auto [r, report] = test::run_with_report(
      "simulate --case euler --omega 1,0,0 --gamma 0,0.6,0.8 "
      "--formulation riccati --no-chart-switch --t-end 6 --csv " +
          (dir / "f.csv").string(),
      dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("dop853 failed at t = "), std::string::npos) << r.err;
  // The advice names what this user can change: the formulation or the chart switch.
  EXPECT_NE(r.err.find("; use --formulation spinor"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--no-chart-switch"), std::string::npos) << r.err;
  ASSERT_TRUE(report["failure"].is_object());
  EXPECT_EQ(report["failure"]["method"], "dop853");
  EXPECT_GT(report["failure"]["t"].get<double>(), 0.5);
  EXPECT_EQ(report["failure_kind"], "chart_pole");
  // The report carries the fact and the advice apart, and the line stderr showed.
  const auto message = report["failure"]["message"].get<std::string>();
  const std::string tail = report["failure"]["detail"].get<std::string>() + "; " +
                           report["failure"]["advice"].get<std::string>();
  ASSERT_GE(message.size(), tail.size());
  EXPECT_EQ(message.substr(message.size() - tail.size()), tail);
  EXPECT_NE(r.err.find("epviz: " + message + "\n"), std::string::npos) << r.err;
  // The samples written stop before the failure and are finite.
  for (const auto& row : lines(test::slurp(dir / "f.csv")))
    EXPECT_EQ(row.find("nan"), std::string::npos) << row;
}

TEST(SimulateFailure, ImplicitStepTooLargeAdvisesASmallerStep) {
  test::TempDir dir;
  const auto [r, report] = test::run_with_report(
      "simulate --case lagrange --omega 0,0,50 --method gauss4 --step 5 --t-end 10 --samples 2",
      dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("epviz: gauss4 failed at t = 0: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("; use a smaller --step"), std::string::npos) << r.err;
  EXPECT_EQ(report["failure_kind"], "solver_divergence");
  EXPECT_EQ(report["failure"]["method"], "gauss4");
}

TEST(SimulateReport, NoFailureKindWithoutAFailure) {
  test::TempDir dir;
  const auto [r, report] = test::run_with_report("simulate --case euler --t-end 1", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(report.contains("failure_kind"));
  EXPECT_TRUE(report["failure_kind"].is_null());
  EXPECT_TRUE(report["failure"].is_null());
}

TEST(Cases, ListsEveryPresetWithConditions) {
  test::TempDir dir;
  const auto r = test::run_epviz("cases --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto all = nlohmann::json::parse(r.out);
  ASSERT_EQ(all.size(), 6u);
  for (const auto& c : all) {
    EXPECT_FALSE(c["conditions"].get<std::string>().empty());
    EXPECT_EQ(c["inertia"].size(), 3u);
  }
}

}  // namespace
}  // namespace epviz
