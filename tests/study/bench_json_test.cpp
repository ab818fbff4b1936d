// Typed rows -> the JSON objects `epviz bench` writes: the study name, the
// run's fields, null for what does not apply, yes/no for flags.
#include <gtest/gtest.h>

#include "study/bench_json.hpp"

namespace epviz {
namespace {

TEST(BenchJson, RunRowFields) {
  study::InvariantCostRow r;
  r.run.case_name = "kovalevskaya";
  r.run.formulation = "direct";
  r.run.method = "rk4";
  r.run.adaptive = false;
  r.run.step = 0.01;
  r.run.t_end = 100.0;
  r.run.steps = 10000;
  r.run.rhs_evals = 40000;
  r.run.flow_evals = 5;
  r.reached = true;
  r.target = 1e-8;
  const auto j = study::row_json(r);
  EXPECT_EQ(j.at("study"), "invariant_cost");
  EXPECT_EQ(j.at("impl"), "epviz");
  EXPECT_EQ(j.at("case"), "kovalevskaya");
  EXPECT_EQ(j.at("accuracy"), "step");
  EXPECT_TRUE(j.at("tol").is_null());
  EXPECT_EQ(j.at("step").get<double>(), 0.01);
  EXPECT_EQ(j.at("cost").get<double>(), 40005.0);
  EXPECT_EQ(j.at("reached"), "yes");
  EXPECT_EQ(j.at("status"), "ok");
  EXPECT_TRUE(j.at("failure_t").is_null());
  EXPECT_EQ(j.at("failure_reason"), "");
  EXPECT_TRUE(j.at("drift_C1").is_null());
}

TEST(BenchJson, FailedPeerRowAndSeries) {
  study::WorkPrecisionRow w;
  w.run.impl = "scipy";
  w.run.ok = false;
  w.run.failure_t = 0.0;
  w.run.failure_reason = "step size too small";
  const auto j = study::row_json(w);
  EXPECT_EQ(j.at("status"), "failed");
  EXPECT_EQ(j.at("failure_t").get<double>(), 0.0);
  EXPECT_TRUE(j.at("steps").is_null());  // the library did not say
  EXPECT_TRUE(j.at("error").is_null());
  EXPECT_EQ(j.at("error_resolved"), "no");

  study::DriftRow d;
  d.series_t = {0.0, 1.0};
  d.series_drift_extra = {study::kNaN, 1e-12};
  const auto a = study::rows_json({w, d});
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[1].at("study"), "drift");
  EXPECT_TRUE(a[1].at("series_drift_extra")[0].is_null());
  EXPECT_EQ(a[1].at("series_drift_extra")[1].get<double>(), 1e-12);
}

}  // namespace
}  // namespace epviz
