// Input that used to hang epviz or turn its one-line error into kilobytes:
// a named pipe nobody writes to as the job or sweep file, a 100 KB sweep
// value, a 5,000-character output.dir. Each is refused with exit 2 and one
// short line, before any work.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "support/cli.hpp"
#include "support/temp_dir.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

// Opening a pipe that has no writer waits for one; epviz must give up on its
// own. `timeout` ends the run (exit 124, a failure) should it wait for ever.
TEST(HostileMessages, APipeNobodyWritesToIsRefusedNotWaitedOn) {
  const test::TempDir dir;
  const fs::path fifo = dir / "idle.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& command :
       {"sweep " + fifo.string() + " --out {dir}/rows.jsonl", "simulate --job " + fifo.string()}) {
    SCOPED_TRACE(command);
    const auto r = test::run_epviz(dir.expand(command), dir, "timeout 20");
    test::expect_bad_input(r, "idle.fifo: nothing to read for");
  }
  EXPECT_FALSE(fs::exists(dir / "rows.jsonl"));
}

TEST(HostileMessages, AHugeSweepValueIsQuotedShort) {
  const test::TempDir dir;
  const std::string value(100'000, 'x');
  const auto file = dir.write("big.sweep.json",
                              R"({"axes": [{"field": "method", "values": [")" + value + R"("]}]})");
  const auto r =
      test::run_epviz(dir.expand("sweep " + file.string() + " --out {dir}/rows.jsonl"), dir);
  test::expect_bad_input(r, "key 'axes[0]' (method = \"xxxx");
  EXPECT_NE(r.err.find("(100002 bytes)"), std::string::npos) << r.err.substr(0, 500);
  EXPECT_FALSE(fs::exists(dir / "rows.jsonl"));
}

// One name longer than a file system takes, and a path longer than the
// system takes: both are the job's mistake, told in a line of bounded length.
TEST(HostileMessages, AHugeOutputDirIsBadInputQuotedShort) {
  const test::TempDir dir;
  std::string nested;
  while (nested.size() < 5000) nested += "abcdefghi/";
  for (const std::string& out :
       {(dir / std::string(5000, 'd')).string(), (dir / nested).string()}) {
    SCOPED_TRACE(out.size());
    const auto job = dir.write(
        "job.json", R"({"simulation": {"case": "lagrange"}, "width": 160, "height": 120, )"
                    R"("fps": 2, "duration": 1, "output": {"dir": ")" +
                        out + "\"}}");
    const auto r = test::run_epviz("render " + job.string(), dir);
    test::expect_bad_input(r, "output.dir: '" + dir.path().string());
    EXPECT_NE(r.err.find("is too long"), std::string::npos) << r.err.substr(0, 500);
  }
  EXPECT_EQ(dir.file_count(), 1u) << "something besides the job file was created";
}

// A value with a newline, a terminal's escape code and 5,000 more bytes, as
// one shell word: the message quotes it escaped and cut short, on one line.
const std::string kHostileValue = "bo\ngus\x1b[31m" + std::string(5000, 'x');

void expect_quoted_short(const test::CliResult& r, const std::string& must_name) {
  test::expect_bad_input(r, must_name);
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << "an escape code reached the terminal";
  EXPECT_NE(r.err.find("'bo\\ngus\\u001b[31mxxx"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(5011 bytes)"), std::string::npos) << r.err;
}

TEST(HostileMessages, AJobNameIsQuotedEscapedAndShort) {
  const test::TempDir dir;
  expect_quoted_short(test::run_epviz("render '" + kHostileValue + "'", dir), "no such job file");
}

TEST(HostileMessages, AnEpvizSimdValueIsQuotedEscapedAndShort) {
  const test::TempDir dir;
  expect_quoted_short(test::run_epviz("cases", dir, "env EPVIZ_SIMD='" + kHostileValue + "'"),
                      "EPVIZ_SIMD=");
}

TEST(HostileMessages, AnAtlasOptionIsQuotedEscapedAndShort) {
  const test::TempDir dir;
  // Not METRIC:X:Y: refused before the folder is looked at.
  expect_quoted_short(
      test::run_epviz("merge " + dir.path().string() + " --atlas '" + kHostileValue + "'", dir),
      "--atlas: expected METRIC:XAXIS:YAXIS");
}

}  // namespace
}  // namespace epviz
