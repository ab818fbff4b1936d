// The peer / epviz CPU time ratio at equal error: two sweeps on power laws
// cpu = c * error^(-1/8), the peer's twice as dear, give a ratio of exactly 2
// at every target inside both sweeps (log-log interpolation is exact on a
// power law); targets outside a sweep, unresolved and failed runs give none.
#include <gtest/gtest.h>

#include <cmath>

#include "study/peers/peer_study.hpp"

namespace epviz {
namespace {

study::WorkPrecisionRow point(const std::string& impl, const std::string& method, double error,
                              double factor) {
  study::WorkPrecisionRow r;
  r.run.impl = impl;
  r.run.method = method;
  r.run.case_name = "euler";
  r.run.formulation = "direct";
  r.error = error;
  r.error_resolved = true;
  r.run.cpu_ms = factor * std::pow(error, -1.0 / 8.0);
  return r;
}

TEST(PeerStudy, RatioAtEqualErrorOnPowerLaws) {
  std::vector<study::WorkPrecisionRow> rows;
  for (const double e : {1e-4, 1e-6, 1e-8, 1e-10}) {
    rows.push_back(point("epviz", "dop853", e, 1.0));
    rows.push_back(point("gsl", "rk8pd", e * 3.0, 2.0));  // the peer's points fall elsewhere
  }
  auto unresolved = point("gsl", "rk8pd", 1e-12, 100.0);
  unresolved.error_resolved = false;
  rows.push_back(unresolved);
  std::vector<const study::WorkPrecisionRow*> ptrs;
  for (const auto& r : rows) ptrs.push_back(&r);
  const auto ratios = study::peers::equal_error_ratios(ptrs, {1e-6, 1e-8, 1e-11});
  ASSERT_EQ(ratios.size(), 2u);  // 1e-11 is below both sweeps' resolved points
  for (const auto& r : ratios) {
    EXPECT_EQ(r.impl, "gsl");
    EXPECT_EQ(r.method, "rk8pd");
    EXPECT_NEAR(r.ratio, 2.0, 1e-12);
    EXPECT_NEAR(r.epviz_dop853_cpu_ms, std::pow(r.error, -1.0 / 8.0), 1e-12);
  }
}

}  // namespace
}  // namespace epviz
