// Sections checked against what must hold whatever the code does: the first
// integrals (and Kovalevskaya's K, Lagrange's Omega3) are the same at every
// crossing of an orbit, each crossing lies on the surface and crosses it the
// right way, a finely sampled run of the same orbit sees the same crossings,
// and a tighter tolerance moves them by far less than a pixel.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/direct.hpp"
#include "physics/invariants.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"
#include "sim/simulate.hpp"

namespace epviz::section {
namespace {

SectionJob level_job(physics::Case c, double energy, double area, int orbits, int crossings) {
  SectionJob job;
  job.case_id = c;
  job.body = physics::preset(c).body;
  job.level = physics::Level{energy, area};
  job.orbits = orbits;
  job.crossings = crossings;
  job.t_end = 1e4;
  job.methods[0].tol = 1e-12;
  return job;
}

std::vector<OrbitResult> run(const SectionJob& job) {
  auto results = run_section(job, section_starts(job), 2);
  for (const auto& r : results) EXPECT_FALSE(r.failure) << lost_orbits_line(job, results);
  return results;
}

// |I - I0| / scale, the scale being that of physics/invariants.hpp.
double drift(double now, double start, double scale) { return std::abs(now - start) / scale; }

TEST(SectionOracle, KovalevskayaCrossingsKeepKAndTheTwoIntegrals) {
  const auto job = level_job(physics::Case::kovalevskaya, 2.0, 0.5, 8, 40);
  const auto results = run(job);
  ASSERT_EQ(results.size(), 8u);
  for (const auto& r : results) {
    ASSERT_EQ(r.crossings.size(), 40u) << "orbit " << r.orbit;
    const auto c = physics::Case::kovalevskaya;
    const auto i0 = physics::invariants(job.body, c, r.start.omega, r.start.gamma);
    const auto sc = physics::invariant_scales(job.body, c, r.start.omega, r.start.gamma);
    for (const auto& x : r.crossings) {
      const auto i = physics::invariants(job.body, c, x.omega, x.gamma);
      EXPECT_LE(drift(*i.extra, *i0.extra, *sc.extra), 1e-9) << "orbit " << r.orbit;
      EXPECT_LE(drift(i.energy, i0.energy, sc.energy), 1e-10) << "orbit " << r.orbit;
      EXPECT_LE(drift(i.area, i0.area, sc.area), 1e-10) << "orbit " << r.orbit;
    }
  }
}

TEST(SectionOracle, LagrangeCrossingsKeepOmega3OfTheirOrbit) {
  auto job = level_job(physics::Case::lagrange, 30.0, 6.0, 6, 25);
  job.surface.function = sim::StateComponent::omega1;  // the spin about the axis precesses
  const auto results = run(job);
  ASSERT_EQ(results.size(), 6u);
  for (const auto& r : results) {
    ASSERT_EQ(r.crossings.size(), 25u) << "orbit " << r.orbit;
    for (const auto& x : r.crossings)
      EXPECT_NEAR(x.omega.z(), r.start.omega.z(), 1e-10 * (1.0 + std::abs(r.start.omega.z())))
          << "orbit " << r.orbit << " crossing " << x.number;
  }
}

// The surface's function and its time derivative along the equations (1.1)-(1.2).
std::pair<double, double> level_and_rate(const SectionJob& job, const sim::Crossing& x) {
  const physics::DirectSystem sys(job.body);
  physics::DirectSystem::State s, ds;
  s << x.omega, x.gamma;
  sys.rhs(0.0, s, ds);
  const int i = int(job.surface.function);
  return {s[i] - job.surface.value, ds[i]};
}

TEST(SectionOracle, CrossingsLieOnTheSurfaceAndCrossItTheWayAsked) {
  using enum sim::Method;
  for (auto [direction, method] : {std::pair{sim::CrossingDirection::upward, dop853},
                                   {sim::CrossingDirection::downward, dop853},
                                   {sim::CrossingDirection::upward, rk4},
                                   {sim::CrossingDirection::downward, exact_split4}}) {
    SCOPED_TRACE(std::string(sim::name(method)));
    auto job = level_job(physics::Case::generic, 2.0, 1.0, 4, 50);
    job.methods[0].tol = 1e-10;
    job.t_end = 500.0;  // an orbit that never crosses runs to t_end
    job.methods[0].method = method;
    job.surface = {sim::StateComponent::omega3, 0.3, direction};
    const auto results = run(job);
    std::size_t seen = 0;  // an orbit whose Omega3 stays below 0.3 has none
    for (const auto& r : results) {
      seen += r.crossings.size();
      for (const auto& x : r.crossings) {
        const auto [level, rate] = level_and_rate(job, x);
        EXPECT_LE(std::abs(level), sim::kSectionResidual) << "orbit " << r.orbit;
        if (direction == sim::CrossingDirection::upward)
          EXPECT_GT(rate, 0.0);
        else
          EXPECT_LT(rate, 0.0);
      }
    }
    EXPECT_GE(seen, 50u);
  }
}

// The same orbit sampled densely by sim::simulate: every sign change of
// gamma3 between two samples holds exactly one crossing, and no crossing
// lies elsewhere.
TEST(SectionOracle, AFinelySampledRunSeesTheSameCrossings) {
  auto job = level_job(physics::Case::generic, 2.0, 1.0, 1, 1000000);
  job.methods[0].tol = 1e-10;
  job.t_end = 60.0;
  const auto starts = section_starts(job);
  const auto crossings = run_section(job, starts, 1).at(0).crossings;
  const auto spec = sim::body_run(physics::Case::generic, job.body, starts[0], sim::Method::dop853,
                                  sim::Formulation::direct, job.t_end, 60000);
  auto sampled_spec = spec;
  sampled_spec.tol = job.methods[0].tol;
  const auto samples = sim::simulate(sampled_spec).samples;
  std::vector<std::pair<double, double>> brackets;
  for (std::size_t k = 1; k < samples.size(); ++k)
    if (samples[k - 1].gamma.z() < 0.0 && samples[k].gamma.z() >= 0.0)
      brackets.emplace_back(samples[k - 1].t, samples[k].t);
  ASSERT_GE(brackets.size(), 5u);
  ASSERT_EQ(crossings.size(), brackets.size());
  for (std::size_t i = 0; i < brackets.size(); ++i) {
    EXPECT_GE(crossings[i].t, brackets[i].first - 1e-9);
    EXPECT_LE(crossings[i].t, brackets[i].second + 1e-9);
  }
}

// A section plotted 1000 pixels across a range of about 2 in each coordinate:
// half a pixel is 1e-3. The two tolerances must agree far within it.
TEST(SectionOracle, ATighterToleranceMovesNoCrossingByHalfAPixel) {
  auto loose = level_job(physics::Case::kovalevskaya, 2.0, 0.5, 1, 60);
  loose.methods[0].tol = 1e-10;
  auto tight = loose;
  tight.methods[0].tol = 1e-13;
  const auto a = run(loose).at(0).crossings;
  const auto b = run(tight).at(0).crossings;
  ASSERT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, (a[i].omega - b[i].omega).cwiseAbs().maxCoeff());
    worst = std::max(worst, (a[i].gamma - b[i].gamma).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-5);
}

// A fixed-step method finds the same crossings as DOP853 at a tight
// tolerance, within its own error: rk4 at h = 0.002 (error about 1e-9 here)
// and the interpolant between its steps (about 1e-11).
TEST(SectionOracle, AFixedStepMethodFindsTheSameCrossings) {
  auto reference = level_job(physics::Case::kovalevskaya, 2.0, 0.5, 1, 30);
  reference.methods[0].tol = 1e-13;
  auto fixed = reference;
  fixed.methods[0].method = sim::Method::rk4;
  fixed.methods[0].step = 0.002;
  const auto a = run(reference).at(0).crossings;
  const auto b = run(fixed).at(0).crossings;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].t, b[i].t, 1e-6);
    EXPECT_LT((a[i].omega - b[i].omega).cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_LT((a[i].gamma - b[i].gamma).cwiseAbs().maxCoeff(), 1e-6);
  }
}

}  // namespace
}  // namespace epviz::section
