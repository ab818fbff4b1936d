// Each classical case's fourth integral (or invariant relation) is conserved by
// DOP853 at tol 1e-12, and the generic body has none to report.
#include <gtest/gtest.h>

#include <vector>

#include "physics/cases.hpp"
#include "run_helpers.hpp"
#include "sim/drift.hpp"

namespace epviz {
namespace {

class ExtraIntegral : public ::testing::TestWithParam<physics::Case> {};

TEST_P(ExtraIntegral, ConservedByDop853) {
  auto spec = sim::preset_run(GetParam(), sim::Method::dop853, sim::Formulation::direct, 50.0, 500);
  spec.tol = 1e-12;
  const auto result = sim::simulate(spec);
  ASSERT_FALSE(result.failure) << result.failure->message();
  const sim::InvariantMonitor monitor(spec.body, spec.case_id, spec.initial);
  const auto drift = monitor.max_relative_drift(result.samples);
  ASSERT_TRUE(drift.extra.has_value());
  EXPECT_LT(*drift.extra, 1e-9) << physics::case_name(GetParam());
  EXPECT_LT(drift.energy, 1e-9);
  EXPECT_LT(drift.area, 1e-9);
}

TEST_P(ExtraIntegral, NotConservedWhenTheConditionIsBroken) {
  // The same fourth integral on a perturbed (non-integrable) body drifts: the
  // conservation above is a property of the case, not of the bookkeeping.
  auto spec = sim::preset_run(GetParam(), sim::Method::dop853, sim::Formulation::direct, 50.0, 500);
  spec.tol = 1e-12;
  spec.body.inertia[0] *= 1.1;
  spec.body.com += Eigen::Vector3d(0.13, 0.21, 0.17);
  spec.initial.omega += Eigen::Vector3d(0.2, -0.1, 0.3);
  const auto result = sim::simulate(spec);
  ASSERT_FALSE(result.failure);
  const sim::InvariantMonitor monitor(spec.body, spec.case_id, spec.initial);
  const auto drift = monitor.max_relative_drift(result.samples);
  ASSERT_TRUE(drift.extra.has_value());
  EXPECT_GT(*drift.extra, 1e-4) << physics::case_name(GetParam());
}

// Every row of the case table with a fourth integral, so that a new case is run too.
std::vector<physics::Case> cases_with_an_integral() {
  std::vector<physics::Case> out;
  for (const auto& p : physics::case_presets())
    if (p.integral) out.push_back(p.id);
  return out;
}

INSTANTIATE_TEST_SUITE_P(Cases, ExtraIntegral, ::testing::ValuesIn(cases_with_an_integral()),
                         [](const auto& param_info) {
                           std::string n = physics::case_name(param_info.param);
                           for (auto& ch : n)
                             if (ch == '-') ch = '_';
                           return n;
                         });

TEST(ExtraIntegral, GenericHasNone) {
  auto spec = sim::preset_run(physics::Case::generic, sim::Method::dop853, sim::Formulation::direct,
                              1.0, 10);
  const auto result = sim::simulate(spec);
  const sim::InvariantMonitor monitor(spec.body, spec.case_id, spec.initial);
  EXPECT_FALSE(monitor.max_relative_drift(result.samples).extra.has_value());
}

}  // namespace
}  // namespace epviz
