// The cloud of a render job: its members are the same trajectories integrated
// alone, they keep the run's energy, and its spread tells an integrable top
// (the cloud stays coherent) from a chaotic one (it smears over the sphere).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "numerics/embedded_rk.hpp"
#include "physics/cases.hpp"
#include "physics/direct.hpp"
#include "physics/invariants.hpp"
#include "scene/cloud_run.hpp"
#include "scene/plan.hpp"
#include "sim/steppers.hpp"

namespace epviz {
namespace {

using physics::Case;

// The shipped cloud jobs' initial state (render_jobs/cloud_*.json): the same
// disc for both bodies.
sim::RunSpec shipped_disc(Case c, double t_end) {
  auto run = sim::preset_run(c, sim::Method::dop853, sim::Formulation::direct, t_end, 1);
  run.initial.omega = {1.0, 0.8, 0.6};
  run.initial.gamma = {0.7198463103929541, 0.6040227735550536, 0.3420201433256688};
  run.tol = 1e-10;
  return run;
}

std::vector<double> times(double t_end, int frames) {
  std::vector<double> t;
  for (int i = 0; i < frames; ++i) t.push_back(t_end * i / (frames - 1));
  return t;
}

TEST(Cloud, MembersFillTheDiscAndKeepTheRunsEnergy) {
  const auto run = shipped_disc(Case::generic, 1.0);
  const scene::CloudSettings cloud{500, 0.1};
  const auto members = scene::cloud_members(run.body, run.initial, cloud);
  ASSERT_EQ(members.size(), 500u);
  const double e0 =
      physics::invariants(run.body, run.case_id, run.initial.omega, run.initial.gamma).energy;
  double widest = 0.0;
  for (const auto& m : members) {
    EXPECT_NEAR(m.gamma.norm(), 1.0, 1e-15);
    const double angle = std::acos(std::clamp(m.gamma.dot(run.initial.gamma), -1.0, 1.0));
    EXPECT_LE(angle, 0.1 + 1e-12);
    widest = std::max(widest, angle);
    EXPECT_NEAR(physics::invariants(run.body, run.case_id, m.omega, m.gamma).energy, e0,
                1e-14 * std::abs(e0));
  }
  EXPECT_GT(widest, 0.095);  // the disc is filled to its edge
}

TEST(Cloud, RefusesMembersThatCannotKeepTheEnergy) {
  auto run = shipped_disc(Case::generic, 1.0);
  run.initial.omega.setZero();
  EXPECT_THROW(scene::cloud_members(run.body, run.initial, {10, 0.05}), scene::PlanError);
}

// Each member at a frame time is the scalar DOP853 on that member alone,
// stepped to the time and interpolated there (its batch lane's output is
// bitwise the scalar one, so its float gamma is too).
TEST(Cloud, MembersAreTheScalarRunsAlone) {
  const auto run = shipped_disc(Case::generic, 8.0);
  const scene::CloudSettings cloud{37, 0.2};
  const auto t = times(run.t_end, 17);
  const scene::CloudRun c(run, cloud, t, 2);
  const int frame = 11;
  const auto& gamma = c.gamma_at(frame);
  ASSERT_EQ(gamma.size(), 37u);
  const auto members = scene::cloud_members(run.body, run.initial, cloud);
  // The cloud's integrator as documented: DOP853 at the run's tolerance.
  numerics::AdaptiveOptions opts;
  opts.rtol = opts.atol = run.tol;
  opts.max_steps = run.max_steps;
  for (std::size_t i = 0; i < members.size(); ++i) {
    numerics::Dop853<physics::DirectSystem> s(physics::DirectSystem(run.body), opts);
    physics::DirectSystem::State x0;
    x0 << members[i].omega, members[i].gamma;
    s.init(0.0, x0);
    for (int k = 0; k <= frame; ++k)
      while (s.t() < t[std::size_t(k)]) s.step();
    const auto x = s.dense(t[std::size_t(frame)]);
    EXPECT_EQ(gamma[i].x(), float(x[3])) << i;
    EXPECT_EQ(gamma[i].y(), float(x[4])) << i;
    EXPECT_EQ(gamma[i].z(), float(x[5])) << i;
  }
}

// The members as rows (what `render --h5` and epviz.cloud hold): each
// member's outputs where it reached them, NaN from its failure on, and the
// chunks in member order.
TEST(Cloud, RowsHoldEachMembersOutputsAndNaNFromItsFailureOn) {
  auto run = shipped_disc(Case::generic, 8.0);
  const scene::CloudSettings cloud{int(scene::kCloudChunk) + 5, 0.2};
  const auto t = times(run.t_end, 9);
  // Whole to the end first, then with a step budget that ends every member
  // part of the way (a step_budget failure).
  std::vector<scene::CloudRows> whole, cut;
  std::vector<std::optional<numerics::Failure>> failures;
  scene::integrate_cloud(run, cloud, t, 2,
                         [&](std::size_t first, const std::vector<sim::DirectBatchResult>& r) {
                           whole.push_back(scene::cloud_rows(first, r, t.size()));
                         });
  run.max_steps = 12;
  scene::integrate_cloud(run, cloud, t, 2,
                         [&](std::size_t first, const std::vector<sim::DirectBatchResult>& r) {
                           EXPECT_EQ(first, cut.size() * scene::kCloudChunk);
                           cut.push_back(scene::cloud_rows(first, r, t.size()));
                           for (const auto& x : r) failures.push_back(x.failure);
                         });
  ASSERT_EQ(cut.size(), 2u);
  ASSERT_EQ(cut[1].members, 5u);
  ASSERT_EQ(failures.size(), std::size_t(cloud.members));
  int cut_short = 0;
  for (std::size_t chunk = 0; chunk < cut.size(); ++chunk)
    for (std::size_t i = 0; i < cut[chunk].members; ++i) {
      const auto& f = failures[cut[chunk].first + i];
      ASSERT_TRUE(f.has_value());
      EXPECT_EQ(f->kind, numerics::FailureKind::step_budget);
      EXPECT_EQ(cut[chunk].failure_kind[i], "step_budget");
      EXPECT_EQ(cut[chunk].failure_t[i], f->t);
      for (std::size_t k = 0; k < t.size(); ++k)
        for (int c = 0; c < 6; ++c) {
          const double x = cut[chunk].state[std::size_t(c)][i * t.size() + k];
          if (t[k] < f->t) {
            // Before the failure: the very numbers of the run to the end.
            EXPECT_EQ(x, whole[chunk].state[std::size_t(c)][i * t.size() + k]);
          } else {
            EXPECT_TRUE(std::isnan(x)) << "member " << i << " at t = " << t[k];
          }
        }
      cut_short += std::isnan(cut[chunk].state[0][i * t.size() + t.size() - 1]);
      EXPECT_GT(f->t, t[1]);  // part of the way: outputs before the failure and NaN after
    }
  EXPECT_EQ(cut_short, cloud.members);
  EXPECT_EQ(cut[0].failed + cut[1].failed, cloud.members);
  for (const auto& rows : whole) {
    EXPECT_EQ(rows.failed, 0);
    for (const auto& c : rows.state)
      for (double x : c) EXPECT_TRUE(std::isfinite(x));
    for (std::size_t i = 0; i < rows.members; ++i)
      EXPECT_TRUE(std::isnan(rows.failure_t[i]) && rows.failure_kind[i].empty());
  }
}

TEST(CloudSpread, IsOneCellForAPointAndNearlyAllForAnEvenSphere) {
  EXPECT_DOUBLE_EQ(scene::cloud_spread(std::vector<Eigen::Vector3f>(100, {0.3f, 0.4f, 0.866f})),
                   1.0 / scene::kSpreadCells);
  // A Fibonacci sphere: points evenly spread by area; with 200 per cell the
  // histogram's entropy is within a few percent of log(cells).
  std::vector<Eigen::Vector3f> even;
  const int n = 200 * scene::kSpreadCells;
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - 2.0 * (k + 0.5) / n, r = std::sqrt(1.0 - z * z);
    const double phi = k * M_PI * (3.0 - std::sqrt(5.0));
    even.emplace_back(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
  }
  EXPECT_GT(scene::cloud_spread(even), 0.97);
  EXPECT_LE(scene::cloud_spread(even), 1.0 + 1e-12);
}

// The same disc on two bodies over the shipped jobs' time: Kovalevskaya's
// cloud keeps to a thin band (its members stay on nearby tori), the generic
// body's smears over much of the sphere.
TEST(CloudSpread, StaysSmallForKovalevskayaAndGrowsForTheGenericBody) {
  const double t_end = 60.0;
  const auto t = times(t_end, 61);
  const scene::CloudSettings cloud{2000, 0.05};
  const scene::CloudRun kov(shipped_disc(Case::kovalevskaya, t_end), cloud, t, 2);
  const scene::CloudRun gen(shipped_disc(Case::generic, t_end), cloud, t, 2);
  const int last = int(t.size()) - 1;
  for (int k : {0, 20, 40, last})
    std::printf("t = %4.0f  kovalevskaya %.4f  generic %.4f\n", t[std::size_t(k)], kov.spread_at(k),
                gen.spread_at(k));
  EXPECT_EQ(kov.gamma_at(last).size(), 2000u);
  EXPECT_EQ(gen.gamma_at(last).size(), 2000u);
  // Both start as the same small disc.
  EXPECT_DOUBLE_EQ(kov.spread_at(0), gen.spread_at(0));
  EXPECT_LT(kov.spread_at(last), 0.02);  // measured 0.008: about 9 cells
  EXPECT_GT(gen.spread_at(last), 0.3);   // measured 0.63
  EXPECT_GT(gen.spread_at(last), 10.0 * kov.spread_at(last));
}

}  // namespace
}  // namespace epviz
