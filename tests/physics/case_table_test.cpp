// The case table as a whole: every row says all a case is, and the rules a
// row carries work on bodies the row was not written for, so that a new row
// is held to the same checks without a test of its own.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "helpers.hpp"
#include "physics/cases.hpp"
#include "physics/invariants.hpp"

namespace epviz::physics {
namespace {

TEST(CaseTable, EveryRowIsComplete) {
  std::set<Case> ids;
  std::set<std::string> names;
  for (const CasePreset& p : case_presets()) {
    SCOPED_TRACE(p.name);
    EXPECT_NE(p.id, Case::custom);
    EXPECT_TRUE(ids.insert(p.id).second);
    EXPECT_TRUE(names.insert(p.name).second);
    EXPECT_EQ(case_name(p.id), p.name);
    EXPECT_FALSE(p.title.empty());
    EXPECT_FALSE(p.summary.empty());
    EXPECT_FALSE(p.panel_conditions.empty());
    // A fourth integral comes with its formula and its overlay symbol.
    EXPECT_EQ(p.integral != nullptr, !p.extra_integral.empty());
    EXPECT_EQ(p.integral != nullptr, !p.integral_symbol.empty());
    // Conditions come with the check and the fit that restores them.
    EXPECT_EQ(p.broken != nullptr, p.conditions != "none");
    EXPECT_EQ(p.broken != nullptr, p.fit != nullptr);
  }
  // Every named enumerator has a row: custom is the only one without.
  EXPECT_EQ(ids.size(), static_cast<std::size_t>(Case::generic));
}

// The preset body and state of a row with conditions, pulled off them: every
// moment, the centre of mass and Omega moved (Hess keeps I1 > I2 > I3).
void perturb(Body& b, InitialState& s, test::Random& rng) {
  const Vector3d I = b.inertia;
  do b.inertia = I.cwiseProduct(rng.vec(0.8, 1.25));
  while (!(b.inertia.x() > b.inertia.y() && b.inertia.y() > b.inertia.z()) && I.x() > I.y() &&
         I.y() > I.z());
  b.com += rng.vec(-0.3, 0.3);
  s.omega += rng.vec(-0.5, 0.5);
}

TEST(CaseTable, FitRestoresTheConditionsTheCheckNames) {
  test::Random rng;
  for (const CasePreset& p : case_presets()) {
    if (!p.fit) continue;
    for (Moment kept : {Moment::first, Moment::second, Moment::third}) {
      for (int trial = 0; trial < 20; ++trial) {
        Body b = p.body;
        InitialState s = p.initial;
        perturb(b, s, rng);
        const auto before = broken_condition(p.id, b, s);
        ASSERT_TRUE(before.has_value()) << p.name << ": the perturbation broke nothing";
        EXPECT_EQ(before->rfind(p.name + " needs ", 0), 0u) << *before;
        const Body edited = b;
        const Vector3d gamma = s.gamma;
        fit_to_case(p.id, kept, b, s);
        EXPECT_EQ(broken_condition(p.id, b, s), std::nullopt)
            << p.name << ": " << broken_condition(p.id, b, s).value_or("");
        EXPECT_EQ(b.weight, edited.weight);
        EXPECT_EQ(s.gamma, gamma);
      }
    }
  }
}

TEST(CaseTable, IntegralMagnitudeBoundsItsValue) {
  // The magnitude drifts are measured against is at least the integral's size
  // (a sum of absolute values bounds the absolute value of the sum).
  test::Random rng;
  for (const CasePreset& p : case_presets()) {
    if (!p.integral) continue;
    for (int trial = 0; trial < 200; ++trial) {
      const Body b = test::random_body(rng);
      const Vector3d w = rng.vec(), g = rng.unit();
      const IntegralValue v = p.integral(b, w, g);
      EXPECT_GE(v.magnitude, std::abs(v.value) * (1 - 1e-15)) << p.name;
      EXPECT_EQ(extra_integral(p.id, b, w, g), v.value);
      EXPECT_EQ(invariants(b, p.id, w, g).extra, v.value);
    }
  }
  EXPECT_EQ(extra_integral(Case::custom, Body{}, Vector3d(1, 2, 3), Vector3d(0, 0, 1)),
            std::nullopt);
}

}  // namespace
}  // namespace epviz::physics
