#pragma once
// The structure-of-arrays state of W trajectories advanced side by side by the
// batch steppers (batch_driver.hpp): component i of lane l at [i][l], so that
// one loop over the lanes is one vector operation.
//
// The arithmetic on these arrays (batch_kernel.hpp) is compiled once per
// instruction set; the step-size control, the queue of trajectories and the
// output (batch_driver.hpp) once, with the default flags. The two halves meet
// through EmbeddedKernels / Rk4Kernel, plain function pointers, so that no
// inline function compiled for a wider instruction set can be picked by the
// linker for code that runs on any CPU.
#include <utility>

#include "numerics/rk_tableaus.hpp"

namespace epviz::numerics {

// A system the batch steppers can advance (e.g. physics/direct_rhs_batch.hpp):
//
//   static constexpr int dim = D;     // an even dimension (see eigen_order_sum)
//   template <class T>
//   [[gnu::always_inline]] void rhs(const T& t, const T (&x)[D], T (&dxdt)[D]) const;
//
// T is a double or a vector of W doubles (GCC's and clang's vector extension),
// so rhs is written once with +, -, * and / only, and acts on each lane alone.
// It must be always_inline: it is compiled into each instruction set's kernel.
template <class Sys>
concept BatchSystem = (Sys::dim > 0) && (Sys::dim % 2 == 0) && requires(const Sys& s) {
  s.rhs(std::declval<const double&>(), std::declval<const double(&)[Sys::dim]>(),
        std::declval<double(&)[Sys::dim]>());
};

// Whether the method's error estimate uses f(t + h, xnew), the first stage of
// the next step: then every attempt evaluates it, else only accepted ones do
// (as EmbeddedRk, whose evaluation counts the batch reports).
template <class Tableau>
inline constexpr bool error_needs_fsal_v =
    Tableau::e[Tableau::stages] != 0.0 || Tableau::e2[Tableau::stages] != 0.0;

// Lanes of an embedded Runge–Kutta method (Tableau as in rk_tableaus.hpp).
template <int D, int W, class Tableau>
struct EmbeddedLanes {
  static constexpr int N = Tableau::total;
  static constexpr int M = 4 + Tableau::dense_rows;
  alignas(64) double x[D][W];        // state at t
  alignas(64) double x_prev[D][W];   // state at the start of the last accepted step
  alignas(64) double xnew[D][W];     // trial state at t + h
  alignas(64) double acc[D][W];      // sum_j b_j k_j of the trial step
  alignas(64) double k[N][D][W];     // stages; k[0] = f(t, x)
  alignas(64) double cont[M][D][W];  // dense output coefficients of the last accepted step
  alignas(64) double t[W];
  alignas(64) double t_prev[W];
  alignas(64) double h[W];       // size of the trial step
  alignas(64) double h_last[W];  // size of the last accepted step
  alignas(64) double err[W];     // error norm of the trial step (<= 1: accepted)
  // 1 / err^(1/8): the step-size factor of an eighth-order controller without
  // beta (the driver's err_power), for every lane in one vector.
  alignas(64) double err_root8[W];
  alignas(64) long long trial_finite[W];  // nonzero when err and xnew are all finite
  alignas(64) long long accept[W];        // set by the driver: ~0 for each lane accepted
  double atol = 0, rtol = 0;
};

// W trajectories about to start: their first derivative and initial step
// size, computed together before their lanes take them.
template <int D, int W>
struct StartLanes {
  alignas(64) double x[D][W];   // x0
  alignas(64) double t[W];      // t0
  alignas(64) double k0[D][W];  // f(t0, x0)
  alignas(64) double h0[W];     // the initial step size guess
  double atol = 0, rtol = 0, h_max = 0;
};

// What one instruction set's kernel does to embedded-method lanes.
template <class Sys, int W, class Tableau>
struct EmbeddedKernels {
  using Lanes = EmbeddedLanes<Sys::dim, W, Tableau>;
  using Starts = StartLanes<Sys::dim, W>;
  // k0 and h0 from x and t, h0 as EmbeddedRk::initial_step (Hairer's HINIT);
  // each lane's inputs may be anything, NaN included.
  void (*start)(Starts&, const Sys&);
  // Stages 1 .. S-1 from (t, x) with k[0] set and step h, then xnew, acc,
  // k[S] = f(t + h, xnew), err, err_root8 and trial_finite; every lane,
  // whether it will be accepted or not.
  void (*attempt)(Lanes&, const Sys&);
  // The accepted lanes (accept) move on: t_prev, x_prev = t, x; t, x =
  // t + h, xnew; h_last = h. The others are left as they are.
  void (*commit)(Lanes&);
  // cont from x_prev, x, k[0 .. S] and h_last of every lane (the extra stages
  // of the continuous extension are evaluated into k[S+1 ..]).
  void (*dense)(Lanes&, const Sys&);
  // First same as last: k[0] = k[S] in the accepted lanes.
  void (*fsal)(Lanes&);
};

// Lanes of the classical fourth-order Runge–Kutta method.
template <int D, int W>
struct Rk4Lanes {
  alignas(64) double x[D][W];
  alignas(64) double xnew[D][W];  // x + h (k1 + 2 (k2 + k3) + k4) / 6
  alignas(64) double t[W];
  alignas(64) double h[W];
};

template <class Sys, int W>
struct Rk4Kernel {
  void (*step)(Rk4Lanes<Sys::dim, W>&, const Sys&);  // xnew from (t, x) with step h
};

// sum_i q[i] in the order Eigen's fixed-size sum() adds a vector of even size
// D with two-double packets (SSE2, the plain x86-64 build of the scalar
// steppers): the packets (q0, q1), (q2, q3), ... are added by halving the list,
// p0 + (p1 + p2) for D = 6, then the two halves of the result. The batch
// steppers sum their error norms in this order so that a lane takes the very
// steps of the scalar stepper (embedded_rk.hpp). T: a double or W lanes of them.
template <int Start, int Len, int Half, class T, int D>
[[gnu::always_inline]] inline T packet_sum(const T (&q)[D]) {
  if constexpr (Len == 1) {
    return q[2 * Start + Half];
  } else {
    return packet_sum<Start, Len / 2, Half>(q) +
           packet_sum<Start + Len / 2, Len - Len / 2, Half>(q);
  }
}
template <class T, int D>
[[gnu::always_inline]] inline T eigen_order_sum(const T (&q)[D]) {
  static_assert(D % 2 == 0, "the order of Eigen's sum is mirrored for even sizes only");
  return packet_sum<0, D / 2, 0>(q) + packet_sum<0, D / 2, 1>(q);
}

}  // namespace epviz::numerics
