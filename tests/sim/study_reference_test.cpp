// The reference used by `epviz bench` for global errors is itself checked: the
// Richardson-extrapolated Gauss6 solution and DOP853 at tol 1e-14 agree to well
// below the smallest error a sweep reports, and errors fall with tol/step.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/study_bench.hpp"
#include "sim/study_reference.hpp"

namespace epviz {
namespace {

std::vector<sim::StudyRow> reduced_sweep() {
  sim::StudyOptions o;
  o.quick = true;
  o.repeats = 1;
  o.cases = {physics::Case::kovalevskaya};
  o.methods = {sim::Method::dop853, sim::Method::rk4};
  o.formulations = {sim::Formulation::direct};
  return sim::work_precision_study(o);
}

TEST(StudyReference, RichardsonGauss6AgreesWithDop853) {
  const auto& p = physics::preset(physics::Case::kovalevskaya);
  const auto ref = sim::compute_reference(p.body, p.initial, 10.0, 10, sim::reference_step(p.initial));
  ASSERT_EQ(ref.samples.size(), 11u);
  EXPECT_LT(ref.self_check, 1e-11);
  EXPECT_NEAR(ref.samples.back().t, 10.0, 1e-12);
}

TEST(StudyReference, AgreesToWellBelowTheSmallestReportedError) {
  const auto rows = reduced_sweep();
  const sim::StudyRow* ref = nullptr;
  for (const auto& r : rows)
    if (r.study == "reference") ref = &r;
  ASSERT_NE(ref, nullptr);
  const double check = *ref->number("self_check"), smallest = *ref->number("smallest_error");
  EXPECT_TRUE(std::isfinite(smallest));
  EXPECT_LT(check * 10.0, smallest) << "self-check " << check << " vs smallest error " << smallest;
}

TEST(StudyWorkPrecision, ErrorsDecreaseWithToleranceAndStep) {
  const auto rows = reduced_sweep();
  for (const char* method : {"dop853", "rk4"}) {
    std::vector<double> errors;
    for (const auto& r : rows)
      if (r.study == "work_precision" && r.text_of("method") == method) {
        EXPECT_EQ(r.text_of("status"), "ok");
        errors.push_back(*r.number("error"));
      }
    ASSERT_GE(errors.size(), 3u) << method;
    // Strictly down between consecutive points until round-off (1e-12) is reached.
    for (std::size_t i = 1; i < errors.size(); ++i)
      if (errors[i - 1] > 1e-11) {
        EXPECT_LT(errors[i], errors[i - 1]) << method << " point " << i;
      }
    EXPECT_LT(errors.back(), 1e-3 * errors.front()) << method;
  }
}

TEST(StudyWorkPrecision, SkipsIncompatiblePairs) {
  sim::StudyOptions o;
  o.quick = true;
  o.repeats = 1;
  o.cases = {physics::Case::euler};
  o.methods = {sim::Method::splitting};
  o.formulations = {sim::Formulation::riccati};
  const auto rows = sim::work_precision_study(o);
  for (const auto& r : rows) EXPECT_NE(r.study, "work_precision");
}

}  // namespace
}  // namespace epviz
