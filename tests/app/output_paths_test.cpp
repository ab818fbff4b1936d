// Every output path is checked before any work: exit 2, one line naming the
// option (or file and key), nothing written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"
#include "support/render_job.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

TEST(SimulateOutputPaths, ReportJsonDirectoryIsRefusedBeforeWork) {
  test::TempDir dir;
  fs::create_directories(dir / "reports");
  const auto r = test::run_epviz("simulate --case euler --csv " + (dir / "s.csv").string() +
                                     " --report-json " + (dir / "reports").string(),
                                 dir);
  test::expect_bad_input(r, "--report-json");
  EXPECT_FALSE(fs::exists(dir / "s.csv")) << "the CSV was written despite exit 2";
}

TEST(SimulateOutputPaths, CsvDirectoryIsRefused) {
  test::TempDir dir;
  fs::create_directories(dir / "out");
  test::expect_bad_input(
      test::run_epviz("simulate --case euler --csv " + (dir / "out").string(), dir), "--csv");
  test::expect_bad_input(
      test::run_epviz("simulate --case euler --csv " + (dir / "x/").string(), dir), "--csv");
}

TEST(SimulateOutputPaths, CsvInMissingDirectoryIsRefused) {
  test::TempDir dir;
  test::expect_bad_input(
      test::run_epviz("simulate --case euler --csv " + (dir / "no" / "s.csv").string(), dir),
      "--csv");
}

TEST(SimulateOutputPaths, UnwritableDirectoryIsRefused) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write anywhere";
  test::TempDir dir;
  fs::create_directories(dir / "ro");
  fs::permissions(dir / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  const auto r = test::run_epviz(
      "simulate --case euler --report-json " + (dir / "ro" / "r.json").string(), dir);
  fs::permissions(dir / "ro", fs::perms::owner_all);
  test::expect_bad_input(r, "--report-json");
}

// Two frames.
nlohmann::json small_job(const fs::path& out) { return test::small_render_job(out, 2, 1.0); }

TEST(RenderOutputPaths, OutThatIsAFileIsRefused) {
  test::TempDir dir;
  std::ofstream(dir / "taken") << "a file";
  const auto job = dir.write("job.json", small_job(dir / "frames").dump(2));
  test::expect_bad_input(
      test::run_epviz("render " + job.string() + " --out " + (dir / "taken").string(), dir),
      "--out");
  EXPECT_EQ(test::slurp(dir / "taken"), "a file");
}

TEST(RenderOutputPaths, OutputDirBelowAFileIsRefused) {
  test::TempDir dir;
  std::ofstream(dir / "taken") << "a file";
  const auto job = dir.write("job.json", small_job(dir / "taken" / "frames").dump(2));
  test::expect_bad_input(test::run_epviz("render " + job.string(), dir), "output.dir");
}

TEST(RenderOutputPaths, ReportJsonDirectoryIsRefusedBeforeRendering) {
  test::TempDir dir;
  fs::create_directories(dir / "reports");
  const auto job = dir.write("job.json", small_job(dir / "frames").dump(2));
  test::expect_bad_input(
      test::run_epviz("render " + job.string() + " --report-json " + (dir / "reports").string(),
                      dir),
      "--report-json");
  EXPECT_FALSE(fs::exists(dir / "frames")) << "frames rendered despite exit 2";
}

TEST(RenderOutputPaths, OutputNamesThatAreNotFileNamesAreRefused) {
  for (const std::string& name :
       {std::string("a\0b", 3), std::string("sub/frame"), std::string(".."),
        std::string("line\nbreak"), std::string(300, 'n')}) {
    test::TempDir dir;
    auto j = small_job(dir / "frames");
    j["output"]["name"] = name;
    test::expect_render_refused(dir, j.dump(2), "", dir / "frames", "output.name");
  }
}

TEST(RenderOutputPaths, ReportJsonDashPutsOnlyTheReportOnStandardOutput) {
  test::TempDir dir;
  const auto job = dir.write("job.json", small_job(dir / "frames").dump(2));
  const auto r = test::run_epviz("render " + job.string() + " --quiet --report-json -", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);  // throws if the summary line got in
  EXPECT_EQ(report["frames_drawn"], 2);
  EXPECT_NE(r.err.find("frames"), std::string::npos) << "the summary line goes to stderr";
  EXPECT_FALSE(fs::exists(dir / "-"));
}

}  // namespace
}  // namespace epviz
