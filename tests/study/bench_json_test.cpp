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

// The metadata's reference summary: the worst self-check of the references
// and the smallest finite error any of them resolved (null when none did).
TEST(BenchJson, DocumentSummarisesTheReferences) {
  study::ReferenceRow a, b;
  a.self_check = 2e-13;
  a.smallest_error = 4e-9;
  b.self_check = 7e-13;
  b.smallest_error = study::kNaN;
  study::WorkPrecisionRow w;
  w.error = 1e-15;  // a run's error is not a reference's
  const auto doc = study::bench_document({a, w, b}, true, 12.5);
  const auto& meta = doc.at("metadata");
  EXPECT_EQ(meta.at("mode"), "quick");
  EXPECT_EQ(meta.at("wall_seconds").get<double>(), 12.5);
  EXPECT_EQ(meta.at("reference").at("max_self_check").get<double>(), 7e-13);
  EXPECT_EQ(meta.at("reference").at("smallest_reported_error").get<double>(), 4e-9);
  EXPECT_EQ(doc.at("rows"), study::rows_json({a, w, b}));

  const auto none = study::bench_document({b}, false, 1.0);
  EXPECT_EQ(none.at("metadata").at("mode"), "full");
  EXPECT_TRUE(none.at("metadata").at("reference").at("smallest_reported_error").is_null());
}

}  // namespace
}  // namespace epviz
