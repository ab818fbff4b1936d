// How well the shipped Kovalevskaya section (render_jobs/kovalevskaya.section.json,
// dop853 at its tol 1e-10) keeps K, C0 and C1 at its crossings, against the
// figures docs/sections.md quotes for it. The oracle is the integrals
// themselves, recomputed from each crossing's state; the tighter bounds at
// tol 1e-12 are section_oracle_test.cpp's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/invariants.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"

namespace epviz::section {
namespace {

TEST(ShippedSection, KovalevskayaKeepsItsIntegralsToTheDocumentedFigures) {
  const auto job =
      read_section_job(std::string(EPVIZ_SOURCE_DIR) + "/render_jobs/kovalevskaya.section.json");
  ASSERT_EQ(job.methods[0].tol, 1e-10) << "the shipped tolerance changed: docs/sections.md too";
  const auto results = run_section(job, section_starts(job), 2);
  const auto c = physics::Case::kovalevskaya;
  double k = 0.0, energy = 0.0, area = 0.0;
  std::size_t crossings = 0;
  for (const auto& r : results) {
    ASSERT_FALSE(r.failure);
    const auto i0 = physics::invariants(job.body, c, r.start.omega, r.start.gamma);
    const auto sc = physics::invariant_scales(job.body, c, r.start.omega, r.start.gamma);
    for (const auto& x : r.crossings) {
      const auto i = physics::invariants(job.body, c, x.omega, x.gamma);
      k = std::max(k, std::abs(*i.extra - *i0.extra) / *sc.extra);
      energy = std::max(energy, std::abs(i.energy - i0.energy) / sc.energy);
      area = std::max(area, std::abs(i.area - i0.area) / sc.area);
      ++crossings;
    }
  }
  std::printf("%zu crossings: K %.2g, C1 %.2g, C0 %.2g (largest relative drift)\n", crossings, k,
              energy, area);
  // docs/sections.md: K within 1e-7, C0 and C1 within 1e-8 at the shipped tolerance.
  EXPECT_LE(k, 1e-7);
  EXPECT_LE(energy, 1e-8);
  EXPECT_LE(area, 1e-8);
}

}  // namespace
}  // namespace epviz::section
