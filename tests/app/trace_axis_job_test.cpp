// A render job's "trace_axis": the space view's trail follows body axis 1, 2
// or 3; anything else is refused naming the key, before any work.
#include <gtest/gtest.h>

#include "support/cli.hpp"

namespace epviz {
namespace {

using test::run_epviz;
using test::TempDir;

// A small space-view job drawing into <dir>/out, its trace_axis as given.
std::string job(const TempDir& dir, const std::string& trace_axis) {
  return R"({"simulation": {"case": "euler", "t_end": 2}, "view": "space", "trace_axis": )" +
         trace_axis +
         R"(, "width": 64, "height": 48, "fps": 2, "duration": 1, "output": {"dir": ")" +
         (dir / "out").string() + R"(", "format": "png"}})";
}

TEST(TraceAxisJob, BadValuesExitTwoNamingTheKey) {
  for (const char* bad : {"0", "4", "2.5", "\"x\""}) {
    SCOPED_TRACE(bad);
    TempDir dir;
    test::expect_render_refused(dir, job(dir, bad), "--quiet", dir / "out",
                                "job.json: key 'trace_axis'");
  }
}

TEST(TraceAxisJob, AcceptedValuesRender) {
  TempDir dir;
  const auto r =
      run_epviz("render " + dir.write("job.json", job(dir, "2")).string() + " --quiet", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "out"));
}

}  // namespace
}  // namespace epviz
