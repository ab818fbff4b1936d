#pragma once
// Test-only helpers: a classical RK4 written independently of src/, and random states and bodies.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <random>

#include "physics/body.hpp"

namespace epviz::physics::test {

// One classical Runge-Kutta step of x' = f(t, x) for any Eigen vector or matrix type.
template <class X, class F>
X rk4_step(const F& f, double t, const X& x, double h) {
  const X k1 = f(t, x);
  const X k2 = f(t + 0.5 * h, X(x + 0.5 * h * k1));
  const X k3 = f(t + 0.5 * h, X(x + 0.5 * h * k2));
  const X k4 = f(t + h, X(x + h * k3));
  return x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

// Integrates from t0 to t1 in n equal RK4 steps.
template <class X, class F>
X rk4(const F& f, double t0, double t1, X x, int n) {
  const double h = (t1 - t0) / n;
  for (int i = 0; i < n; ++i) x = rk4_step(f, t0 + i * h, x, h);
  return x;
}

struct Random {
  std::mt19937_64 gen{12345};
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(gen);
  }
  Eigen::Vector3d vec(double lo = -2.0, double hi = 2.0) {
    return Eigen::Vector3d(uniform(lo, hi), uniform(lo, hi), uniform(lo, hi));
  }
  Eigen::Vector3d unit() {
    Eigen::Vector3d v;
    do v = vec(-1.0, 1.0);
    while (v.norm() < 0.1 || v.norm() > 1.0);
    return v.normalized();
  }
};

// A body with moments in [0.5, 3], centre of mass in [-1, 1]^3 and weight in
// [0.5, 2]: generic, with no symmetry to hide a wrong term.
inline Body random_body(Random& rng) {
  return Body{rng.vec(0.5, 3.0), rng.vec(-1.0, 1.0), rng.uniform(0.5, 2.0)};
}

}  // namespace epviz::physics::test
