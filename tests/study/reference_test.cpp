// The reference used by `epviz bench` for global errors is itself checked: the
// Richardson-extrapolated Gauss6 solution and DOP853 at tol 1e-14 agree to well
// below the smallest error a sweep reports, and errors fall with tol/step.
#include <gtest/gtest.h>

#include <cmath>

#include "study/quick_options.hpp"
#include "study/reference.hpp"
#include "study/work_precision.hpp"

namespace epviz {
namespace {

std::vector<study::StudyRow> reduced_sweep() {
  return study::work_precision_study(testing::quick_options({sim::Method::dop853, sim::Method::rk4},
                                                            {physics::Case::kovalevskaya},
                                                            {sim::Formulation::direct}));
}

TEST(StudyReference, RichardsonGauss6AgreesWithDop853) {
  const auto& p = physics::preset(physics::Case::kovalevskaya);
  const auto ref =
      study::compute_reference(p.body, p.initial, 10.0, 10, study::reference_step(p.initial));
  ASSERT_EQ(ref.samples.size(), 11u);
  EXPECT_LT(ref.self_check, 1e-11);
  EXPECT_NEAR(ref.samples.back().t, 10.0, 1e-12);
}

TEST(StudyReference, AgreesToWellBelowTheSmallestReportedError) {
  const auto rows = reduced_sweep();
  const auto refs = study::rows_of<study::ReferenceRow>(rows);
  ASSERT_EQ(refs.size(), 1u);
  const double check = refs[0]->self_check, smallest = refs[0]->smallest_error;
  EXPECT_TRUE(std::isfinite(smallest));
  EXPECT_LT(check * 10.0, smallest) << "self-check " << check << " vs smallest error " << smallest;
}

TEST(StudyWorkPrecision, ErrorsDecreaseWithToleranceAndStep) {
  const auto rows = reduced_sweep();
  for (const char* method : {"dop853", "rk4"}) {
    std::vector<double> errors;
    for (const auto* r : study::rows_of<study::WorkPrecisionRow>(rows))
      if (r->run.method == method) {
        EXPECT_TRUE(r->run.ok);
        errors.push_back(r->error);
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
  const auto o = testing::quick_options({sim::Method::splitting}, {physics::Case::euler},
                                        {sim::Formulation::riccati});
  const auto rows = study::work_precision_study(o);
  EXPECT_TRUE(study::rows_of<study::WorkPrecisionRow>(rows).empty());
  EXPECT_EQ(study::rows_of<study::ReferenceRow>(rows).size(), 1u);
}

}  // namespace
}  // namespace epviz
