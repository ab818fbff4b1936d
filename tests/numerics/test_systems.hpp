#pragma once
// Small ODE systems with closed-form solutions (the oracles of the numerics
// tests). Each is written here, independently of src/physics.
#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "numerics/system.hpp"

namespace epviz::numerics::testing {

// Harmonic oscillator q' = p, p' = -w^2 q; also split into drift and kick.
struct Oscillator {
  static constexpr int dim = 2;
  static constexpr int n_flows = 2;
  using State = Vec<2>;
  double w = 1.0;
  void rhs(double, const State& x, State& dx) const {
    dx[0] = x[1];
    dx[1] = -w * w * x[0];
  }
  void flow(int i, double h, State& x) const {
    if (i == 0)
      x[0] += h * x[1];
    else
      x[1] -= h * w * w * x[0];
  }
  // Exact solution from (1, 0) at t = 0.
  State exact(double t) const { return State(std::cos(w * t), -w * std::sin(w * t)); }
  double energy(const State& x) const { return 0.5 * (x[1] * x[1] + w * w * x[0] * x[0]); }
};

// Linear x' = A x, A = [[-0.5, 2], [-2, -0.5]]: a decaying rotation.
struct DecayingRotation {
  static constexpr int dim = 2;
  using State = Vec<2>;
  void rhs(double, const State& x, State& dx) const {
    dx[0] = -0.5 * x[0] + 2.0 * x[1];
    dx[1] = -2.0 * x[0] - 0.5 * x[1];
  }
  // From (1, 0) at t = 0.
  static State exact(double t) {
    const double r = std::exp(-0.5 * t);
    return State(r * std::cos(2.0 * t), -r * std::sin(2.0 * t));
  }
};

// Non-autonomous scalar y' = -y^2 + cos t ... kept simple: y' = -2 t y^2,
// y(0) = 1 -> y = 1 / (1 + t^2).
struct TimeDependentRiccati {
  static constexpr int dim = 1;
  using State = Vec<1>;
  void rhs(double t, const State& x, State& dx) const { dx[0] = -2.0 * t * x[0] * x[0]; }
  static State exact(double t) { return State(1.0 / (1.0 + t * t)); }
};

// Non-autonomous linear y' = 3 cos(3t) y, y(0) = 1 -> y = exp(sin 3t).
struct ExpSin {
  static constexpr int dim = 1;
  using State = Vec<1>;
  void rhs(double t, const State& x, State& dx) const { dx[0] = 3.0 * std::cos(3.0 * t) * x[0]; }
  static State exact(double t) { return State(std::exp(std::sin(3.0 * t))); }
};

// Kepler problem (mu = 1), semi-major axis 1, eccentricity e, starting at
// periapsis. State (q1, q2, p1, p2). Split into drift (q += h p) and kick.
struct Kepler {
  static constexpr int dim = 4;
  static constexpr int n_flows = 2;
  using State = Vec<4>;
  double e = 0.5;
  void rhs(double, const State& x, State& dx) const {
    const double r2 = x[0] * x[0] + x[1] * x[1];
    const double r3 = r2 * std::sqrt(r2);
    dx[0] = x[2];
    dx[1] = x[3];
    dx[2] = -x[0] / r3;
    dx[3] = -x[1] / r3;
  }
  void flow(int i, double h, State& x) const {
    if (i == 0) {
      x[0] += h * x[2];
      x[1] += h * x[3];
    } else {
      const double r2 = x[0] * x[0] + x[1] * x[1];
      const double r3 = r2 * std::sqrt(r2);
      x[2] -= h * x[0] / r3;
      x[3] -= h * x[1] / r3;
    }
  }
  State initial() const { return State(1.0 - e, 0.0, 0.0, std::sqrt((1.0 + e) / (1.0 - e))); }
  // Closed form through Kepler's equation E - e sin E = t (period 2 pi).
  State exact(double t) const {
    long double E = t, ee = e;
    for (int k = 0; k < 100; ++k) {
      const long double dE = (E - ee * std::sin(E) - t) / (1.0L - ee * std::cos(E));
      E -= dE;
      if (std::abs(dE) < 1e-19L) break;
    }
    const long double s = std::sqrt(1.0L - ee * ee), den = 1.0L - ee * std::cos(E);
    return State(double(std::cos(E) - ee), double(s * std::sin(E)), double(-std::sin(E) / den),
                 double(s * std::cos(E) / den));
  }
  double energy(const State& x) const {
    return 0.5 * (x[2] * x[2] + x[3] * x[3]) - 1.0 / std::sqrt(x[0] * x[0] + x[1] * x[1]);
  }
  double angular_momentum(const State& x) const { return x[0] * x[3] - x[1] * x[2]; }
};

// Heavy rigid body about a fixed point (Euler–Poisson), state (Omega, gamma).
// Three quadratic first integrals: |gamma|^2, the area integral, the energy.
struct HeavyTop {
  static constexpr int dim = 6;
  using State = Vec<6>;
  double I1 = 1.0, I2 = 1.5, I3 = 2.2;  // satisfies the triangle inequalities
  double P = 1.0, a0 = 0.3, b0 = -0.2, c0 = 0.5;
  double i1 = 1.0 / I1, i2 = 1.0 / I2, i3 = 1.0 / I3;  // inverses (keep in sync)
  void rhs(double, const State& x, State& dx) const {
    const double w1 = x[0], w2 = x[1], w3 = x[2], g1 = x[3], g2 = x[4], g3 = x[5];
    dx[0] = ((I2 - I3) * w2 * w3 + P * (g2 * c0 - g3 * b0)) * i1;
    dx[1] = ((I3 - I1) * w3 * w1 + P * (g3 * a0 - g1 * c0)) * i2;
    dx[2] = ((I1 - I2) * w1 * w2 + P * (g1 * b0 - g2 * a0)) * i3;
    dx[3] = w3 * g2 - w2 * g3;
    dx[4] = w1 * g3 - w3 * g1;
    dx[5] = w2 * g1 - w1 * g2;
  }
  static State initial() {
    State x;
    x << 0.7, -0.4, 1.1, 0.0, 0.6, 0.8;
    return x;
  }
  double gamma2(const State& x) const { return x.tail<3>().squaredNorm(); }
  double area(const State& x) const {
    return I1 * x[0] * x[3] + I2 * x[1] * x[4] + I3 * x[2] * x[5];
  }
  double energy(const State& x) const {
    return 0.5 * (I1 * x[0] * x[0] + I2 * x[1] * x[1] + I3 * x[2] * x[2]) +
           P * (a0 * x[3] + b0 * x[4] + c0 * x[5]);
  }
};

// y' = y^2 from y(0) = 1: y = 1 / (1 - t), blows up at t = 1.
struct BlowUp {
  static constexpr int dim = 1;
  using State = Vec<1>;
  void rhs(double, const State& x, State& dx) const { dx[0] = x[0] * x[0]; }
};

// y' = exp(y): blows up in finite time, and overflows quickly with a big step.
struct ExpBlowUp {
  static constexpr int dim = 1;
  using State = Vec<1>;
  void rhs(double, const State& x, State& dx) const { dx[0] = std::exp(x[0]); }
};

// y' = lambda y (stiff for large |lambda|).
struct Linear1 {
  static constexpr int dim = 1;
  using State = Vec<1>;
  double lambda = -1000.0;
  void rhs(double, const State& x, State& dx) const { dx[0] = lambda * x[0]; }
};

// Observed orders log2(e(h) / e(h/2)) for the errors e of a step-halving study.
inline std::vector<double> observed_orders(const std::vector<double>& errors) {
  std::vector<double> p;
  for (std::size_t i = 0; i + 1 < errors.size(); ++i)
    p.push_back(std::log2(errors[i] / errors[i + 1]));
  return p;
}

}  // namespace epviz::numerics::testing
