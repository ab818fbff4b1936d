// Hostile input to `epviz render` and `epviz simulate`: whatever a job file
// or an option holds, the answer is exit code 2 and one short line on stderr
// naming the file and key (or the option) and what is allowed, before any work.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <fstream>

#include "support/cli.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;
using Refused = test::RefusedCase;

// A small render job with `sim` as its simulation object and `extra` keys
// after it (text, so that it can hold what a JSON library would not write).
std::string render_job(const fs::path& out, const std::string& sim = R"({"case": "lagrange"})",
                       const std::string& extra = "") {
  return R"({"simulation": )" + sim + R"(, "width": 160, "height": 120, "fps": 2, )" +
         R"("duration": 1, "output": {"dir": ")" + out.string() + "\"}" + extra + "}";
}

std::string nested_arrays(int depth) {
  return std::string(std::size_t(depth), '[') + std::string(std::size_t(depth), ']');
}

// A render job drawing into {dir}/frames with `sim` as its "simulation" object
// and `extra` keys (each starting with ", ") after it.
Refused hostile_job(const std::string& name, const std::string& sim, const std::string& extra,
                    const std::string& must_name) {
  return {name, "--quiet", must_name, render_job("{dir}/frames", sim, extra)};
}

// A good job with hostile options.
Refused hostile_option(const std::string& name, const std::string& args,
                       const std::string& must_name) {
  return {name, "--quiet " + args, must_name, render_job("{dir}/frames")};
}

class RenderRefuses : public ::testing::TestWithParam<Refused> {};

TEST_P(RenderRefuses, WithOneLineAndExitTwoBeforeDrawing) {
  const auto& c = GetParam();
  test::TempDir dir;
  test::expect_render_refused(dir, dir.expand(c.job), c.args, dir / "frames", c.must_name);
}

const std::string lagrange = R"({"case": "lagrange"})";

INSTANTIATE_TEST_SUITE_P(
    Jobs, RenderRefuses,
    ::testing::Values(
        // A value nested 100,000 deep, where a string or a number belongs.
        hostile_job("deep_title", lagrange, R"(, "title": )" + nested_arrays(100'000),
                    "job.json: key 'title"),
        hostile_job("deep_azimuth", lagrange,
                    R"(, "camera": {"azimuth": )" + nested_arrays(100'000) + "}",
                    "job.json: key 'camera.azimuth"),
        hostile_job("deep_simulation_value",
                    R"({"case": "lagrange", "omega": )" + nested_arrays(100'000) + "}", "",
                    "job.json: key 'simulation.omega"),
        // A 10 MB string where a number belongs: quoted by its start only.
        hostile_job("huge_string", lagrange,
                    R"(, "camera": {"azimuth": ")" + std::string(10'000'000, 'x') + "\"}",
                    "job.json: key 'camera.azimuth': expected a number, got a string \"xxx"),
        // Newlines in keys and values are escaped, not printed.
        hostile_job("newline_in_key", lagrange, ", \"vi\\new\": \"body\"",
                    "job.json: key 'vi\\new': unknown key"),
        hostile_job("newline_in_choice", lagrange, R"(, "view": "top\nbottom")",
                    "key 'view': 'top\\nbottom' is not one of: body, space"),
        hostile_job("newline_in_colour", lagrange, R"(, "colours": {"body": "#12\n456"})",
                    "key 'colours.body': expected a colour \"#rrggbb\" or \"#rrggbbaa\", got "
                    "\"#12\\n456\""),
        hostile_job("newline_in_case", R"({"case": "lag\r\nrange"})", "",
                    "key 'simulation.case': unknown case 'lag\\r\\nrange'"),
        // Numbers out of range of a double, with the key.
        hostile_job("overflowing_t_end", R"({"case": "lagrange", "t_end": 1e400})", "",
                    "job.json: key 'simulation.t_end': the number 1e400 is out of range"),
        hostile_job("overflowing_negative", lagrange, R"(, "camera": {"azimuth": -1e999})",
                    "job.json: key 'camera.azimuth': the number -1e999 is out of range"),
        // Integers past 64 bits are quoted as written, not wrapped.
        hostile_job("uint64_samples", R"({"case": "lagrange", "samples": 18446744073709551615})",
                    "",
                    "key 'simulation.samples': expected an integer from 1 to 100000000, got the "
                    "integer 18446744073709551615"),
        hostile_job("duplicate_key", R"({"case": "lagrange", "case": "euler"})", "",
                    "job.json: key 'simulation.case': given twice"),
        hostile_job("duplicate_top_key", lagrange, R"(, "width": 320)",
                    "job.json: key 'width': given twice"),
        // Values the job format accepted but nothing could draw.
        hostile_job("huge_moment", R"({"inertia": [1, 1, 1e308], "allow_nonphysical": true})", "",
                    "job.json: key 'simulation.inertia': expected three numbers from 1e-6 to 1e6"),
        hostile_job("tiny_moment", R"({"inertia": [1e-300, 1e-300, 1e-300]})", "",
                    "job.json: key 'simulation.inertia': expected three numbers from 1e-6 to 1e6"),
        hostile_job("huge_com", R"({"case": "generic", "com": [1e300, 0, 0]})", "",
                    "job.json: key 'simulation.com': expected three numbers from -1e6 to 1e6"),
        hostile_job("tiny_plane_extent", lagrange, R"(, "plane": {"extent": 5e-324})",
                    "job.json: key 'plane.extent': expected a number from 0.01 to 1000, got the "
                    "number 5e-324"),
        hostile_job("huge_plane_extent", lagrange, R"(, "plane": {"extent": 1e300})",
                    "job.json: key 'plane.extent'"),
        hostile_job("far_camera", lagrange, R"(, "camera": {"distance": 1e300})",
                    "job.json: key 'camera.distance': expected at most 100 sphere radii"),
        hostile_job("huge_weight", R"({"case": "generic", "weight": 1e300})", "",
                    "job.json: key 'simulation.weight': expected a number from -1e6 to 1e6"),
        hostile_job("huge_omega", R"({"case": "generic", "omega": [1e300, 0, 0]})", "",
                    "job.json: key 'simulation.omega'")),
    test::case_name);

TEST(HostileJobFile, ADirectoryIsNotAJob) {
  test::TempDir dir;
  fs::create_directory(dir / "jobs");
  test::expect_bad_input(test::run_epviz("render " + (dir / "jobs").string(), dir),
                         "jobs: is a directory, not a job file");
  test::expect_bad_input(test::run_epviz("simulate --job " + (dir / "jobs").string(), dir),
                         "jobs: is a directory, not a job file");
}

TEST(HostileJobFile, DevZeroIsReadOnlyUpToTheLimit) {
  test::TempDir dir;
  const auto start = std::chrono::steady_clock::now();
  test::expect_bad_input(test::run_epviz("simulate --job /dev/zero", dir),
                         "/dev/zero: larger than 16 MiB, the limit for a job file");
  test::expect_bad_input(test::run_epviz("render /dev/zero", dir), "/dev/zero: larger than 16 MiB");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
}

TEST(HostileJobFile, AnEndlessPipeIsReadOnlyUpToTheLimit) {
  test::TempDir dir;
  const auto fifo = dir / "job.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A writer that never stops; it ends on SIGPIPE once epviz closes the pipe.
  ASSERT_EQ(std::system(("yes '{' > " + fifo.string() + " 2>/dev/null &").c_str()), 0);
  const auto r = test::run_epviz("simulate --job " + fifo.string(), dir);
  // Should epviz never have opened the pipe, opening it here lets the writer end.
  const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  if (fd >= 0) ::close(fd);
  test::expect_bad_input(r, "job.fifo: larger than 16 MiB");
}

TEST(HostileJobFile, AFileNameWithANewlineStaysOnOneLine) {
  test::TempDir dir;
  const auto job = dir.write("bad\nname.json", "{\"case\": 1}");
  test::expect_bad_input(test::run_epviz("simulate --job '" + job.string() + "'", dir),
                         "bad\\nname.json: key 'case': expected a string");
}

TEST(HostileJobFile, SimulateJobsNameKeysToo) {
  test::TempDir dir;
  const auto deep = dir.write("deep.json", R"({"t_end": )" + nested_arrays(100'000) + "}");
  test::expect_bad_input(test::run_epviz("simulate --job " + deep.string(), dir),
                         "deep.json: key 't_end");
  const auto big = dir.write("big.json", R"({"t_end": 1e400})");
  test::expect_bad_input(test::run_epviz("simulate --job " + big.string(), dir),
                         "big.json: key 't_end': the number 1e400 is out of range");
  const auto twice = dir.write("twice.json", R"({"t_end": 1, "t_end": 2})");
  test::expect_bad_input(test::run_epviz("simulate --job " + twice.string(), dir),
                         "twice.json: key 't_end': given twice");
  const auto samples = dir.write("samples.json", R"({"samples": 9223372036854775808})");
  test::expect_bad_input(test::run_epviz("simulate --job " + samples.string(), dir),
                         "got the integer 9223372036854775808");
}

// "custom" is what the overlay and the report call a body of one's own: as a
// case it means no case at all (the generic preset's values for what is not given).
TEST(HostileJobFile, CaseCustomIsABodyOfOnesOwn) {
  test::TempDir dir;
  const auto report = dir / "report.json";
  const auto job = dir.write("custom.json", R"({"case": "custom", "inertia": [2, 2.5, 3]})");
  auto r = test::run_epviz(
      "simulate --job " + job.string() + " --t-end 0.5 --report-json " + report.string(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(test::slurp(report).find("\"custom\""), std::string::npos) << test::slurp(report);
  r = test::run_epviz("simulate --case custom --t-end 0.5", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

class SimulateRefuses : public ::testing::TestWithParam<Refused> {};

TEST_P(SimulateRefuses, WithOneLineAndExitTwoAndNoFiles) {
  const auto& h = GetParam();
  test::TempDir dir;
  std::ofstream(dir / "target.csv") << "kept\n";
  fs::create_symlink(dir / "target.csv", dir / "link.csv");
  const auto before = dir.file_count();
  const auto r = test::run_epviz("simulate --t-end 0.5 " + dir.expand(h.args), dir);
  test::expect_bad_input(r, h.must_name);
  EXPECT_EQ(dir.file_count(), before) << "a file was left behind";
  EXPECT_EQ(test::slurp(dir / "target.csv"), "kept\n");
}

INSTANTIATE_TEST_SUITE_P(
    Options, SimulateRefuses,
    ::testing::Values(
        Refused{"empty_case", "--case ''", "--case"}, Refused{"empty_tol", "--tol ''", "--tol"},
        Refused{"empty_inertia", "--inertia ''", "--inertia"},
        Refused{"empty_csv", "--csv ''", "--csv"}, Refused{"empty_job", "--job ''", "--job"},
        Refused{"newline_in_case", "--case 'eu\nler'", "--case: unknown case 'eu\\nler'"},
        Refused{"newline_in_number", "--t-end '1\n2'",
                "--t-end: expected a finite number, got '1\\n2'"},
        Refused{"huge_samples", "--samples 99999999999999999999",
                "--samples: expected an integer from 1 to 100000000, got "
                "'99999999999999999999'"},
        Refused{"huge_moment", "--inertia 1,1,1e308 --allow-nonphysical", "--inertia"},
        Refused{"huge_omega", "--omega 1e300,0,0", "--omega"},
        Refused{"same_csv_and_report", "--csv {dir}/out.x --report-json {dir}/out.x",
                "is the same file as --csv"},
        Refused{"same_file_other_spelling", "--csv {dir}/out.x --report-json {dir}/./sub/../out.x",
                "is the same file as --csv"},
        Refused{"same_file_through_symlink", "--csv {dir}/target.csv --report-json {dir}/link.csv",
                "is the same file as --csv"}),
    test::case_name);

INSTANTIATE_TEST_SUITE_P(
    Options, RenderRefuses,
    ::testing::Values(hostile_option("empty_width", "--width ''", "--width"),
                      hostile_option("empty_out", "--out ''", "--out"),
                      hostile_option("empty_format", "--format ''", "--format"),
                      hostile_option("empty_frames", "--frames ''", "--frames")),
    test::case_name);

}  // namespace
}  // namespace epviz
