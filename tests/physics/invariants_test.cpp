// First integrals and the cases' extra integrals: their derivative along the
// direct rhs, computed here by the product rule from docs/math.md §1.3's formulas.
#include <gtest/gtest.h>

#include <cmath>

#include "helpers.hpp"
#include "physics/cases.hpp"
#include "physics/direct.hpp"
#include "physics/invariants.hpp"

namespace epviz::physics {
namespace {

struct Deriv {
  double value;  // dI/dt
  double scale;  // sum of the absolute values of its terms (for a relative test)
};

struct Point {
  Vector3d w, g, dw, dg;
};

Point at(const Body& body, const Vector3d& w, const Vector3d& g) {
  DirectSystem sys(body);
  DirectSystem::State x, dx;
  x << w, g;
  sys.rhs(0, x, dx);
  return {w, g, dx.head<3>(), dx.tail<3>()};
}

// d/dt of a sum of products, term by term.
struct Acc {
  double value = 0, scale = 0;
  void operator+=(double term) {
    value += term;
    scale += std::abs(term);
  }
  Deriv get() const { return {value, scale}; }
};

Deriv d_gamma2(const Point& p) {
  Acc a;
  for (int i = 0; i < 3; ++i) a += 2 * p.g[i] * p.dg[i];
  return a.get();
}
Deriv d_area(const Body& b, const Point& p) {
  Acc a;
  for (int i = 0; i < 3; ++i) {
    a += b.inertia[i] * p.dw[i] * p.g[i];
    a += b.inertia[i] * p.w[i] * p.dg[i];
  }
  return a.get();
}
Deriv d_energy(const Body& b, const Point& p) {
  Acc a;
  for (int i = 0; i < 3; ++i) {
    a += b.inertia[i] * p.w[i] * p.dw[i];
    a += b.weight * b.com[i] * p.dg[i];
  }
  return a.get();
}

// docs/math.md §2.1, written out here.
double euler_L2(const Body& b, const Vector3d& w, const Vector3d&) {
  return b.inertia.cwiseProduct(w).squaredNorm();
}
Deriv d_euler(const Body& b, const Point& p) {
  Acc a;
  for (int i = 0; i < 3; ++i) a += 2 * b.inertia[i] * b.inertia[i] * p.w[i] * p.dw[i];
  return a.get();
}
double kov_K(const Body& b, const Vector3d& w, const Vector3d& g) {
  const double k = b.weight * b.com.x() / b.inertia.z();
  const double x = w.x() * w.x() - w.y() * w.y() - k * g.x(), y = 2 * w.x() * w.y() - k * g.y();
  return x * x + y * y;
}
Deriv d_kov(const Body& b, const Point& p) {
  const double k = b.weight * b.com.x() / b.inertia.z();
  const Vector3d& w = p.w;
  const Vector3d& g = p.g;
  const double x = w.x() * w.x() - w.y() * w.y() - k * g.x(), y = 2 * w.x() * w.y() - k * g.y();
  Acc a;
  a += 2 * x * 2 * w.x() * p.dw.x();
  a += -2 * x * 2 * w.y() * p.dw.y();
  a += -2 * x * k * p.dg.x();
  a += 2 * y * 2 * p.dw.x() * w.y();
  a += 2 * y * 2 * w.x() * p.dw.y();
  a += -2 * y * k * p.dg.y();
  return a.get();
}
double gc_G(const Body& b, const Vector3d& w, const Vector3d& g) {
  return w.z() * (w.x() * w.x() + w.y() * w.y()) -
         b.weight * b.com.x() / b.inertia.z() * w.x() * g.z();
}
Deriv d_gc(const Body& b, const Point& p) {
  const double k = b.weight * b.com.x() / b.inertia.z();
  const Vector3d& w = p.w;
  Acc a;
  a += p.dw.z() * w.x() * w.x();
  a += p.dw.z() * w.y() * w.y();
  a += w.z() * 2 * w.x() * p.dw.x();
  a += w.z() * 2 * w.y() * p.dw.y();
  a += -k * p.dw.x() * p.g.z();
  a += -k * w.x() * p.dg.z();
  return a.get();
}
double hess_H(const Body& b, const Vector3d& w, const Vector3d&) {
  return b.inertia.x() * b.com.x() * w.x() + b.inertia.z() * b.com.z() * w.z();
}
Deriv d_hess(const Body& b, const Point& p) {
  Acc a;
  a += b.inertia.x() * b.com.x() * p.dw.x();
  a += b.inertia.z() * b.com.z() * p.dw.z();
  return a.get();
}

TEST(Invariants, ValuesMatchFormulas) {
  test::Random rng;
  const Body body = test::random_body(rng);
  const Vector3d w = rng.vec(), g = rng.unit();
  const Invariants v = invariants(body, Case::custom, w, g);
  EXPECT_DOUBLE_EQ(v.gamma_norm2, g.dot(g));
  double c0 = 0, c1 = 0;
  for (int i = 0; i < 3; ++i) {
    c0 += body.inertia[i] * w[i] * g[i];
    c1 += 0.5 * body.inertia[i] * w[i] * w[i] + body.weight * body.com[i] * g[i];
  }
  EXPECT_NEAR(v.area, c0, 1e-14 * (1 + std::abs(c0)));
  EXPECT_NEAR(v.energy, c1, 1e-14 * (1 + std::abs(c1)));
  EXPECT_FALSE(v.extra.has_value());
  EXPECT_FALSE(invariants(body, Case::generic, w, g).extra.has_value());
}

TEST(Invariants, CasimirsAndEnergyAreConservedByTheRhs) {
  test::Random rng;
  for (int trial = 0; trial < 500; ++trial) {
    const Body body = test::random_body(rng);
    // gamma need not be unit for these identities.
    const Point p = at(body, rng.vec(), rng.vec(-1, 1));
    for (const Deriv d : {d_gamma2(p), d_area(body, p), d_energy(body, p)})
      EXPECT_LE(std::abs(d.value), 1e-12 * d.scale) << "trial " << trial;
  }
}

TEST(Invariants, DerivativeTestCanFail) {
  // The same check on a perturbed vector field (gamma' off by 1e-6) fails.
  test::Random rng;
  const Body body = test::random_body(rng);
  Point p = at(body, rng.vec(), rng.unit());
  p.dg.x() += 1e-6;
  const Deriv d = d_area(body, p);
  EXPECT_GT(std::abs(d.value), 1e-12 * d.scale);
}

// Random state for a body of case c (on C0 = 0 / H = 0 where the case needs it).
void random_state(Case c, const Body& b, test::Random& rng, Vector3d& w, Vector3d& g) {
  w = rng.vec();
  g = rng.unit();
  if (c == Case::goryachev_chaplygin)
    w.z() =
        -(b.inertia.x() * w.x() * g.x() + b.inertia.y() * w.y() * g.y()) / (b.inertia.z() * g.z());
  if (c == Case::hess) w.x() = -b.inertia.z() * b.com.z() * w.z() / (b.inertia.x() * b.com.x());
}

Body random_case_body(Case c, test::Random& rng) {
  const double s = rng.uniform(0.5, 2.0), a0 = rng.uniform(-1.5, 1.5), P = rng.uniform(0.5, 2.0);
  switch (c) {
    case Case::euler: return Body{rng.vec(0.5, 3.0), Vector3d::Zero(), P};
    case Case::lagrange: return Body{Vector3d(s, s, rng.uniform(0.5, 2.0)), Vector3d(0, 0, a0), P};
    case Case::kovalevskaya: return Body{Vector3d(2 * s, 2 * s, s), Vector3d(a0, 0, 0), P};
    case Case::goryachev_chaplygin: return Body{Vector3d(4 * s, 4 * s, s), Vector3d(a0, 0, 0), P};
    case Case::hess: {
      const double i3 = rng.uniform(0.5, 1.0), i2 = i3 + rng.uniform(0.1, 0.5),
                   i1 = i2 + rng.uniform(0.1, 0.4);
      const Vector3d I(i1, i2, i3);
      const double c0 = (rng.uniform(0, 1) < 0.5 ? -1 : 1) * a0 * std::sqrt(i1 * (i2 - i3)) /
                        std::sqrt(i3 * (i1 - i2));
      return Body{I, Vector3d(a0, 0, c0), P};
    }
    default: return Body{};
  }
}

struct CaseOracle {
  Case c;
  double (*value)(const Body&, const Vector3d&, const Vector3d&);
  Deriv (*deriv)(const Body&, const Point&);
};
const CaseOracle kOracles[] = {
    {Case::euler, euler_L2, d_euler},
    {Case::lagrange, [](const Body&, const Vector3d& w, const Vector3d&) { return w.z(); },
     [](const Body&, const Point& p) {
       return Deriv{p.dw.z(), std::abs(p.dw.z()) + 1e-300};
     }},
    {Case::kovalevskaya, kov_K, d_kov},
    {Case::goryachev_chaplygin, gc_G, d_gc},
    {Case::hess, hess_H, d_hess},
};

TEST(Invariants, ExtraIntegralsAreConservedInTheirCase) {
  test::Random rng;
  for (const CaseOracle& o : kOracles) {
    for (int trial = 0; trial < 200; ++trial) {
      const Body body = random_case_body(o.c, rng);
      ASSERT_EQ(broken_condition(o.c, body, InitialState{}), std::nullopt)
          << case_name(o.c) << ": " << *broken_condition(o.c, body, InitialState{});
      Vector3d w, g;
      random_state(o.c, body, rng, w, g);
      EXPECT_EQ(broken_condition(o.c, body, InitialState{w, g}), std::nullopt) << case_name(o.c);
      const auto lib = extra_integral(o.c, body, w, g);
      ASSERT_TRUE(lib.has_value());
      const double ref = o.value(body, w, g);
      EXPECT_NEAR(*lib, ref, 1e-13 * (1 + std::abs(ref))) << case_name(o.c);
      EXPECT_EQ(invariants(body, o.c, w, g).extra, lib);
      const Deriv d = o.deriv(body, at(body, w, g));
      if (o.c == Case::lagrange) {
        EXPECT_LE(std::abs(d.value), 1e-14 * (1 + w.norm() * w.norm())) << case_name(o.c);
      } else {
        EXPECT_LE(std::abs(d.value), 1e-12 * d.scale) << case_name(o.c) << " trial " << trial;
      }
      // The hand-written derivative agrees with the library's integral (finite differences).
      const Point p = at(body, w, g);
      const double eps = 1e-6;
      const double fd = (*extra_integral(o.c, body, w + eps * p.dw, g + eps * p.dg) -
                         *extra_integral(o.c, body, w - eps * p.dw, g - eps * p.dg)) /
                        (2 * eps);
      EXPECT_NEAR(fd, d.value, 1e-6 * (1 + d.scale));
    }
  }
}

TEST(Invariants, ExtraIntegralsDriftWhenTheConditionBreaks) {
  test::Random rng;
  int nonzero[5] = {0, 0, 0, 0, 0};
  for (int k = 0; k < 5; ++k) {
    const CaseOracle& o = kOracles[k];
    for (int trial = 0; trial < 20; ++trial) {
      Body body = random_case_body(o.c, rng);
      // Break the defining condition.
      switch (o.c) {
        case Case::euler: body.com = Vector3d(0.3, -0.2, 0.5); break;
        case Case::lagrange: body.com.x() = 0.3; break;
        case Case::kovalevskaya: body.inertia.z() *= 1.2; break;
        case Case::goryachev_chaplygin: body.com.z() = 0.4; break;
        case Case::hess: body.com.z() *= 1.3; break;
        default: break;
      }
      EXPECT_TRUE(broken_condition(o.c, body, InitialState{}).has_value()) << case_name(o.c);
      Vector3d w, g;
      random_state(o.c, body, rng, w, g);
      const Deriv d = o.deriv(body, at(body, w, g));
      if (std::abs(d.value) > 1e-6 * d.scale) ++nonzero[k];
    }
    EXPECT_GE(nonzero[k], 18) << case_name(o.c);
  }
}

TEST(Invariants, GoryachevChaplyginNeedsZeroArea) {
  // dG/dt = -(P a0 Omega2 / (4 I3^2)) C0 (docs/math.md eq. 2.1), so G drifts off C0 = 0.
  test::Random rng;
  for (int trial = 0; trial < 100; ++trial) {
    const Body body = random_case_body(Case::goryachev_chaplygin, rng);
    const Vector3d w = rng.vec(), g = rng.unit();
    const Point p = at(body, w, g);
    const double c0 = body.inertia.cwiseProduct(w).dot(g);
    const double expected =
        -body.weight * body.com.x() * w.y() / (4 * body.inertia.z() * body.inertia.z()) * c0;
    const Deriv d = d_gc(body, p);
    EXPECT_NEAR(d.value, expected, 1e-12 * d.scale);
    EXPECT_TRUE(broken_condition(Case::goryachev_chaplygin, body, InitialState{w, g}).has_value());
  }
}

TEST(Invariants, HessRelationDerivativeIsProportionalToH) {
  // dH/dt = Omega2 (a0 (I2 - I3) Omega3 + c0 (I1 - I2) Omega1) = mu H with
  // mu = Omega2 c0 (I1 - I2) / (I1 a0) under the Hess condition on c0.
  test::Random rng;
  for (int trial = 0; trial < 100; ++trial) {
    const Body body = random_case_body(Case::hess, rng);
    const Vector3d w = rng.vec(), g = rng.unit();
    const Deriv d = d_hess(body, at(body, w, g));
    const Vector3d& I = body.inertia;
    const double mu = w.y() * body.com.z() * (I.x() - I.y()) / (I.x() * body.com.x());
    EXPECT_NEAR(d.value, mu * hess_H(body, w, g),
                1e-12 * (d.scale + std::abs(mu * hess_H(body, w, g))));
  }
}

TEST(Invariants, ScalesAreMeaningfulForZeroInvariants) {
  const CasePreset& gc = preset(Case::goryachev_chaplygin);
  const Invariants s = invariant_scales(gc.body, gc.id, gc.initial.omega, gc.initial.gamma);
  const Invariants v = invariants(gc.body, gc.id, gc.initial.omega, gc.initial.gamma);
  EXPECT_EQ(s.gamma_norm2, 1.0);
  EXPECT_NEAR(s.area, gc.body.inertia.cwiseProduct(gc.initial.omega).norm(), 1e-15);
  EXPECT_GT(s.area, 1e6 * std::abs(v.area));
  const double e = 0.5 * gc.body.inertia.cwiseProduct(gc.initial.omega).dot(gc.initial.omega) +
                   gc.body.weight * gc.body.com.norm();
  EXPECT_NEAR(s.energy, std::max(e, std::abs(v.energy)), 1e-14);
  ASSERT_TRUE(s.extra.has_value());
  EXPECT_GT(*s.extra, 0.0);
  const CasePreset& h = preset(Case::hess);
  const Invariants sh = invariant_scales(h.body, h.id, h.initial.omega, h.initial.gamma);
  const double terms = std::abs(h.body.inertia.x() * h.body.com.x() * h.initial.omega.x()) +
                       std::abs(h.body.inertia.z() * h.body.com.z() * h.initial.omega.z());
  EXPECT_NEAR(*sh.extra, terms, 1e-15);
  EXPECT_GT(terms, 0.1);
  // A body at rest still gets positive scales.
  const Invariants rest =
      invariant_scales(Body{}, Case::euler, Vector3d::Zero(), Vector3d::UnitZ());
  EXPECT_GT(rest.area, 0);
  EXPECT_GT(rest.energy, 0);
  EXPECT_GT(*rest.extra, 0);
  EXPECT_FALSE(invariant_scales(Body{}, Case::generic, Vector3d::Ones(), Vector3d::UnitZ()).extra);
}

}  // namespace
}  // namespace epviz::physics
