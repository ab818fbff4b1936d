#include <gtest/gtest.h>

#include <unistd.h>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include "support/eventually.hpp"
#include "support/temp_dir.hpp"
#include "sweep/atlas.hpp"
#include "sweep/point_run.hpp"
#include "sweep/rows_file.hpp"

namespace epviz::sweep {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// The free rigid body turning about its middle axis is an unstable
// equilibrium; its neighbours leave at the rate of the linearised Euler
// equations, lambda = W sqrt((I2 - I1)(I3 - I2) / (I1 I3)) (a textbook
// result, independent of the code measured), and the FTLE must find it.
TEST(Ftle, MatchesTheGrowthRateAtTheUnstableMiddleAxis) {
  sim::RunSpec run;
  run.body = {{1.0, 2.0, 3.0}, {0.0, 0.0, 0.0}, 0.0};
  run.initial = {{0.0, 1.5, 0.0}, {0.0, 0.0, 1.0}};
  // The estimate carries a bias of order log(alignment of the first offset) / T.
  run.t_end = 200.0;
  run.samples = 2000;
  run.tol = 1e-12;
  const double lambda = 1.5 * std::sqrt((2.0 - 1.0) * (3.0 - 2.0) / (1.0 * 3.0));
  const auto ftle = finite_time_lyapunov(run, {});
  ASSERT_TRUE(ftle);
  EXPECT_NEAR(*ftle, lambda, 0.015 * lambda);

  // About the stable largest axis nothing grows exponentially.
  run.initial.omega = {0.0, 0.0, 1.5};
  const auto stable = finite_time_lyapunov(run, {});
  ASSERT_TRUE(stable);
  EXPECT_LT(std::abs(*stable), 0.1 * lambda);
}

TEST(Reference, ARunCloseToItsReferenceIsCloserAtASmallerStep) {
  sim::RunSpec run;
  run.case_id = physics::Case::generic;
  run.body = physics::preset(physics::Case::generic).body;
  run.initial = physics::preset(physics::Case::generic).initial;
  run.method = sim::Method::rk4;
  run.t_end = 5.0;
  run.samples = 50;
  ReferenceCache cache;
  const auto ref = cache.get(run);
  ASSERT_FALSE(ref->empty());
  EXPECT_EQ(cache.get(run), ref);  // computed once
  run.step = 0.02;
  const double coarse = max_separation(sim::simulate(run).samples, *ref);
  run.step = 0.01;
  const double fine = max_separation(sim::simulate(run).samples, *ref);
  // RK4: halving the step divides the error by about 2^4.
  EXPECT_GT(coarse / fine, 12.0);
  EXPECT_LT(coarse / fine, 20.0);
}

TEST(RowsFile, ResumeKeepsCompleteRowsAndCutsATornLine) {
  const test::TempDir dir;
  const fs::path p = dir / "rows.jsonl";
  std::ofstream(p) << R"({"index":3,"sweep":"h"})"
                      "\n"
                      R"({"index":0,"sweep":"h"})"
                      "\n"
                   << R"({"index":1,"sw)";
  const auto got = resume_rows(p, "h", 10);
  EXPECT_EQ(got.indices, (std::set<long>{0, 3}));
  EXPECT_TRUE(got.dropped_torn);
  EXPECT_EQ(fs::file_size(p), std::string(R"({"index":3,"sweep":"h"})"
                                          "\n"
                                          R"({"index":0,"sweep":"h"})"
                                          "\n")
                                  .size());
  EXPECT_THROW(resume_rows(p, "other", 10), RowsFileError);  // rows of another sweep
  EXPECT_THROW(resume_rows(p, "h", 2), RowsFileError);       // index outside the sweep
}

TEST(RowsFile, ResumeDropsARowTwiceAndRefusesTwoDifferentRowsOfAPoint) {
  const test::TempDir dir;
  const fs::path p = dir / "rows.jsonl";
  const std::string r0 = R"({"index":0,"sweep":"h"})", r1 = R"({"index":1,"sweep":"h"})";
  std::ofstream(p) << r0 << "\n"
                   << r1 << "\n"
                   << r0 << "\n"
                   << R"({"index":0,"sw)";
  const auto got = resume_rows(p, "h", 10);
  EXPECT_EQ(got.indices, (std::set<long>{0, 1}));
  EXPECT_EQ(got.dropped_duplicates, 1);
  EXPECT_TRUE(got.dropped_torn);
  EXPECT_EQ(test::slurp(p), r0 + "\n" + r1 + "\n");
  EXPECT_EQ(repairs_note(got), " (a torn last line dropped, 1 duplicate rows dropped)");

  const std::string other = R"({"index":1,"sweep":"h","x":2})";
  std::ofstream(p, std::ios::app) << other << "\n";
  try {
    resume_rows(p, "h", 10);
    ADD_FAILURE() << "two different rows of point 1 were accepted";
  } catch (const RowsFileError& e) {
    EXPECT_NE(
        std::string(e.what()).find("rows.jsonl: line 3 and line 2 are different rows of point 1"),
        std::string::npos)
        << e.what();
  }
  EXPECT_EQ(test::slurp(p), r0 + "\n" + r1 + "\n" + other + "\n") << "changed though refused";
}

TEST(RowsFile, ResumeOfAShardRefusesAnotherShardsRows) {
  const test::TempDir dir;
  const fs::path p = dir / "rows.jsonl";
  std::ofstream(p) << R"({"index":3,"sweep":"h"})"
                   << "\n";
  EXPECT_EQ(resume_rows(p, "h", 10, {2, 5}).indices, (std::set<long>{3}));
  try {
    resume_rows(p, "h", 10, {5, 10});
    ADD_FAILURE() << "a row of another shard was accepted";
  } catch (const RowsFileError& e) {
    EXPECT_NE(std::string(e.what()).find("line 1 holds point 3, outside this shard's points 5..9"),
              std::string::npos)
        << e.what();
  }
}

// A finished row reaches the file soon, with no further row to push it out
// (a killed sweep then loses only what it was computing), and rows arrive
// whole and in order: whenever the file is looked at, it holds the first
// rows appended, none cut.
TEST(RowsFile, AppendedRowsAreOnDiskWithinAFractionOfASecond) {
  const test::TempDir dir;
  const fs::path p = dir / "rows.jsonl";
  const std::string row0 = "{\"index\":0}\n", row1 = "{\"index\":1}\n";
  {
    RowAppender rows(p);
    rows.append(R"({"index":0})");
    rows.append(R"({"index":1})");
    // The writer may take the rows in one write or two; wait for both.
    std::string seen;
    const bool both = test::eventually(
        [&] {
          seen = test::slurp(p);
          EXPECT_TRUE(seen.empty() || seen == row0 || seen == row0 + row1)
              << "torn or out of order: " << seen;
          return seen == row0 + row1;
        },
        std::chrono::seconds(2));
    EXPECT_TRUE(both) << "rows still held back after 2 s (the writer writes every 0.2 s): " << seen;
    rows.append(R"({"index":2})");
  }
  EXPECT_EQ(test::slurp(p), row0 + row1 + "{\"index\":2}\n")
      << "the last row was not written when the appender closed";
}

Json row(long index, const char* method, double step, double energy, bool failed) {
  return {{"index", index},
          {"axes", {{"method", method}, {"step", step}, {"energy", energy}}},
          {"failure", failed ? Json{{"t", 1.0}} : Json(nullptr)},
          {"t_end", 10.0}};
}

TEST(Atlas, LargestStableStepPerMethodAndEnergy) {
  std::vector<Json> rows;
  long i = 0;
  for (const char* m : {"rk4", "gauss4"})
    for (double step : {0.1, 0.2, 0.4})
      for (double e : {1.0, 2.0})
        // rk4 fails above 0.2 at energy 2 and everywhere above 0.1 at energy 1... by construction.
        rows.push_back(
            row(i++, m, step, e,
                std::string(m) == "rk4" ? (e == 2.0 ? step > 0.2 : step > 0.1) : step > 0.4));
  const auto figs = atlas_figures(rows, parse_atlas_option("largest_stable:step:energy:method"));
  ASSERT_EQ(figs.size(), 1u);
  const auto& h = figs[0].heat_map;
  EXPECT_EQ(h.columns, (std::vector<std::string>{"1", "2"}));
  // Rows top down: methods in the sweep's order.
  EXPECT_EQ(h.rows, (std::vector<std::string>{"rk4", "gauss4"}));
  EXPECT_EQ(h.values, (std::vector<std::vector<double>>{{0.1, 0.2}, {0.4, 0.4}}));

  const auto per_method = atlas_figures(rows, parse_atlas_option("time_to_failure:energy:step"));
  ASSERT_EQ(per_method.size(), 2u);  // one figure per method
  EXPECT_THROW(atlas_figures(rows, parse_atlas_option("ftle:energy:nope")), AtlasError);
  EXPECT_THROW(parse_atlas_option("ftle:energy"), AtlasError);
}

}  // namespace
}  // namespace epviz::sweep
