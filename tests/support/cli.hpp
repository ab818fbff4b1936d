#pragma once
// Runs the built epviz binary and captures its exit code, stdout and stderr;
// and what every refused input must look like.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/temp_dir.hpp"

namespace epviz::test {

struct CliResult {
  int exit_code = -1;
  std::string out, err;
};

// `args` is appended to the binary path as shell words; stdin is /dev/null.
// The output is captured through two files in `dir`, removed afterwards.
// `wrapper` goes before the binary ("timeout 20" where a defect would hang).
inline CliResult run_epviz(const std::string& args, const TempDir& dir,
                           const std::string& wrapper = "") {
  const auto out = dir / ".stdout", err = dir / ".stderr";
  const std::string cmd = wrapper + " " + std::string(EPVIZ_BINARY) + " " + args + " >" +
                          out.string() + " 2>" + err.string() + " </dev/null";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// `args` run with " --report-json <dir>/report.json" added: the result and
// the report (null when none was written).
struct ReportedRun {
  CliResult result;
  nlohmann::json report;
};
inline ReportedRun run_with_report(const std::string& args, const TempDir& dir) {
  const auto file = dir / "report.json";
  ReportedRun r{run_epviz(args + " --report-json " + file.string(), dir), nullptr};
  if (std::filesystem::exists(file)) r.report = nlohmann::json::parse(slurp(file));
  return r;
}

inline std::size_t line_count(const std::string& text) {
  return std::size_t(std::count(text.begin(), text.end(), '\n'));
}

// Bad input is refused before any work: exit code 2, nothing on stdout, and
// one short line on stderr, "epviz: error: ...", that contains `must_name`
// (the option, or the file and key, and what is allowed).
inline void expect_bad_input(const CliResult& r, const std::string& must_name) {
  const std::string err = r.err.substr(0, 500);
  EXPECT_EQ(r.exit_code, 2) << err;
  EXPECT_EQ(line_count(r.err), 1u) << err;
  EXPECT_EQ(r.err.rfind("epviz: error: ", 0), 0u) << err;
  EXPECT_NE(r.err.find(must_name), std::string::npos) << "not named: " << must_name << "\n" << err;
  EXPECT_LT(r.err.size(), 600u) << err;
  EXPECT_TRUE(r.out.empty()) << "work was done before the check:\n" << r.out.substr(0, 500);
}

// A case of a table of refused command lines: its name (the test's), the
// arguments ("{dir}" stands for the test's directory, see TempDir::expand),
// what the message must name, and the text of {dir}/job.json where the case
// needs one.
struct RefusedCase {
  std::string name;
  std::string args;
  std::string must_name;
  std::string job = "";
};
inline void PrintTo(const RefusedCase& c, std::ostream* os) { *os << c.name; }

// INSTANTIATE_TEST_SUITE_P's test names for cases that carry their own.
inline constexpr auto case_name = [](const auto& param_info) { return param_info.param.name; };

// `epviz render <dir>/job.json <args>`, the job file holding `job` and
// drawing into `out`: refused as bad input naming `must_name`, with nothing drawn.
inline void expect_render_refused(const TempDir& dir, const std::string& job,
                                  const std::string& args, const std::filesystem::path& out,
                                  const std::string& must_name) {
  const auto file = dir.write("job.json", job);
  expect_bad_input(run_epviz("render " + file.string() + " " + args, dir), must_name);
  EXPECT_FALSE(std::filesystem::exists(out)) << "output written despite the error";
}

}  // namespace epviz::test
