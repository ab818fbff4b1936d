// No output may replace what the run reads: an output naming the command's
// own input (however spelled: another path, a symbolic or a hard link) is
// refused before any work with exit 2, naming both, and the input is left
// as it was.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"
#include "support/render_job.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

void expect_refused_and_kept(const test::CliResult& r, const fs::path& input,
                             const std::string& text, const std::string& option,
                             const std::string& input_name) {
  test::expect_bad_input(r, option);
  EXPECT_NE(r.err.find(input_name), std::string::npos) << r.err;
  EXPECT_EQ(test::slurp(input), text) << "the input was replaced";
}

TEST(OwnInput, SimulateCsvOrReportOnItsJobIsRefused) {
  test::TempDir dir;
  const std::string text = R"({"case": "euler", "t_end": 1})";
  const auto job = dir.write("j.json", text);
  fs::create_hard_link(job, dir / "hard.json");
  fs::create_symlink(job, dir / "soft.json");
  for (const auto& [option, path] : {std::pair{"--csv", job},
                                     {"--csv", dir / "soft.json"},
                                     {"--report-json", dir / "hard.json"},
                                     {"--report-json", dir.path() / "." / "j.json"}}) {
    SCOPED_TRACE(path.string());
    const auto r =
        test::run_epviz("simulate --job " + job.string() + " " + option + " " + path.string(), dir);
    expect_refused_and_kept(r, job, text, option, "--job");
  }
}

TEST(OwnInput, RenderReportOnItsJobIsRefused) {
  test::TempDir dir;
  const std::string text = test::small_render_job(dir / "frames", 2, 1.0).dump(2);
  const auto job = dir.write("J.json", text);
  fs::create_hard_link(job, dir / "hard.json");
  for (const auto& report : {job, dir / "hard.json"}) {
    const auto r =
        test::run_epviz("render " + job.string() + " --report-json " + report.string(), dir);
    expect_refused_and_kept(r, job, text, "--report-json", "the job");
    EXPECT_FALSE(fs::exists(dir / "frames")) << "frames rendered despite exit 2";
  }
}

std::string section_text(const std::string& csv, const std::string& picture_key = "",
                         const std::string& picture = "") {
  nlohmann::json j = {{"case", "generic"},
                      {"level", {{"energy", 2}, {"area", 1}}},
                      {"orbits", 2},
                      {"crossings", 5},
                      {"csv", csv}};
  if (!picture_key.empty()) j[picture_key] = picture;
  return j.dump();
}

TEST(OwnInput, SectionOutputsOnTheSectionFileAreRefused) {
  test::TempDir dir;
  const auto file = dir / "s.section.json";
  const std::string other = (dir / "c.csv").string();
  struct Case {
    std::string text, args, must_name;
  };
  for (const auto& c : {Case{section_text(other), " --out " + file.string(), "--out"},
                        Case{section_text(file.string()), "", "key 'csv'"},
                        Case{section_text(other, "png", file.string()), "", "key 'png'"},
                        Case{section_text(other, "svg", (dir / "." / "s.section.json").string()),
                             "", "key 'svg'"}}) {
    SCOPED_TRACE(c.must_name);
    std::ofstream(file) << c.text;
    const auto r = test::run_epviz("section " + file.string() + c.args, dir);
    expect_refused_and_kept(r, file, c.text, c.must_name, "the section file");
    EXPECT_FALSE(fs::exists(other)) << "work was done before the check";
  }
}

TEST(OwnInput, SweepOutOnTheSweepFileIsRefused) {
  test::TempDir dir;
  const std::string text = R"({"simulation": {"case": "euler", "t_end": 1},
      "axes": [{"field": "omega[0]", "from": 0.5, "to": 1, "count": 2}]})";
  const auto file = dir.write("m.sweep.json", text);
  const auto r = test::run_epviz("sweep " + file.string() + " --out " + file.string(), dir);
  expect_refused_and_kept(r, file, text, "--out", "the sweep file");
}

TEST(OwnInput, CheckJunitOnAJobOrAGoldenIsRefused) {
  test::TempDir dir;
  const std::string text = test::small_render_job(dir / "frames", 2, 1.0).dump(2);
  const auto job = dir.write("job.json", text);
  const auto golden = dir / "golden";
  const auto update =
      test::run_epviz("check " + job.string() + " --update --golden " + golden.string(), dir);
  ASSERT_EQ(update.exit_code, 0) << update.err;
  const auto r = test::run_epviz("check " + job.string() + " --junit " + job.string(), dir);
  expect_refused_and_kept(r, job, text, "--junit", "the job");

  fs::path frame;
  for (const auto& e : fs::directory_iterator(golden / "job"))
    if (e.path().extension() == ".png") frame = e.path();
  ASSERT_FALSE(frame.empty());
  const std::string png = test::slurp(frame);
  const auto g = test::run_epviz(
      "check " + job.string() + " --golden " + golden.string() + " --junit " + frame.string(), dir);
  expect_refused_and_kept(g, frame, png, "--junit", "a golden");
}

TEST(OwnInput, BenchJsonOnItsJobIsRefused) {
  test::TempDir dir;
  const std::string text = R"({"case": "euler", "t_end": 1})";
  const auto job = dir.write("j.json", text);
  const auto r =
      test::run_epviz("bench --quick --job " + job.string() + " --json " + job.string(), dir);
  expect_refused_and_kept(r, job, text, "--json", "--job");
}

}  // namespace
}  // namespace epviz
