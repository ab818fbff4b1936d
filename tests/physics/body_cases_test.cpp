// Input validation, case names, presets and their defining conditions.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "helpers.hpp"
#include "physics/body.hpp"
#include "physics/cases.hpp"
#include "physics/direct.hpp"
#include "physics/euler_closed_form.hpp"
#include "physics/invariants.hpp"

namespace epviz::physics {
namespace {

using Eigen::Vector3d;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The message and field of the InvalidInput thrown by f.
template <class F>
std::pair<std::string, std::string> error_of(F&& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return {e.field(), e.what()};
  }
  return {"", "(no exception)"};
}

// A body with its centre of mass at the fixed point (an Eigen vector given as
// {} would be left uninitialised).
Body centred(const Vector3d& inertia, double weight) {
  return Body{inertia, Vector3d::Zero(), weight};
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

TEST(ValidateBody, AcceptsAPhysicalBody) {
  EXPECT_NO_THROW(validate_body(Body{}, false));
  EXPECT_NO_THROW(
      validate_body(Body{Vector3d(1, 1, 2), Vector3d(1, 2, 3), 0.0}, false));  // flat disc
}

TEST(ValidateBody, RejectsBadMoments) {
  for (const Vector3d& I :
       {Vector3d(1, -2, 3), Vector3d(0, 2, 3), Vector3d(1, kNaN, 3), Vector3d(kInf, 2, 3)}) {
    const auto [field, msg] = error_of([&] { validate_body(centred(I, 1), true); });
    EXPECT_EQ(field, "inertia") << msg;
    EXPECT_TRUE(contains(msg, "inertia must be three positive finite numbers; got (")) << msg;
  }
  const auto [field, msg] = error_of([&] { validate_body(centred(Vector3d(1, -2, 3), 1), false); });
  EXPECT_EQ(msg, "inertia must be three positive finite numbers; got (1, -2, 3)");
}

TEST(ValidateBody, TriangleInequalityAndOverride) {
  {
    const auto [field, msg] =
        error_of([&] { validate_body(centred(Vector3d(1, 1, 3), 1), false); });
    EXPECT_EQ(field, "inertia");
    EXPECT_EQ(msg,
              "inertia (1, 1, 3) breaks the triangle inequality I1 + I2 >= I3 (not a rigid body)");
  }
  {
    const auto [field, msg] =
        error_of([&] { validate_body(centred(Vector3d(5, 1, 3), 1), false); });
    EXPECT_TRUE(contains(msg, "I2 + I3 >= I1")) << msg;
  }
  {
    const auto [field, msg] =
        error_of([&] { validate_body(centred(Vector3d(1, 4.5, 3), 1), false); });
    EXPECT_TRUE(contains(msg, "I1 + I3 >= I2")) << msg;
  }
  EXPECT_NO_THROW(validate_body(centred(Vector3d(1, 1, 3), 1), true));
  // Equality is a flat body.
  EXPECT_NO_THROW(validate_body(centred(Vector3d(1, 2, 3), 1), false));
}

TEST(ValidateBody, RejectsBadComAndWeight) {
  auto [field, msg] = error_of([&] {
    validate_body(Body{Vector3d(1, 2, 3), Vector3d(0, kNaN, 0), 1}, false);
  });
  EXPECT_EQ(field, "com");
  EXPECT_TRUE(contains(msg, "finite")) << msg;
  std::tie(field, msg) = error_of([&] { validate_body(centred(Vector3d(1, 2, 3), -1), false); });
  EXPECT_EQ(field, "weight");
  EXPECT_TRUE(contains(msg, "non-negative")) << msg;
  std::tie(field, msg) = error_of([&] { validate_body(centred(Vector3d(1, 2, 3), kInf), true); });
  EXPECT_EQ(field, "weight");
}

TEST(ValidateInitialState, GammaNormAndNormalize) {
  const InitialState ok{Vector3d(1, 2, 3), Vector3d(0.6, 0, 0.8)};
  EXPECT_EQ(validate_initial_state(ok, false).gamma, ok.gamma);
  // Within 1e-9: returned unchanged, even with normalize.
  const InitialState near{Vector3d(1, 2, 3), Vector3d(0, 0, 1 + 5e-10)};
  EXPECT_EQ(validate_initial_state(near, false).gamma, near.gamma);
  EXPECT_EQ(validate_initial_state(near, true).gamma, near.gamma);
  const InitialState off{Vector3d(1, 2, 3), Vector3d(0, 0, 1.02)};
  const auto [field, msg] = error_of([&] { validate_initial_state(off, false); });
  EXPECT_EQ(field, "gamma");
  EXPECT_EQ(msg, "gamma must be a unit vector (| |gamma| - 1 | <= 1e-9); got |gamma| = 1.02");
  const InitialState fixed =
      validate_initial_state(InitialState{ok.omega, Vector3d(3, 0, 4)}, true);
  EXPECT_NEAR(fixed.gamma.norm(), 1.0, 1e-15);
  EXPECT_NEAR(fixed.gamma.x(), 0.6, 1e-15);
  EXPECT_EQ(fixed.omega, ok.omega);
  const auto zero = error_of([&] {
    validate_initial_state(InitialState{ok.omega, Vector3d::Zero()}, true);
  });
  EXPECT_EQ(zero.first, "gamma");
  EXPECT_TRUE(contains(zero.second, "zero")) << zero.second;
}

TEST(ValidateInitialState, RejectsNonFinite) {
  auto [field, msg] = error_of([&] {
    validate_initial_state(InitialState{Vector3d(1, kNaN, 0), Vector3d::UnitZ()}, true);
  });
  EXPECT_EQ(field, "omega");
  EXPECT_TRUE(contains(msg, "finite")) << msg;
  std::tie(field, msg) = error_of([&] {
    validate_initial_state(InitialState{Vector3d::Zero(), Vector3d(kInf, 0, 1)}, true);
  });
  EXPECT_EQ(field, "gamma");
  EXPECT_TRUE(contains(msg, "finite")) << msg;
}

TEST(Cases, NamesRoundTrip) {
  for (Case c : {Case::custom, Case::euler, Case::lagrange, Case::kovalevskaya,
                 Case::goryachev_chaplygin, Case::hess, Case::generic})
    EXPECT_EQ(case_from_name(case_name(c)), c) << case_name(c);
  EXPECT_EQ(case_name(Case::goryachev_chaplygin), "goryachev-chaplygin");
  EXPECT_EQ(case_from_name("nope"), std::nullopt);
  EXPECT_EQ(case_from_name(""), std::nullopt);
  EXPECT_THROW(preset(Case::custom), std::out_of_range);
  for (const CasePreset& p : case_presets()) {
    EXPECT_EQ(case_from_name(p.name), p.id);
    EXPECT_EQ(&preset(p.id), &p);
    EXPECT_FALSE(p.summary.empty());
    EXPECT_FALSE(p.conditions.empty());
    EXPECT_EQ(p.extra_integral.empty(), p.id == Case::generic);
  }
  EXPECT_EQ(case_presets().size(), 6u);
}

TEST(Cases, PresetsAreValidAndSatisfyTheirConditions) {
  for (const CasePreset& p : case_presets()) {
    EXPECT_NO_THROW(validate_body(p.body, false)) << p.name;
    const InitialState s = validate_initial_state(p.initial, false);
    EXPECT_EQ(s.gamma, p.initial.gamma);
    EXPECT_NEAR(p.initial.gamma.norm(), 1.0, 1e-15) << p.name;
    EXPECT_EQ(broken_condition(p.id, p.body, p.initial), std::nullopt)
        << p.name << ": " << broken_condition(p.id, p.body, p.initial).value_or("");
    EXPECT_EQ(extra_integral(p.id, p.body, p.initial.omega, p.initial.gamma).has_value(),
              p.id != Case::generic);
    EXPECT_GT(p.initial.omega.norm(), 0.0) << p.name;
    EXPECT_GT(p.body.weight, 0.0) << p.name;
  }
  // Goryachev-Chaplygin starts on C0 = 0 to round-off; Hess on H = 0.
  const CasePreset& gc = preset(Case::goryachev_chaplygin);
  const Invariants v = invariants(gc.body, gc.id, gc.initial.omega, gc.initial.gamma);
  const Invariants sc = invariant_scales(gc.body, gc.id, gc.initial.omega, gc.initial.gamma);
  EXPECT_LT(std::abs(v.area), 1e-15 * sc.area);
  const CasePreset& h = preset(Case::hess);
  EXPECT_LT(std::abs(*extra_integral(h.id, h.body, h.initial.omega, h.initial.gamma)), 1e-15);
  const Vector3d& I = h.body.inertia;
  EXPECT_TRUE(I.x() > I.y() && I.y() > I.z());
  EXPECT_EQ(h.body.com.y(), 0.0);
  // Lagrange: tilted 30 degrees, fast spin about the symmetry axis.
  const CasePreset& l = preset(Case::lagrange);
  EXPECT_NEAR(std::acos(l.initial.gamma.z()) * 180 / M_PI, 30.0, 1e-12);
  EXPECT_GT(l.initial.omega.z(), 5.0);
  // Kovalevskaya and Goryachev-Chaplygin bodies as specified.
  EXPECT_EQ(preset(Case::kovalevskaya).body.inertia, Vector3d(2, 2, 1));
  EXPECT_EQ(preset(Case::kovalevskaya).body.com, Vector3d(1, 0, 0));
  EXPECT_EQ(gc.body.inertia, Vector3d(4, 4, 1));
  EXPECT_EQ(gc.body.com, Vector3d(1, 0, 0));
}

TEST(Cases, EulerPresetFlipsAwayFromTheSeparatrix) {
  const CasePreset& e = preset(Case::euler);
  EXPECT_EQ(e.body.com, Vector3d::Zero());
  const EulerClosedForm cf(e.body.inertia, e.initial.omega);  // throws on the separatrix
  EXPECT_EQ(cf.dominant_axis(), 2);
  EXPECT_LT(cf.modulus(), 0.999);
  double lo = 0, hi = 0;
  for (int i = 0; i < 100; ++i) {
    const double w2 = cf.omega(cf.period() * i / 100.0).y();
    lo = std::min(lo, w2);
    hi = std::max(hi, w2);
  }
  EXPECT_LT(lo, -2.5);  // the spin about the intermediate axis reverses
  EXPECT_GT(hi, 2.5);
  EXPECT_LT(cf.period(), 20.0);
}

TEST(Cases, GenericPresetIsChaotic) {
  // Two trajectories 1e-9 apart separate by many orders of magnitude.
  const CasePreset& g = preset(Case::generic);
  const DirectSystem sys(g.body);
  const auto f = [&](double t, const DirectSystem::State& x) {
    DirectSystem::State dx;
    sys.rhs(t, x, dx);
    return dx;
  };
  DirectSystem::State x = sys.pack(g.initial), y = x;
  y[0] += 1e-9;
  x = test::rk4(f, 0, 150, x, 30000);
  y = test::rk4(f, 0, 150, y, 30000);
  EXPECT_GT((x - y).norm(), 1e-3);
  // An integrable preset does not (for contrast).
  const CasePreset& k = preset(Case::kovalevskaya);
  const DirectSystem ks(k.body);
  const auto fk = [&](double t, const DirectSystem::State& s) {
    DirectSystem::State dx;
    ks.rhs(t, s, dx);
    return dx;
  };
  x = ks.pack(k.initial);
  y = x;
  y[0] += 1e-9;
  x = test::rk4(fk, 0, 150, x, 30000);
  y = test::rk4(fk, 0, 150, y, 30000);
  EXPECT_LT((x - y).norm(), 1e-5);
}

TEST(Cases, BrokenConditionsNameTheCondition) {
  const auto broken = [](Case c, Body b, InitialState s) {
    return broken_condition(c, b, s).value_or("(none)");
  };
  const CasePreset& kov = preset(Case::kovalevskaya);
  Body b = kov.body;
  b.inertia.z() = 1.5;
  EXPECT_EQ(broken(Case::kovalevskaya, b, kov.initial),
            "kovalevskaya needs I1 = I2 = 2 I3; got I = (2, 2, 1.5)");
  b = kov.body;
  b.com.z() = 0.2;
  EXPECT_TRUE(contains(broken(Case::kovalevskaya, b, kov.initial), "c0 = 0"))
      << broken(Case::kovalevskaya, b, kov.initial);
  b.com = Vector3d(1, 0.1, 0);
  EXPECT_TRUE(contains(broken(Case::kovalevskaya, b, kov.initial), "b0 = c0 = 0"));
  // Relative tolerance 1e-12.
  b = kov.body;
  b.inertia.z() = 1.0 + 1e-14;
  EXPECT_EQ(broken_condition(Case::kovalevskaya, b, kov.initial), std::nullopt);
  b.inertia.z() = 1.0 + 1e-10;
  EXPECT_TRUE(broken_condition(Case::kovalevskaya, b, kov.initial).has_value());

  const CasePreset& lag = preset(Case::lagrange);
  b = lag.body;
  b.com.x() = 0.1;
  EXPECT_EQ(
      broken(Case::lagrange, b, lag.initial),
      "lagrange needs a0 = b0 = 0 (centre of mass on the symmetry axis); got r = (0.1, 0, 1)");
  b = lag.body;
  b.inertia.y() = 2.5;
  EXPECT_EQ(broken(Case::lagrange, b, lag.initial), "lagrange needs I1 = I2; got I = (2, 2.5, 1)");

  const CasePreset& eu = preset(Case::euler);
  b = eu.body;
  b.com = Vector3d(0, 0, 0.5);
  EXPECT_TRUE(contains(broken(Case::euler, b, eu.initial), "euler needs r = 0 or P = 0"))
      << broken(Case::euler, b, eu.initial);
  b.weight = 0;
  EXPECT_EQ(broken_condition(Case::euler, b, eu.initial), std::nullopt);

  const CasePreset& gc = preset(Case::goryachev_chaplygin);
  InitialState s = gc.initial;
  s.omega.z() += 0.1;
  EXPECT_TRUE(contains(broken(Case::goryachev_chaplygin, gc.body, s),
                       "goryachev-chaplygin needs the initial area integral C0"))
      << broken(Case::goryachev_chaplygin, gc.body, s);
  b = gc.body;
  b.inertia = Vector3d(4, 4, 2);
  EXPECT_EQ(broken(Case::goryachev_chaplygin, b, gc.initial),
            "goryachev-chaplygin needs I1 = I2 = 4 I3; got I = (4, 4, 2)");
  b = gc.body;
  b.com.z() = 0.3;
  EXPECT_TRUE(contains(broken(Case::goryachev_chaplygin, b, gc.initial), "b0 = c0 = 0"));

  const CasePreset& h = preset(Case::hess);
  b = h.body;
  b.com.z() *= 1.1;
  EXPECT_TRUE(contains(broken(Case::hess, b, h.initial),
                       "hess needs c0 = +-a0 sqrt(I1 (I2 - I3)) / sqrt(I3 (I1 - I2))"))
      << broken(Case::hess, b, h.initial);
  b = h.body;
  b.com.z() = -b.com.z();  // the other sign is a Hess body too (with its own H = 0 states)
  EXPECT_FALSE(contains(broken(Case::hess, b, h.initial), "c0 = +-"))
      << broken(Case::hess, b, h.initial);
  EXPECT_TRUE(contains(broken(Case::hess, b, h.initial),
                       "hess needs the initial relation H = I1 a0 Omega1 + I3 c0 Omega3 = 0"));
  s = h.initial;
  s.omega.x() += 0.1;
  EXPECT_TRUE(
      contains(broken(Case::hess, h.body, s), "H = I1 a0 Omega1 + I3 c0 Omega3 = 0; got H = 0.3"))
      << broken(Case::hess, h.body, s);
  b = h.body;
  b.inertia = Vector3d(2, 3, 1.5);
  EXPECT_TRUE(contains(broken(Case::hess, b, h.initial), "hess needs I1 > I2 > I3"));
  b = h.body;
  b.com.y() = 0.2;
  EXPECT_TRUE(contains(broken(Case::hess, b, h.initial), "hess needs b0 = 0"));

  // custom and generic have no conditions.
  const Body any{Vector3d(1, 1.5, 2), Vector3d(0.3, 0.2, 0.1), 2};
  EXPECT_EQ(broken_condition(Case::custom, any, InitialState{}), std::nullopt);
  EXPECT_EQ(broken_condition(Case::generic, any, InitialState{}), std::nullopt);
  EXPECT_EQ(extra_integral(Case::custom, any, Vector3d::Ones(), Vector3d::UnitZ()), std::nullopt);
}

}  // namespace
}  // namespace epviz::physics
