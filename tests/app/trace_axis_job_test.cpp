// A render job's "trace_axis": the space view's trail follows body axis 1, 2
// or 3; anything else is refused naming the key, before any work.
#include <gtest/gtest.h>

#include <fstream>

#include "support/cli.hpp"

namespace epviz {
namespace {

using test::run_epviz;
using test::TempDir;

void write_job(const TempDir& dir, const std::string& trace_axis) {
  std::ofstream(dir / "job.json") << R"({"simulation": {"case": "euler", "t_end": 2},
      "view": "space", "trace_axis": )"
                                  << trace_axis << R"(, "width": 64, "height": 48,
      "fps": 2, "duration": 1, "output": {"dir": ")"
                                  << (dir / "out").string() << R"(", "format": "png"}})";
}

TEST(TraceAxisJob, BadValuesExitTwoNamingTheKey) {
  for (const char* bad : {"0", "4", "2.5", "\"x\""}) {
    TempDir dir;
    write_job(dir, bad);
    const auto r = run_epviz("render " + (dir / "job.json").string() + " --quiet", dir);
    SCOPED_TRACE(bad);
    expect_bad_input(r, "job.json: key 'trace_axis'");
    EXPECT_FALSE(std::filesystem::exists(dir / "out")) << bad;
  }
}

TEST(TraceAxisJob, AcceptedValuesRender) {
  TempDir dir;
  write_job(dir, "2");
  const auto r = run_epviz("render " + (dir / "job.json").string() + " --quiet", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "out"));
}

}  // namespace
}  // namespace epviz
