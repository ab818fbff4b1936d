// The bifurcation diagram (physics/critical_values.hpp): its curves follow
// their closed forms; an independent search for critical states
// (critical_oracle.hpp) finds only values on the drawn curves, and finds a
// state for the drawn points it is asked about; values off the curves are not
// critical, so that the checks can fail.
#include "physics/critical_values.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "physics/critical_oracle.hpp"

namespace epviz::physics {
namespace {

using test::IntegralsAt;

// The distance from p to the drawn curve: to its segments between finite
// points, and to each point (an isolated one, or a part's end).
double distance(const ValuePoint& p, const CriticalCurve& curve) {
  const Eigen::Vector2d q(p.energy, p.integral);
  double best = std::numeric_limits<double>::infinity();
  const auto& pts = curve.points;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector2d a(pts[i].energy, pts[i].integral);
    if (!a.allFinite()) continue;
    best = std::min(best, (q - a).norm());
    if (i + 1 == pts.size() || !std::isfinite(pts[i + 1].energy)) continue;
    const Eigen::Vector2d b(pts[i + 1].energy, pts[i + 1].integral);
    const double t = std::clamp((q - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (q - a - t * (b - a)).norm());
  }
  return best;
}

double distance(const ValuePoint& p, const BifurcationDiagram& d) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& c : d.curves) best = std::min(best, distance(p, c));
  return best;
}

// The same as a fraction of the figure: energies and integrals divided by the
// spans the curves cover.
double figure_distance(const ValuePoint& p, const BifurcationDiagram& d) {
  double k0 = std::numeric_limits<double>::infinity(), k1 = -k0;
  for (const auto& c : d.curves)
    for (const auto& q : c.points)
      if (std::isfinite(q.integral)) k0 = std::min(k0, q.integral), k1 = std::max(k1, q.integral);
  const double sx = d.energy_max - d.energy_min, sy = k1 - k0;
  BifurcationDiagram scaled = d;
  for (auto& c : scaled.curves)
    for (auto& q : c.points) q = {q.energy / sx, q.integral / sy};
  return distance({p.energy / sx, p.integral / sy}, scaled);
}

// The real roots of s³ − h s² + ℓ²/4 (the parametric curve's parameters at h).
std::vector<double> cubic_roots(double h, double l) {
  Eigen::Matrix3d companion;
  companion << h, 0, -l * l / 4, 1, 0, 0, 0, 1, 0;
  std::vector<double> roots;
  for (const auto& r : companion.eigenvalues())
    if (std::abs(r.imag()) <= 1e-7 * (1 + std::abs(r.real()))) roots.push_back(r.real());
  return roots;
}

// How far (h, k) is from the named closed-form curve of the normalised
// Kovalevskaya top at area l (in k, at the same h).
double closed_form_miss(const std::string& id, ValuePoint p, double l) {
  const double h = p.energy, k = p.integral;
  if (id == "class_I") return std::abs(k);
  if (id == "class_II") return std::abs(k - (h - l * l / 2) * (h - l * l / 2));
  double best = std::numeric_limits<double>::infinity();
  // At l = 0 the parts near s = 0 tend to k = 1 + h², h >= 0 (s = ∓l/(2√h), l → 0).
  if (l == 0 && id == "s_negative" && h >= 0) best = std::abs(k - 1 - h * h);
  for (double s : l == 0 ? std::vector<double>{h} : cubic_roots(h, l)) {
    if ((id == "s_negative") != (s < 0)) continue;
    const double ks = 1 - l * l / (2 * s) + std::pow(l, 4) / (16 * std::pow(s, 4));
    best = std::min(best, std::abs(k - ks));
  }
  return best;
}

// Critical values found by the oracle from `starts` random starts, up to energy_max.
std::vector<ValuePoint> oracle_values(const IntegralsAt& f, double area, double energy_max,
                                      int starts, double omega_max) {
  std::mt19937_64 random(2024);
  std::vector<ValuePoint> values;
  for (int i = 0; i < starts; ++i) {
    const auto x = test::oracle_search(f, area, test::random_oracle_start(random, omega_max));
    if (!x) continue;
    const auto v = f(*x).value;
    if (v(1) <= energy_max) values.push_back({v(1), v(2)});
  }
  return values;
}

// Whether the oracle finds a state critical with exactly this value.
bool oracle_attains(const IntegralsAt& f, double area, ValuePoint p, int starts, double omega_max) {
  std::mt19937_64 random(77);
  for (int i = 0; i < starts; ++i)
    if (test::oracle_search(f, area, test::random_oracle_start(random, omega_max),
                            Eigen::Vector2d(p.energy, p.integral)))
      return true;
  return false;
}

DiagramRequest kovalevskaya_request(double area) {
  DiagramRequest r;
  r.case_id = Case::kovalevskaya;
  r.body = preset(Case::kovalevskaya).body;
  r.area = area;
  r.samples = 2000;
  return r;
}

TEST(KovalevskayaDiagram, EveryPointLiesOnItsClosedFormCurve) {
  const auto d = bifurcation_diagram(kovalevskaya_request(0.5));
  int drawn = 0;
  for (const auto& c : d.curves) {
    drawn += !c.points.empty();
    for (const auto& p : c.points) {
      if (!std::isfinite(p.energy)) continue;
      EXPECT_LE(closed_form_miss(c.id, p, 0.5), 1e-6 * (1 + std::abs(p.integral)))
          << c.id << " at (" << p.energy << ", " << p.integral << ")";
    }
  }
  EXPECT_GE(drawn, 3);
  // The check can fail: a point of one curve is off the others.
  EXPECT_GT(closed_form_miss("class_II", {1.0, 0.3}, 0.5), 0.1);
}

// The least energy of the states with K = 0 at area l (preset body), by a
// scan over γ: there Ω1 + iΩ2 = ±√(γ1 + iγ2), Ω3 follows from C0 = l, and
// every state is critical (∇K = 0 where K = 0). Towards γ3 = 0 the energy
// grows without bound, so on each hemisphere the energies of K = 0 fill
// [least, ∞): a value (h, 0) is attained iff h is at least this.
double class_one_floor(double l) {
  double best = std::numeric_limits<double>::infinity();
  const int n = 300;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double th = std::numbers::pi * (i + 0.5) / n, ph = std::numbers::pi * j / n;
      const double g1 = std::sin(th) * std::cos(ph), g2 = std::sin(th) * std::sin(ph),
                   g3 = std::cos(th);
      const std::complex<double> w = std::sqrt(std::complex<double>(g1, g2));
      for (const double sign : {1.0, -1.0}) {
        const double o1 = sign * w.real(), o2 = sign * w.imag();
        const double o3 = (l - 2 * (o1 * g1 + o2 * g2)) / g3;
        best = std::min(best, o1 * o1 + o2 * o2 + o3 * o3 / 2 + g1);
      }
    }
  return best;
}

// At a small and a large area: at 3 the cusp of the s > 0 branch and class
// II past ℓ²/2 are not attained, and are not drawn.
class KovalevskayaOracle : public ::testing::TestWithParam<double> {};

TEST_P(KovalevskayaOracle, CriticalValuesLieOnTheDrawnCurves) {
  const double area = GetParam();
  const auto d = bifurcation_diagram(kovalevskaya_request(area));
  const auto f = test::kovalevskaya_integrals(1, 1, 1);
  const auto values = oracle_values(f, area, d.energy_max, 300, 1.5 + area);
  ASSERT_GE(values.size(), 30u);
  double worst = 0;
  for (const auto& v : values) {
    worst = std::max(worst, figure_distance(v, d));
    EXPECT_LT(figure_distance(v, d), 0.002)
        << "critical value (" << v.energy << ", " << v.integral << ") is on no drawn curve";
  }
  std::printf("%zu critical values, farthest %.2g of the figure from a drawn curve\n",
              values.size(), worst);
}

TEST_P(KovalevskayaOracle, DrawnPointsAreAttainedAndOthersAreNot) {
  const double area = GetParam();
  const auto d = bifurcation_diagram(kovalevskaya_request(area));
  const auto f = test::kovalevskaya_integrals(1, 1, 1);
  const double floor = class_one_floor(area);
  int attained = 0, off_curve = 0;
  for (const auto& c : d.curves) {
    for (std::size_t i = 0; i < c.points.size(); i += 37) {
      const auto p = c.points[i];
      if (!std::isfinite(p.energy)) continue;
      ++attained;
      // K = 0 is a double root of K − k, where Gauss–Newton crawls: the scan above instead.
      const bool reached = c.id == "class_I" ? p.energy >= floor - 1e-6 * (1 + floor)
                                             : oracle_attains(f, area, p, 60, 1.5 + area);
      EXPECT_TRUE(reached) << c.id << ": (" << p.energy << ", " << p.integral
                           << ") is drawn but not attained";
      // Moved off the curve, the same value is not critical.
      const ValuePoint off{p.energy, p.integral + 0.15 * (1 + std::abs(p.integral))};
      if (distance(off, d) < 0.1) continue;
      ++off_curve;
      EXPECT_FALSE(oracle_attains(f, area, off, 20, 1.5 + area))
          << "(" << off.energy << ", " << off.integral << ") is critical";
    }
  }
  EXPECT_GE(attained, 25);
  EXPECT_GE(off_curve, 15);
}

INSTANTIATE_TEST_SUITE_P(Areas, KovalevskayaOracle, ::testing::Values(0.0, 0.5, 3.0, 5.0, 8.0));

TEST(KovalevskayaDiagram, ScaledBodyFollowsTheNormalisedCurves) {
  // I = (4, 4, 2), a0 = −0.5, P = 3: ε = 0.75, C1 = c ε h̃, C0 = c √ε ℓ̃, K = ε² k̃.
  DiagramRequest r = kovalevskaya_request(0.8);
  r.body = Body{Eigen::Vector3d(4, 4, 2), Eigen::Vector3d(-0.5, 0, 0), 3.0};
  const auto d = bifurcation_diagram(r);
  const double eps = 0.75, c = 2;
  const double l = 0.8 / (c * std::sqrt(eps));
  int drawn = 0;
  for (const auto& curve : d.curves) {
    drawn += !curve.points.empty();
    for (const auto& p : curve.points) {
      if (!std::isfinite(p.energy)) continue;
      EXPECT_LE(closed_form_miss(curve.id, {p.energy / (c * eps), p.integral / (eps * eps)}, l),
                1e-6 * (1 + std::abs(p.integral)))
          << curve.id;
    }
  }
  EXPECT_GE(drawn, 3);
  // The body's own critical values, found with its own integrals, are on them.
  const auto values =
      oracle_values(test::kovalevskaya_integrals(2, -0.5, 3), 0.8, d.energy_max, 150, 1.5);
  ASSERT_GE(values.size(), 10u);
  for (const auto& v : values) EXPECT_LT(figure_distance(v, d), 0.002);
}

DiagramRequest lagrange_request(double area) {
  DiagramRequest r;
  r.case_id = Case::lagrange;
  r.body = preset(Case::lagrange).body;  // A = 2, C = 1, P z0 = 4
  r.area = area;
  r.samples = 2000;
  return r;
}

// How far (h, n) is from being a steady precession: the least over u in
// (−1, 1) of |V'(u) (1 − u²)² A| + |V(u) − h| at spin n, from a scan in
// u = −cos θ (dense towards u = ±1) refined by golden sections.
double lagrange_miss(ValuePoint p, double area, double a, double c, double pz) {
  const double n = p.integral;
  const auto misfit = [&](double theta) {
    const double u = -std::cos(theta);
    const double dv = c * c * u * n * n - c * area * (1 + u * u) * n + area * area * u +
                      pz * a * (1 - u * u) * (1 - u * u);
    const double v =
        0.5 * c * n * n + std::pow(area - c * n * u, 2) / (2 * a * (1 - u * u)) + pz * u;
    return std::abs(dv) + std::abs(v - p.energy);
  };
  const int steps = 20000;
  const double dt = std::numbers::pi / steps;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 1; i < steps; ++i) {
    const double t = i * dt;
    if (!(misfit(t) <= misfit(t - dt) && misfit(t) <= misfit(t + dt))) continue;
    double lo = std::max(t - dt, 1e-12), hi = std::min(t + dt, std::numbers::pi - 1e-12);
    for (int k = 0; k < 200; ++k) {
      const double m1 = lo + (hi - lo) * 0.382, m2 = lo + (hi - lo) * 0.618;
      (misfit(m1) < misfit(m2) ? hi : lo) = misfit(m1) < misfit(m2) ? m2 : m1;
    }
    best = std::min(best, misfit(0.5 * (lo + hi)));
  }
  return best;
}

TEST(LagrangeDiagram, CurvesAreSteadyPrecessionsAndSleepingTops) {
  for (const double area : {5.0, 7.0, -3.0}) {
    const auto d = bifurcation_diagram(lagrange_request(area));
    int tops = 0;
    for (const auto& c : d.curves) {
      if (c.isolated) {
        ++tops;
        ASSERT_EQ(c.points.size(), 1u);
        const double u = c.id == "sleeping_up" ? 1 : -1;
        EXPECT_NEAR(c.points[0].integral, area / u, 1e-12);
        EXPECT_NEAR(c.points[0].energy, 0.5 * area * area + 4 * u, 1e-12);
        continue;
      }
      EXPECT_FALSE(c.points.empty()) << c.id;
      for (std::size_t i = 0; i < c.points.size(); i += 7) {
        if (!std::isfinite(c.points[i].energy)) continue;
        EXPECT_LE(lagrange_miss(c.points[i], area, 2, 1, 4), 1e-6 * (1 + c.points[i].energy))
            << c.id << " at area " << area;
      }
    }
    EXPECT_EQ(tops, 2);
    EXPECT_GT(lagrange_miss({d.energy_min + 1.0, 0.3}, area, 2, 1, 4), 1e-3);  // can fail
  }
}

TEST(LagrangeDiagram, OracleCriticalValuesLieOnTheDrawnCurves) {
  const double area = 5.0;
  const auto d = bifurcation_diagram(lagrange_request(area));
  const auto f = test::lagrange_integrals(2, 1, 4);
  const auto values = oracle_values(f, area, d.energy_max, 300, 4.0);
  ASSERT_GE(values.size(), 20u);
  double worst = 0;
  for (const auto& v : values) {
    worst = std::max(worst, figure_distance(v, d));
    EXPECT_LT(figure_distance(v, d), 0.002)
        << "critical value (" << v.energy << ", " << v.integral << ") is on no drawn curve";
  }
  std::printf("%zu critical values, farthest %.2g of the figure from a drawn curve\n",
              values.size(), worst);
  for (const auto& c : d.curves)
    for (std::size_t i = 0; i < c.points.size(); i += 301) {
      const auto p = c.points[i];
      if (!std::isfinite(p.energy) || c.isolated) continue;
      EXPECT_TRUE(oracle_attains(f, area, p, 60, 4.0)) << c.id;
      const ValuePoint off{p.energy + 0.7, p.integral};
      if (distance(off, d) > 0.3) {
        EXPECT_FALSE(oracle_attains(f, area, off, 20, 4.0));
      }
    }
}

TEST(DiagramRequest, RefusesWhatHasNoDiagram) {
  const auto field_of = [](DiagramRequest r) -> std::string {
    try {
      check_diagram_request(r);
    } catch (const InvalidInput& e) {
      return e.field();
    }
    return "accepted";
  };
  auto r = kovalevskaya_request(0.5);
  EXPECT_EQ(field_of(r), "accepted");
  r.case_id = Case::euler;
  EXPECT_EQ(field_of(r), "case");
  r = kovalevskaya_request(0.5);
  r.body.inertia.z() = 1.5;
  EXPECT_EQ(field_of(r), "body");
  r = kovalevskaya_request(0.5);
  r.body.com.x() = 0;  // ε = 0
  EXPECT_EQ(field_of(r), "body");
  r = kovalevskaya_request(std::numeric_limits<double>::infinity());
  EXPECT_EQ(field_of(r), "area");
  r = kovalevskaya_request(-8.01);  // past the areas the search is checked at
  EXPECT_EQ(field_of(r), "area");
  r = kovalevskaya_request(0.5);
  r.energy_max = -2.0;  // below the least energy (about −0.94)
  EXPECT_EQ(field_of(r), "energy_max");
  r = lagrange_request(5.0);
  r.body.com.x() = 0.1;
  EXPECT_EQ(field_of(r), "body");
}

TEST(DiagramSamples, AreReproducibleStatesOfTheLevel) {
  const auto a = bifurcation_diagram(kovalevskaya_request(0.5));
  const auto b = bifurcation_diagram(kovalevskaya_request(0.5));
  ASSERT_EQ(a.sampled.size(), 2000u);
  for (std::size_t i = 0; i < a.sampled.size(); ++i) {
    EXPECT_EQ(a.sampled[i].energy, b.sampled[i].energy);
    EXPECT_LE(a.sampled[i].energy, a.energy_max);
    EXPECT_GE(a.sampled[i].energy, a.energy_min - 1e-9);
    EXPECT_GE(a.sampled[i].integral, 0.0);
  }
}

}  // namespace
}  // namespace epviz::physics
