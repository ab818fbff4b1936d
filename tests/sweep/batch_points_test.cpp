// The batch path of a sweep (sweep/batch_points.hpp) writes the very rows of
// the scalar path, sim::simulate one point at a time: every number but the
// CPU time, failures included, the FTLE and the reference separation too.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "numerics/simd_path.hpp"
#include "physics/cases.hpp"
#include "support/simd_env.hpp"
#include "support/temp_dir.hpp"
#include "sweep/batch_points.hpp"
#include "sweep/rows_by_index.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {
namespace {

using epviz::testing::rows_by_index;
using Rows = std::map<long, nlohmann::json>;

Rows rows_of(const SweepSpec& spec, const std::vector<PreparedPoint>& points, int threads,
             PointPath path, const std::filesystem::path& file) {
  {
    RowAppender rows(file);
    run_points(spec, points, threads, rows, {}, path);
  }
  return rows_by_index(file);
}

using epviz::test::ScopedSimdEnv;

// Generic-body runs with omega[0] varied, among them points that fail in
// every way a lane can (the step budget, lost motion at an output time, a
// state that is not finite), points of another tolerance (another batch)
// and points the batch cannot take (rk4, the Riccati formulation).
std::vector<PreparedPoint> mixed_points(long n) {
  std::vector<PreparedPoint> out;
  for (long i = 0; i < n; ++i) {
    PointFields f;
    f.index = i;
    f.axis_values["omega[0]"] = 0.4 + 0.07 * double(i);
    sim::RunSpec run = sim::preset_run(physics::Case::generic, sim::Method::dop853,
                                       sim::Formulation::direct, 3.0 + 0.1 * double(i % 7), 30);
    run.initial.omega[0] = 0.4 + 0.07 * double(i);
    switch (i % 9) {
      case 2: run.max_steps = 5; break;
      case 3:  // the drift passes the limit mid-run
        run.max_drift = 1e-13;
        run.tol = 1e-6;
        break;
      case 4: run.initial.omega[1] = std::numeric_limits<double>::quiet_NaN(); break;
      case 5: run.tol = 1e-8; break;
      case 6: run.method = sim::Method::rk4; break;
      case 7: run.formulation = sim::Formulation::riccati; break;
      default: break;
    }
    out.push_back(prepared_point(f, run));
  }
  return out;
}

TEST(BatchSweep, TheBatchPathWritesTheScalarPathsRows) {
  const test::TempDir dir;
  SweepSpec spec;
  spec.hash = "h";
  spec.reference = true;
  spec.ftle = FtleSettings{1e-8, 0.5, true};
  const auto points = mixed_points(45);
  const Rows scalar = rows_of(spec, points, 1, PointPath::scalar, dir / "scalar.jsonl");
  const Rows batch = rows_of(spec, points, 2, PointPath::batch, dir / "batch.jsonl");
  ASSERT_EQ(scalar.size(), 45u);
  ASSERT_EQ(batch.size(), 45u);
  for (const auto& [i, row] : scalar) EXPECT_EQ(batch.at(i), row) << "point " << i;

  // The failing lanes failed alone, each as its row says; their neighbours finished.
  EXPECT_EQ(batch.at(2)["failure_kind"], "step_budget");
  EXPECT_EQ(batch.at(3)["failure_kind"], "lost_motion");
  EXPECT_GT(batch.at(3)["failure"]["t"].get<double>(), 0.0);
  EXPECT_EQ(batch.at(4)["failure_kind"], "non_finite");
  for (long i : {0L, 1L, 5L, 8L, 9L, 10L}) {
    EXPECT_TRUE(batch.at(i)["failure"].is_null()) << i;
    EXPECT_TRUE(batch.at(i)["ftle"].is_number()) << i;
    EXPECT_TRUE(batch.at(i)["ftle_curve"].is_array()) << i;
    EXPECT_TRUE(batch.at(i)["reference_error"].is_number()) << i;
  }
}

TEST(BatchSweep, EveryInstructionSetWritesTheSameRows) {
  const test::TempDir dir;
  SweepSpec spec;
  spec.hash = "h";
  spec.ftle = FtleSettings{1e-8, 0.0};
  const auto points = mixed_points(27);
  const Rows scalar = rows_of(spec, points, 1, PointPath::scalar, dir / "scalar.jsonl");
  for (numerics::SimdPath path : numerics::kSimdPaths) {
    if (!numerics::cpu_supports(path)) continue;
    const std::string name(numerics::name(path));
    ScopedSimdEnv env(name.c_str());
    const Rows batch =
        rows_of(spec, points, 1, PointPath::batch, dir / ("batch-" + name + ".jsonl"));
    ASSERT_EQ(batch.size(), scalar.size()) << name;
    for (const auto& [i, row] : scalar) EXPECT_EQ(batch.at(i), row) << name << " point " << i;
  }
}

// The shipped chaos map (T = 100, FTLE in windows of 0.5), its first points.
TEST(BatchSweep, TheChaosMapsFirstPointsAsOnTheScalarPath) {
  const test::TempDir dir;
  const SweepSpec spec =
      read_sweep_file(std::filesystem::path(EPVIZ_SOURCE_DIR) / "render_jobs/chaos_map.sweep.json");
  ASSERT_TRUE(spec.ftle);
  const auto points = pending_points(spec, {0, 12}, {});
  for (const auto& p : points) ASSERT_TRUE(runs_batched(p.run));
  const Rows scalar = rows_of(spec, points, 1, PointPath::scalar, dir / "scalar.jsonl");
  const Rows batch = rows_of(spec, points, 2, PointPath::batch, dir / "batch.jsonl");
  ASSERT_EQ(scalar.size(), 12u);
  for (const auto& [i, row] : scalar) {
    EXPECT_EQ(batch.at(i), row) << "point " << i;
    EXPECT_TRUE(row["ftle"].is_number()) << i;
  }
}

// Without an FTLE a row is handed on as soon as its run ends, not when the
// batch does, so that a killed sweep loses only the runs in flight.
TEST(BatchSweep, RowsLeaveTheBatchAsTheirRunsEnd) {
  ScopedSimdEnv two_lanes("sse2");
  std::vector<PreparedPoint> points;
  for (long i = 0; i < 4; ++i) {
    PointFields f;
    f.index = i;
    // The first run is long, the others short: they end while it goes on.
    points.push_back(
        prepared_point(f, sim::preset_run(physics::Case::generic, sim::Method::dop853,
                                          sim::Formulation::direct, i == 0 ? 40.0 : 1.0, 10)));
  }
  std::vector<const PreparedPoint*> batch;
  for (const auto& p : points) batch.push_back(&p);
  std::vector<long> order;
  run_batched(batch, "h", false, {}, nullptr, [&](const PointRow& row) {
    order.push_back(nlohmann::json::parse(row.line)["index"].get<long>());
  });
  EXPECT_EQ(order, (std::vector<long>{1, 2, 3, 0}));
}

TEST(BatchSweep, OnlyDirectDop853RunsTakeTheBatch) {
  sim::RunSpec run;
  EXPECT_TRUE(runs_batched(run));
  run.method = sim::Method::dopri5;
  EXPECT_FALSE(runs_batched(run));
  run.method = sim::Method::dop853;
  run.formulation = sim::Formulation::spinor;
  EXPECT_FALSE(runs_batched(run));
  run.formulation = sim::Formulation::direct;
  run.samples = kKeptSamples + 1;  // streamed, to keep memory flat
  EXPECT_FALSE(runs_batched(run));

  // A batch has one body, tolerance and step budget.
  const auto points = mixed_points(6);  // point 5 has another tolerance
  EXPECT_NE(batch_key(points[0].run), batch_key(points[5].run));
  EXPECT_EQ(batch_key(points[0].run), batch_key(points[1].run));
  EXPECT_THROW(run_batched({&points[0], &points[5]}, "h", false, {}, nullptr, [](auto&) {}),
               std::logic_error);
}

}  // namespace
}  // namespace epviz::sweep
