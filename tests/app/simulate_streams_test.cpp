// `epviz simulate` writes its CSV to streams (standard output, /dev/null, a
// FIFO) directly, follows symbolic links, and keeps memory flat however many
// samples are asked for.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <thread>

#include "io/temp_name.hpp"
#include "support/cli.hpp"
#include "support/peak_rss.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

TEST(SimulateStreams, DashWritesTheCsvToStandardOutputAndTheSummaryToStderr) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --case lagrange --samples 10 --csv -", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(r.out.rfind("t,omega1,", 0), 0u) << "stdout must start with the CSV header:\n" << r.out;
  EXPECT_EQ(test::line_count(r.out), 12u) << "header + 11 rows and nothing else:\n" << r.out;
  EXPECT_NE(r.err.find("max relative drift"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "-"));
  EXPECT_EQ(dir.file_count(), 0u);
}

TEST(SimulateStreams, DevStdoutIsTheSameAsDash) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --case lagrange --samples 10 --csv /dev/stdout", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("t,omega1,", 0), 0u) << r.out;
  EXPECT_EQ(test::line_count(r.out), 12u) << r.out;
}

TEST(SimulateStreams, ReportJsonToStandardOutput) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --case euler --samples 10 --report-json -", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("\"samples_written\": 11"), std::string::npos) << r.out;
}

TEST(SimulateStreams, CsvAndReportCannotBothGoToStandardOutput) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --case euler --csv - --report-json -", dir);
  test::expect_bad_input(r, "--report-json");
}

TEST(SimulateStreams, DevNullStaysADevice) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --case euler --samples 10 --csv /dev/null", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_FALSE(fs::exists("/dev/null" + io::temporary_suffix(::getpid())));
}

TEST(SimulateStreams, DevFullIsOneLineWriteErrorExitOne) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --case euler --samples 5000 --csv /dev/full", dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(test::line_count(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No space left"), std::string::npos) << r.err;
}

TEST(SimulateStreams, FifoReadByAThread) {
  test::TempDir dir;
  const auto fifo = dir / "rows.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = test::slurp(fifo); });
  const auto r = test::run_epviz("simulate --case euler --samples 20 --csv " + fifo.string(), dir);
  reader.join();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(received.rfind("t,omega1,", 0), 0u) << received;
  EXPECT_EQ(test::line_count(received), 22u);
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced by a file";
}

TEST(SimulateStreams, SymlinkIsFollowedAndKept) {
  test::TempDir dir;
  fs::create_directories(dir / "real");
  std::ofstream(dir / "real" / "data.csv") << "old";
  fs::create_symlink(dir / "real" / "data.csv", dir / "link.csv");
  const auto r = test::run_epviz(
      "simulate --case euler --samples 10 --csv " + (dir / "link.csv").string(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir / "link.csv")) << "the link was replaced by a file";
  const auto csv = test::slurp(dir / "real" / "data.csv");
  EXPECT_EQ(csv.rfind("t,omega1,", 0), 0u) << csv;
  EXPECT_EQ(test::line_count(csv), 12u);
}

// Peak resident memory (kB) of one `epviz simulate` child.
long peak_rss_kb(const std::string& samples) {
  return test::peak_rss_kb(
      {"simulate", "--case", "lagrange", "--samples", samples, "--csv", "/dev/null"});
}

TEST(SimulateStreams, MemoryDoesNotGrowWithSamples) {
  const long small = peak_rss_kb("10000");
  const long large = peak_rss_kb("1000000");
  ASSERT_GT(small, 0);
  ASSERT_GT(large, 0);
  // Kept in memory, 1e6 samples would take > 100 MB (and their CSV 300 MB more).
  EXPECT_LT(large - small, 8 * 1024)
      << "peak RSS " << small << " kB for 1e4 samples, " << large << " kB for 1e6";
}

// The steps between two samples are not kept either: each is folded into the
// report's step drift as it comes. 1e6 RK4 steps written as one sample held
// about 210 bytes a step (over 100 MB) when the steps waited for their sample.
TEST(SimulateStreams, MemoryDoesNotGrowWithStepsBetweenSamples) {
  const auto rk4 = [](const std::string& samples) {
    return test::peak_rss_kb({"simulate", "--case", "generic", "--method", "rk4", "--step", "1e-5",
                              "--t-end", "10", "--samples", samples, "--csv", "/dev/null"});
  };
  const long one = rk4("1");
  const long many = rk4("1000");
  ASSERT_GT(one, 0);
  ASSERT_GT(many, 0);
  EXPECT_LT(one - many, 8 * 1024) << "peak RSS " << one << " kB for 1e6 steps in one sample, "
                                  << many << " kB in 1000 samples";
}

}  // namespace
}  // namespace epviz
