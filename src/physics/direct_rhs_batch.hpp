#pragma once
// The direct Euler–Poisson right-hand side (direct.hpp) on W lanes in
// structure-of-arrays layout, for the batch steppers (numerics/batch_lanes.hpp).
// Free of Eigen so that the units compiled per instruction set
// (ensemble_<isa>.cpp) instantiate nothing but this and the kernels.
//
// Each lane performs the operations of DirectSystem::rhs and
// euler_omega_dot in their order, so that a lane's derivative is bitwise
// DirectSystem's (tests/sim/ensemble_test.cpp checks it).
namespace epviz::physics {

struct Body;

struct DirectBatchSystem {
  static constexpr int dim = 6;
  double inertia[3];      // I_i
  double inv_inertia[3];  // 1 / I_i
  double pr[3];           // P r

  // The constants as DirectSystem computes them (direct_batch.cpp).
  static DirectBatchSystem of(const Body& body);

  // x = (Omega, gamma); dxdt = (Omega', gamma x Omega). T: a double or a
  // vector of doubles (numerics/batch_lanes.hpp), lane by lane.
  template <class T>
  [[gnu::always_inline]] inline void rhs(const T& /*t*/, const T (&x)[6], T (&dxdt)[6]) const {
    const double d0 = inertia[1] - inertia[2], d1 = inertia[2] - inertia[0],
                 d2 = inertia[0] - inertia[1];
    const T w0 = x[0], w1 = x[1], w2 = x[2];
    const T g0 = x[3], g1 = x[4], g2 = x[5];
    dxdt[0] = (d0 * w1 * w2 + g1 * pr[2] - g2 * pr[1]) * inv_inertia[0];
    dxdt[1] = (d1 * w2 * w0 + g2 * pr[0] - g0 * pr[2]) * inv_inertia[1];
    dxdt[2] = (d2 * w0 * w1 + g0 * pr[1] - g1 * pr[0]) * inv_inertia[2];
    dxdt[3] = w2 * g1 - w1 * g2;
    dxdt[4] = w0 * g2 - w2 * g0;
    dxdt[5] = w1 * g0 - w0 * g1;
  }
};

}  // namespace epviz::physics
