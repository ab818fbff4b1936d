// Every class of bad input: exit code 2, one line on stderr naming the option
// (or file and key) and what is allowed, and no output file left behind.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "physics/cases.hpp"
#include "support/cli.hpp"

namespace epviz {
namespace {

using Refused = test::RefusedCase;

class SimulateRejects : public ::testing::TestWithParam<Refused> {};

TEST_P(SimulateRejects, WithOneLineExitTwoAndNoFiles) {
  const auto& bad = GetParam();
  test::TempDir dir;
  if (!bad.job.empty()) std::ofstream(dir / "job.json") << bad.job;
  const auto before = dir.file_count();
  // The bad part comes last, so that options repeated there win (and a missing
  // value is really missing).
  const auto r =
      test::run_epviz("simulate --t-end 1 --csv " + (dir / "out.csv").string() + " --report-json " +
                          (dir / "report.json").string() + " " + dir.expand(bad.args),
                      dir);
  test::expect_bad_input(r, bad.must_name);
  EXPECT_EQ(dir.file_count(), before) << "a file was left behind";
}

INSTANTIATE_TEST_SUITE_P(
    AllClasses, SimulateRejects,
    ::testing::Values(
        Refused{"unknown_case", "--case kovalevsky",
                "--case: unknown case 'kovalevsky' (allowed: euler"},
        Refused{"malformed_vector", "--inertia 1,2,x", "--inertia: expected three comma-separated"},
        Refused{"short_vector", "--omega 1,2", "--omega: expected three"},
        Refused{"malformed_number", "--t-end abc", "--t-end: expected a finite number"},
        Refused{"negative_time", "--t-end -3", "--t-end: expected a positive number"},
        Refused{"fractional_samples", "--samples 1.5", "--samples: expected an integer"},
        Refused{"missing_value", "--inertia", "--inertia"},
        Refused{"unknown_option", "--inertial 1,2,3", "--inertial"},
        Refused{"unknown_method", "--method rk45", "--method: unknown method 'rk45' (allowed: rk4"},
        Refused{"unknown_formulation", "--formulation quaternion",
                "--formulation: unknown formulation"},
        Refused{"tol_with_fixed_step", "--method rk4 --tol 1e-8",
                "--tol: method rk4 has a fixed step"},
        Refused{"step_with_adaptive", "--method dop853 --step 0.01",
                "--step: method dop853 is adaptive"},
        Refused{"splitting_riccati", "--method splitting --formulation riccati",
                "needs formulation direct"},
        Refused{"chart_switch_direct", "--no-chart-switch",
                "chart switching applies only to formulation riccati"},
        Refused{"tolerance_range", "--tol 0.5",
                "--tol: expected a number from 1e-15 to 0.1, got '0.5'"},
        // The range holds wherever the tolerance is given, whatever the method.
        Refused{"job_tolerance_range", "--job {dir}/job.json",
                "job.json: key 'tol': expected a number from 1e-15 to 0.1, got the number 1e-16",
                R"({"case": "euler", "tol": 1e-16})"},
        Refused{"job_tolerance_range_fixed_step", "--job {dir}/job.json",
                "job.json: key 'tol': expected a number from 1e-15 to 0.1",
                R"({"case": "euler", "method": "rk4", "tol": 1e-16})"},
        Refused{"nonpositive_moment", "--inertia 1,-2,3", "--inertia"},
        Refused{"triangle_inequality", "--inertia 1,1,3", "triangle"},
        Refused{"non_unit_gamma", "--gamma 0,0,1.1", "--gamma"},
        // The checks a user may waive say how, in the words of where the value came from.
        Refused{"triangle_waiver_option", "--inertia 1,1,3",
                "; pass --allow-nonphysical to accept it"},
        Refused{"gamma_waiver_option", "--gamma 0,0,1.1", "; pass --normalize-gamma to rescale it"},
        Refused{"triangle_waiver_job_key", "--job {dir}/job.json",
                R"(; set "allow_nonphysical": true to accept it)", R"({"inertia": [1, 1, 3]})"},
        Refused{"broken_case_condition", "--case kovalevskaya --inertia 2,2,1.5",
                "--case: kovalevskaya"},
        Refused{"broken_initial_condition", "--case goryachev-chaplygin --omega 1,1,1",
                "goryachev-chaplygin"},
        Refused{"missing_output_dir", "--csv {dir}/no/such/out.csv", "does not exist"},
        Refused{"missing_job", "--job {dir}/nope.json", "nope.json: cannot open"},
        Refused{"invalid_json", "--job {dir}/job.json", "job.json:2:", "{\n  \"case\": euler\n}"},
        Refused{"unknown_job_key", "--job {dir}/job.json", "job.json: key 'tolerance': unknown key",
                R"({"case": "euler", "tolerance": 1e-9})"},
        Refused{"wrong_job_type", "--job {dir}/job.json",
                "job.json: key 'inertia': expected an array of 3 numbers",
                R"({"inertia": [1, 2]})"},
        Refused{"job_bad_case", "--job {dir}/job.json", "job.json: key 'case': unknown case",
                R"({"case": "top"})"}),
    test::case_name);

// What each waiver named in the messages above lets through.
TEST(Simulate, WaiversAcceptWhatTheyWaive) {
  test::TempDir dir;
  for (const std::string waived :
       {"--gamma 0,0,2 --normalize-gamma", "--inertia 1,1,3 --allow-nonphysical"}) {
    const auto r = test::run_epviz("simulate --t-end 1 " + waived, dir);
    EXPECT_EQ(r.exit_code, 0) << waived << ": " << r.err;
  }
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

namespace epviz {
namespace {

// A page's view is bounded by --max-view; the bound itself must be sane.
TEST(ServeRejects, AMaxViewThatIsNotASizeInRange) {
  test::TempDir dir;
  for (const auto& [value, must_name] : std::vector<std::pair<std::string, std::string>>{
           {"3840", "--max-view: expected WIDTHxHEIGHT"},
           {"20000x100", "--max-view: expected an integer from 16 to 16384"},
           {"640x8", "--max-view: expected an integer from 16 to 16384"},
           {"axb", "--max-view"}}) {
    SCOPED_TRACE(value);
    test::expect_bad_input(test::run_epviz("serve --port 0 --max-view " + value, dir, "timeout 20"),
                           must_name);
  }
}

}  // namespace
}  // namespace epviz
