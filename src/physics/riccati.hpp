#pragma once
// The Riccati formulation (math.md section 3, Ershkov): state (Omega, a, b),
// 5 dimensions. The Poisson equations become the Riccati pair (3.5) for
// eta = a + i b (north chart) or, near the south pole gamma3 = -1 where eta
// has a pole, the Riccati equation w' = -delta w^2 - beta w - alpha for
// w = 1/eta (south chart), stored in the same two slots as (Re w, Im w).
#include <Eigen/Core>
#include <complex>
#include <optional>

#include "numerics/system.hpp"
#include "physics/body.hpp"
#include "physics/direct.hpp"
#include "physics/stereographic.hpp"

namespace epviz::physics {

enum class Chart { north, south };

class RiccatiSystem {
 public:
  static constexpr int dim = 5;
  using State = Eigen::Matrix<double, 5, 1>;
  static constexpr const char* name = "riccati";

  // Hysteresis band of the chart switch: north -> south when |eta| > switch_radius,
  // south -> north when |w| > switch_radius.
  static constexpr double switch_radius = 2.0;
  // Without chart switching, check() reports a pole once |eta| exceeds this.
  static constexpr double pole_radius = 1e6;

  explicit RiccatiSystem(const Body& body, bool chart_switch = true)
      : inertia_(body.inertia),
        inv_inertia_(body.inertia.cwiseInverse()),
        pr_(body.weight * body.com),
        chart_switch_(chart_switch) {}

  // x = (Omega, a, b) in the current chart.
  [[gnu::always_inline]] void rhs(double /*t*/, const State& x, State& dxdt) const {
    const Vector3d w = x.head<3>();
    const double a = x[3], b = x[4];
    const double d = a * a - b * b, ab = a * b;
    const Vector3d g = gamma(x);
    dxdt.head<3>() = euler_omega_dot(inertia_, inv_inertia_, pr_, w, g);
    if (chart_ == Chart::north) {  // (3.5)
      dxdt[3] = 0.5 * w.y() * (d + 1.0) - w.x() * ab + w.z() * b;
      dxdt[4] = 0.5 * w.x() * (d - 1.0) + w.y() * ab - w.z() * a;
    } else {  // w' = -delta w^2 - beta w - alpha, with (a, b) = (Re w, Im w)
      dxdt[3] = -0.5 * w.y() * (d + 1.0) - w.x() * ab - w.z() * b;
      dxdt[4] = 0.5 * w.x() * (d - 1.0) - w.y() * ab + w.z() * a;
    }
  }

  // Picks the chart by |eta| <= 1 (north) and sets it; without chart switching
  // always the north chart, the paper's (a, b) (a start at the south pole
  // itself is then a pole, reported by check()). The chart is part of the
  // integration state; it is mutable so that pack() works on a const system.
  State pack(const InitialState& s) const {
    State x;
    x.head<3>() = s.omega;
    const Vector3d& g = s.gamma;
    if (g.z() >= 0.0 || !chart_switch_) {  // |eta| <= 1: eta = -(g1 + i g2) / (1 + g3)
      chart_ = Chart::north;
      x[3] = -g.x() / (1.0 + g.z());
      x[4] = -g.y() / (1.0 + g.z());
    } else {  // w = 1/eta = -(g1 - i g2) / (1 - g3)
      chart_ = Chart::south;
      x[3] = -g.x() / (1.0 - g.z());
      x[4] = g.y() / (1.0 - g.z());
    }
    return x;
  }

  Vector3d omega(const State& x) const { return x.head<3>(); }

  // Unit vertical of the state in the current chart.
  [[gnu::always_inline]] Vector3d gamma(const State& x) const {
    return gamma_in(chart_, x[3], x[4]);
  }

  [[gnu::always_inline]] static Vector3d gamma_in(Chart chart, double a, double b) {
    if (chart == Chart::north) return from_stereographic(a, b);
    const double r2 = a * a + b * b;
    const double inv = 1.0 / (1.0 + r2);
    return Vector3d(-2.0 * a * inv, 2.0 * b * inv, (r2 - 1.0) * inv);
  }

  // eta = a + i b in the north chart whatever the current chart (infinite at the
  // south pole): the point drawn on the Riccati plane.
  std::complex<double> eta(const State& x) const {
    const std::complex<double> z(x[3], x[4]);
    return chart_ == Chart::north ? z : 1.0 / z;
  }

  // With chart switching: north -> south when |eta| > 2, south -> north when
  // |w| > 2; maps (a, b) by the inversion 1/z so that gamma is unchanged.
  // Returns true when it switched.
  bool regularize(State& x) {
    if (!chart_switch_) return false;
    const double r2 = x[3] * x[3] + x[4] * x[4];
    if (!(r2 > switch_radius * switch_radius)) return false;
    x[3] = x[3] / r2;
    x[4] = -x[4] / r2;
    chart_ = chart_ == Chart::north ? Chart::south : Chart::north;
    ++switches_;
    return true;
  }

  // Without chart switching: reports the pole once |eta| > 1e6.
  std::optional<numerics::Issue> check(const State& x) const {
    if (chart_switch_) return std::nullopt;
    const double r2 = x[3] * x[3] + x[4] * x[4];
    if (!(r2 > pole_radius * pole_radius)) return std::nullopt;
    return numerics::Issue{
        numerics::FailureKind::chart_pole,
        "Riccati coordinates (a, b) pass a pole near the south pole gamma3 = -1"};
  }

  Chart chart() const { return chart_; }
  void set_chart(Chart c) { chart_ = c; }
  bool chart_switch() const { return chart_switch_; }
  long chart_switches() const { return switches_; }

 private:
  Vector3d inertia_;
  Vector3d inv_inertia_;
  Vector3d pr_;
  bool chart_switch_;
  mutable Chart chart_ = Chart::north;
  long switches_ = 0;
};

}  // namespace epviz::physics
