// DOP853 against the Euler case's closed form (Jacobi elliptic functions).
#include <gtest/gtest.h>

#include "physics/euler_closed_form.hpp"
#include "run_helpers.hpp"

namespace epviz {
namespace {

struct EulerRun {
  Eigen::Vector3d inertia;
  Eigen::Vector3d omega0;
};

class EulerClosedFormAgreement : public ::testing::TestWithParam<EulerRun> {};

TEST_P(EulerClosedFormAgreement, Dop853MatchesClosedFormOver60TimeUnits) {
  const auto& run = GetParam();
  sim::RunSpec spec = sim::preset_run(physics::Case::euler, sim::Method::dop853,
                                      sim::Formulation::direct, 60.0, 600);
  spec.body.inertia = run.inertia;
  spec.initial.omega = run.omega0;
  spec.tol = 1e-12;
  const auto result = sim::simulate(spec);
  ASSERT_FALSE(result.failure) << result.failure->message();

  const physics::EulerClosedForm exact(run.inertia, run.omega0);
  double worst = 0.0;
  for (const auto& s : result.samples) worst = std::max(worst, (s.omega - exact.omega(s.t)).norm());
  EXPECT_LT(worst, 1e-9);
  // The check must be able to fail: a loose tolerance is visibly worse.
  spec.tol = 1e-5;
  const auto loose = sim::simulate(spec);
  double worst_loose = 0.0;
  for (const auto& s : loose.samples)
    worst_loose = std::max(worst_loose, (s.omega - exact.omega(s.t)).norm());
  EXPECT_GT(worst_loose, 100 * worst);
}

INSTANTIATE_TEST_SUITE_P(
    Orderings, EulerClosedFormAgreement,
    ::testing::Values(EulerRun{{1, 2, 3}, {0.4, 0.0, 1.0}},  // math.md's check
                      EulerRun{{3, 2, 1}, {1.0, 0.2, 0.4}},  // reversed order
                      EulerRun{{2, 3, 1.5}, {0.3, -0.5, 0.8}},
                      EulerRun{{1, 2, 3}, {1.0, 0.3, 0.2}},  // other side of the separatrix
                      EulerRun{{2.5, 1, 2}, {-0.2, 0.7, 0.6}}));

}  // namespace
}  // namespace epviz
