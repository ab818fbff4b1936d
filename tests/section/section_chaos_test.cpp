// A generic body's section scatters where an integrable top's draws curves:
// on the level of the shipped generic section, some orbit's neighbours
// separate exponentially, which the finite-time Lyapunov exponent of the
// sweeps (sweep/point_run.hpp) measures as well above zero at T = 500, while
// on the same level the Kovalevskaya top's orbits, which lie on invariant
// tori, separate only linearly: their FTLE is about log(c T) / T with c of
// order one, and falls as T grows. Every orbit of the shipped files is
// measured, none chosen by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "section/section_job.hpp"
#include "section/section_run.hpp"
#include "sweep/point_run.hpp"

namespace epviz::section {
namespace {

SectionJob shipped(const std::string& name) {
  return read_section_job(std::filesystem::path(EPVIZ_SOURCE_DIR) / "render_jobs" /
                          (name + ".section.json"));
}

// The FTLE at T = `horizon` of every orbit of `job`, run by its method at
// its tolerance, in windows of 1 with neighbours 1e-8 apart (the settings of
// the shipped energy-momentum maps).
std::vector<double> orbit_ftles(const SectionJob& job, double horizon) {
  std::vector<double> ftles;
  for (const auto& start : section_starts(job)) {
    sim::RunSpec run;
    run.case_id = job.case_id;
    run.body = job.body;
    run.initial = start;
    run.method = job.methods.at(0).method;
    run.tol = job.methods.at(0).tol;
    run.t_end = horizon;
    run.max_drift = job.max_drift;
    const auto ftle = sweep::finite_time_lyapunov(run, sweep::FtleSettings{1e-8, 1.0});
    EXPECT_TRUE(ftle) << "an orbit was lost";
    if (ftle) ftles.push_back(*ftle);
  }
  return ftles;
}

double largest(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

// Twice what linear separation gives: log(T) / T.
double linear_bound(double horizon) { return 2.0 * std::log(horizon) / horizon; }

TEST(SectionChaos, AGenericOrbitOfTheShippedLevelHasAPositiveExponent) {
  const auto generic = shipped("generic");
  const auto kovalevskaya = shipped("kovalevskaya");
  // The contrast is fair only on the same level, surface and accuracy.
  ASSERT_EQ(generic.level->energy, kovalevskaya.level->energy);
  ASSERT_EQ(generic.level->area, kovalevskaya.level->area);
  ASSERT_EQ(generic.orbits, kovalevskaya.orbits);
  ASSERT_EQ(generic.methods.at(0).tol, kovalevskaya.methods.at(0).tol);

  const auto chaotic = orbit_ftles(generic, 500.0);
  const auto integrable = orbit_ftles(kovalevskaya, 500.0);
  ASSERT_EQ(chaotic.size(), std::size_t(generic.orbits));
  ASSERT_EQ(integrable.size(), std::size_t(kovalevskaya.orbits));
  EXPECT_GT(largest(chaotic), 0.05);
  EXPECT_LT(largest(integrable), linear_bound(500.0));  // 0.025
}

// The integrable top's exponents are those of linear separation at any T, so
// they fall as T grows; a chaotic orbit's do not.
TEST(SectionChaos, KovalevskayaExponentsFallWithTimeAndTheGenericOnesDoNot) {
  const auto integrable = orbit_ftles(shipped("kovalevskaya"), 2000.0);
  const auto chaotic = orbit_ftles(shipped("generic"), 2000.0);
  ASSERT_FALSE(integrable.empty());
  ASSERT_FALSE(chaotic.empty());
  EXPECT_LT(largest(integrable), linear_bound(2000.0));  // 0.0076
  EXPECT_GT(largest(chaotic), 0.05);
}

}  // namespace
}  // namespace epviz::section
