// Every class of bad input: exit code 2, one line on stderr naming the option
// (or file and key) and what is allowed, and no output file left behind.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "cli_runner.hpp"
#include "physics/cases.hpp"

namespace epviz {
namespace {

struct BadInput {
  std::string name;
  std::string args;       // after "simulate"; {dir} is replaced by the temp dir
  std::string must_name;  // the message must contain this
  std::string job = "";   // optional job file content, written to {dir}/job.json
};

void PrintTo(const BadInput& b, std::ostream* os) { *os << b.name; }

class SimulateRejects : public ::testing::TestWithParam<BadInput> {};

std::string expand(std::string s, const std::string& dir) {
  for (std::size_t p; (p = s.find("{dir}")) != std::string::npos;) s.replace(p, 5, dir);
  return s;
}

TEST_P(SimulateRejects, WithOneLineExitTwoAndNoFiles) {
  const auto& bad = GetParam();
  test::TempDir dir;
  if (!bad.job.empty()) std::ofstream(dir / "job.json") << bad.job;
  const auto before = dir.file_count();
  // The bad part comes last, so that options repeated there win (and a missing
  // value is really missing).
  const auto r = test::run_epviz("simulate --t-end 1 --csv " + (dir / "out.csv").string() +
                                     " --report-json " + (dir / "report.json").string() + " " +
                                     expand(bad.args, dir.path().string()),
                                 dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(bad.must_name), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("epviz: error: ", 0), 0u) << r.err;
  EXPECT_EQ(dir.file_count(), before) << "a file was left behind";
}

INSTANTIATE_TEST_SUITE_P(
    AllClasses, SimulateRejects,
    ::testing::Values(
        BadInput{"unknown_case", "--case kovalevsky",
                 "--case: unknown case 'kovalevsky' (allowed: euler"},
        BadInput{"malformed_vector", "--inertia 1,2,x",
                 "--inertia: expected three comma-separated"},
        BadInput{"short_vector", "--omega 1,2", "--omega: expected three"},
        BadInput{"malformed_number", "--t-end abc", "--t-end: expected a finite number"},
        BadInput{"negative_time", "--t-end -3", "--t-end: expected a positive number"},
        BadInput{"fractional_samples", "--samples 1.5", "--samples: expected an integer"},
        BadInput{"missing_value", "--inertia", "--inertia"},
        BadInput{"unknown_option", "--inertial 1,2,3", "--inertial"},
        BadInput{"unknown_method", "--method rk45",
                 "--method: unknown method 'rk45' (allowed: rk4"},
        BadInput{"unknown_formulation", "--formulation quaternion",
                 "--formulation: unknown formulation"},
        BadInput{"tol_with_fixed_step", "--method rk4 --tol 1e-8",
                 "--tol: method rk4 has a fixed step"},
        BadInput{"step_with_adaptive", "--method dop853 --step 0.01",
                 "--step: method dop853 is adaptive"},
        BadInput{"splitting_riccati", "--method splitting --formulation riccati",
                 "needs formulation direct"},
        BadInput{"chart_switch_direct", "--no-chart-switch",
                 "chart switching applies only to formulation riccati"},
        BadInput{"tolerance_range", "--tol 0.5",
                 "--tol: expected a number from 1e-15 to 0.1, got '0.5'"},
        // The range holds wherever the tolerance is given, whatever the method.
        BadInput{"job_tolerance_range", "--job {dir}/job.json",
                 "job.json: key 'tol': expected a number from 1e-15 to 0.1, got the number 1e-16",
                 R"({"case": "euler", "tol": 1e-16})"},
        BadInput{"job_tolerance_range_fixed_step", "--job {dir}/job.json",
                 "job.json: key 'tol': expected a number from 1e-15 to 0.1",
                 R"({"case": "euler", "method": "rk4", "tol": 1e-16})"},
        BadInput{"nonpositive_moment", "--inertia 1,-2,3", "--inertia"},
        BadInput{"triangle_inequality", "--inertia 1,1,3", "triangle"},
        BadInput{"non_unit_gamma", "--gamma 0,0,1.1", "--gamma"},
        // The checks a user may waive say how, in the words of where the value came from.
        BadInput{"triangle_waiver_option", "--inertia 1,1,3",
                 "; pass --allow-nonphysical to accept it"},
        BadInput{"gamma_waiver_option", "--gamma 0,0,1.1",
                 "; pass --normalize-gamma to rescale it"},
        BadInput{"triangle_waiver_job_key", "--job {dir}/job.json",
                 R"(; set "allow_nonphysical": true to accept it)", R"({"inertia": [1, 1, 3]})"},
        BadInput{"broken_case_condition", "--case kovalevskaya --inertia 2,2,1.5",
                 "--case: kovalevskaya"},
        BadInput{"broken_initial_condition", "--case goryachev-chaplygin --omega 1,1,1",
                 "goryachev-chaplygin"},
        BadInput{"missing_output_dir", "--csv {dir}/no/such/out.csv", "does not exist"},
        BadInput{"missing_job", "--job {dir}/nope.json", "nope.json: cannot open"},
        BadInput{"invalid_json", "--job {dir}/job.json", "job.json:2:", "{\n  \"case\": euler\n}"},
        BadInput{"unknown_job_key", "--job {dir}/job.json",
                 "job.json: key 'tolerance': unknown key",
                 R"({"case": "euler", "tolerance": 1e-9})"},
        BadInput{"wrong_job_type", "--job {dir}/job.json",
                 "job.json: key 'inertia': expected an array of 3 numbers",
                 R"({"inertia": [1, 2]})"},
        BadInput{"job_bad_case", "--job {dir}/job.json", "job.json: key 'case': unknown case",
                 R"({"case": "top"})"}),
    [](const auto& param_info) { return param_info.param.name; });

TEST(Simulate, NormalizeGammaAcceptsANonUnitVector) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --gamma 0,0,2 --normalize-gamma --t-end 1", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(Simulate, AllowNonphysicalAcceptsTriangleBreakingMoments) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --inertia 1,1,3 --allow-nonphysical --t-end 1", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// The line of `option` in `help`, and the lines CLI11 wraps it onto, up to the next option.
std::string help_of(const std::string& help, const std::string& option) {
  const auto at = help.find("  " + option + " ");
  if (at == std::string::npos) return "";
  const auto next = help.find("\n  -", at + 1);
  std::string text = help.substr(at, next == std::string::npos ? std::string::npos : next - at);
  std::istringstream words(text);
  std::string word, joined;
  while (words >> word) joined += (joined.empty() ? "" : " ") + word;
  return joined;
}

TEST(SimulateHelp, CaseListsThePresetsByName) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --help", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string names;
  for (const auto& p : physics::case_presets()) names += (names.empty() ? "" : ", ") + p.name;
  const auto help = help_of(r.out, "--case");
  EXPECT_NE(help.find(": " + names + ", custom;"), std::string::npos) << help;
}

}  // namespace
}  // namespace epviz
