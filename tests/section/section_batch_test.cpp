// A section's dop853 orbits integrated side by side by the batch integrator
// give the crossings the scalar path gives them, bit for bit: the same CSV
// rows (orbit, crossing, t, state, integrals) and the same failures, on every
// instruction set this CPU has, with orbits that fail among those that finish.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/bad_input.hpp"
#include "numerics/simd_path.hpp"
#include "section/section_csv.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"
#include "support/simd_env.hpp"

namespace epviz::section {
namespace {

// The generic top on one level (chaotic, so a crossing one ulp off would
// drift away within the run), two dop853 tolerances and an rk4 method (which
// keeps the scalar path), and orbits that end at t_end or at their crossings.
SectionJob mixed_job() {
  SectionJob job;
  job.case_id = physics::Case::generic;
  job.body = physics::preset(job.case_id).body;
  job.level = physics::Level{2.0, 0.5};
  job.orbits = 9;
  job.crossings = 80;
  job.t_end = 150.0;
  job.max_drift = 1e-6;
  job.methods = {SectionMethod{sim::Method::dop853, 1e-10, 0.01},
                 SectionMethod{sim::Method::dop853, 1e-8, 0.01},
                 SectionMethod{sim::Method::rk4, 1e-10, 0.01}};
  return job;
}

// The level's starts and two that fail: one not finite (at its start), one
// far off the level, spinning fast (lost motion at the loose tolerance).
std::vector<physics::InitialState> starts_with_failures(const SectionJob& job) {
  auto starts = section_starts(job);
  physics::InitialState nan = starts[1];
  nan.omega.x() = std::numeric_limits<double>::quiet_NaN();
  physics::InitialState fast = starts[2];
  fast.omega *= 6.0;
  starts.insert(starts.begin() + 3, nan);
  starts.push_back(fast);
  return starts;
}

std::string failures_of(const std::vector<OrbitResult>& results) {
  std::string s;
  for (const auto& r : results)
    if (r.failure) {
      s += std::to_string(r.orbit) + " (method " + std::to_string(r.method) + "): ";
      s += r.failure->message();
      s += "\n";
    }
  return s;
}

TEST(SectionBatch, DopOrbitsOnTheBatchGiveTheScalarPathsCrossingsBitwise) {
  const SectionJob job = mixed_job();
  const auto starts = starts_with_failures(job);
  const auto scalar = run_section(job, starts, 2, std::nullopt, false);
  const std::string csv = crossings_csv(job, scalar);
  const std::string lost = failures_of(scalar);
  // The comparison means something: crossings of every method, orbits cut
  // short by t_end and by their count, and failures of both kinds.
  long full = 0, short_of_count = 0;
  for (const auto& r : scalar)
    if (!r.failure) (r.crossings.size() == std::size_t(job.crossings) ? full : short_of_count)++;
  EXPECT_GT(full, 0);
  EXPECT_GT(short_of_count, 0);
  EXPECT_NE(lost.find("not finite"), std::string::npos) << lost;
  EXPECT_NE(lost.find("drift"), std::string::npos) << lost;
  for (numerics::SimdPath path : numerics::kSimdPaths) {
    if (!numerics::cpu_supports(path)) continue;
    const test::ScopedSimdEnv env(numerics::name(path).data());
    for (int threads : {1, 2}) {
      const auto batch = run_section(job, starts, threads);
      ASSERT_EQ(batch.size(), scalar.size());
      EXPECT_EQ(crossings_csv(job, batch), csv)
          << numerics::name(path) << ", " << threads << " threads";
      EXPECT_EQ(failures_of(batch), lost) << numerics::name(path) << ", " << threads << " threads";
    }
  }
}

// A shard's range of runs (some of a method, some of the next) on the batch
// is that range of the whole section.
TEST(SectionBatch, AShardsRunsAreTheWholeSectionsOnes) {
  const SectionJob job = mixed_job();
  const auto starts = section_starts(job);
  const auto whole = run_section(job, starts, 2, std::nullopt, false);
  const shard::ItemRange range{5, 14};
  const auto part = run_section(job, starts, 2, range);
  ASSERT_EQ(part.size(), 9u);
  const std::vector<OrbitResult> expected(whole.begin() + 5, whole.begin() + 14);
  EXPECT_EQ(crossings_csv(job, part), crossings_csv(job, expected));
}

// EPVIZ_SIMD naming no path is bad input, refused before any orbit runs;
// a section with no orbit for the batch does not read it.
TEST(SectionBatch, ABadSimdVariableIsBadInput) {
  SectionJob job = mixed_job();
  job.orbits = 2;
  const auto starts = section_starts(job);
  const test::ScopedSimdEnv env("avx1024");
  EXPECT_THROW(run_section(job, starts, 1), io::BadInput);
  job.methods = {SectionMethod{sim::Method::rk4, 1e-10, 0.01}};
  EXPECT_EQ(run_section(job, starts, 1).size(), starts.size());
}

TEST(SectionBatch, OnlyDopOrbitsOfOneBodyAndToleranceShareABatch) {
  sim::RunSpec run;
  run.method = sim::Method::dop853;
  EXPECT_TRUE(sim::sections_batched(run));
  sim::RunSpec rk4 = run, loose = run;
  rk4.method = sim::Method::rk4;
  loose.tol = 1e-6;
  EXPECT_FALSE(sim::sections_batched(rk4));
  const sim::SectionSurface surface;
  EXPECT_THROW(sim::section_crossings_batched({run, rk4}, surface, 5, 1), std::invalid_argument);
  EXPECT_THROW(sim::section_crossings_batched({run, loose}, surface, 5, 1), std::invalid_argument);
}

}  // namespace
}  // namespace epviz::section
