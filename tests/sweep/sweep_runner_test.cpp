// The pool of threads that runs a sweep's points: every point's row is
// written once, whole, and says what one thread would have said; failures
// are counted. (The sanitizer pass runs this under ThreadSanitizer too.)
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "io/bad_input.hpp"
#include "physics/cases.hpp"
#include "support/errors.hpp"
#include "support/temp_dir.hpp"
#include "sweep/rows_by_index.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using epviz::testing::rows_by_index;

// Short runs of the generic body with omega[0] varied; every fifth has a
// step budget it cannot meet, so it fails (a row, not an error).
std::vector<PreparedPoint> points(long n) {
  std::vector<PreparedPoint> out;
  for (long i = 0; i < n; ++i) {
    PointFields f;
    f.index = i;
    f.axis_values["omega[0]"] = 0.5 + 0.05 * double(i);
    sim::RunSpec run = sim::preset_run(physics::Case::generic, sim::Method::dop853,
                                       sim::Formulation::direct, 2.0, 20);
    run.initial.omega[0] = 0.5 + 0.05 * double(i);
    if (i % 5 == 4) run.max_steps = 3;
    out.push_back(prepared_point(f, run));
  }
  return out;
}

TEST(SweepRunner, FourThreadsWriteEveryRowOnceAsOneThreadDoes) {
  const test::TempDir dir;
  SweepSpec spec;
  spec.hash = "h";
  const auto prepared = points(40);
  SweepTotals one, four;
  {
    RowAppender rows(dir / "one.jsonl");
    one = run_points(spec, prepared, 1, rows);
  }
  int reported = 0;
  {
    RowAppender rows(dir / "four.jsonl");
    four = run_points(spec, prepared, 4, rows, [&] { ++reported; });
  }
  EXPECT_EQ(one.points, 40);
  EXPECT_EQ(four.points, 40);
  EXPECT_EQ(one.failures, 8);
  EXPECT_EQ(four.failures, 8);
  EXPECT_EQ(reported, 40);
  const auto a = rows_by_index(dir / "one.jsonl");
  const auto b = rows_by_index(dir / "four.jsonl");
  ASSERT_EQ(a.size(), 40u);
  EXPECT_EQ(a, b);
  EXPECT_EQ(b.at(4)["failure_kind"], "step_budget");
  EXPECT_TRUE(b.at(3)["failure"].is_null());
}

SweepSpec sweep_of(const std::string& text) { return read_sweep(Json::parse(text), "s.json"); }

// A shard's pending points: those of its range whose rows are not written
// yet, each resolved with its axis values put in.
TEST(PendingPoints, TheRangeLessWhatIsDone) {
  const auto spec = sweep_of(R"({"simulation": {"method": "rk4"},
      "axes": [{"field": "step", "values": [0.1, 0.2, 0.3, 0.4]}]})");
  ExistingRows done;
  done.indices = {2};
  const auto pending = pending_points(spec, {1, 4}, done);
  ASSERT_EQ(pending.size(), 2u);
  EXPECT_EQ(pending[0].index, 1);
  EXPECT_EQ(pending[0].run.step, 0.2);
  EXPECT_EQ(pending[1].index, 3);
  EXPECT_EQ(pending[1].run.step, 0.4);
  EXPECT_EQ(pending_points(spec, {0, 4}, {}).size(), 4u);
}

TEST(PendingPoints, ABadValueAnywhereIsRefused) {
  // A value outside this shard's range stops it as it stops the shard that has it.
  const auto bad = sweep_of(R"({"axes": [{"field": "omega[2]", "values": [0.5, 1e300]}]})");
  const auto message = test::error_of<io::BadInput>([&] { pending_points(bad, {0, 1}, {}); });
  EXPECT_NE(message.find("axes[0]"), std::string::npos) << message;
}

}  // namespace
}  // namespace epviz::sweep
