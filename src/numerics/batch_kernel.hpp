#pragma once
// The arithmetic of the batch steppers on W lanes (batch_lanes.hpp): stages,
// trial solution, error norm, dense output coefficients, RK4 steps. Included
// only by the translation units that compile it for one instruction set each
// (e.g. physics/direct_batch_avx2.cpp), and instantiated there with a tag type
// of that unit's anonymous namespace: every function here is then local to its
// unit, and no copy built for AVX-512 can stand in for another.
//
// Each lane sees exactly the operations, in the order and with the roundings,
// of the scalar steppers (embedded_rk.hpp, rk4.hpp) on its own trajectory:
// stage sums left to right over the nonzero weights, x + h * sum, the error
// norm's sums in Eigen's order (eigen_order_sum). Lanes never mix. The units
// are compiled with -ffp-contract=off so that no path fuses a multiply and an
// add that the others round twice (docs/ensembles.md).
//
// No standard library templates here (only builtins): an inline function of
// the standard library instantiated in an AVX-512 unit could be chosen by the
// linker for every caller.
#include <array>
#include <cstddef>
#include <utility>

#include "numerics/batch_lanes.hpp"

namespace epviz::numerics::batch {

template <std::size_t N>
constexpr std::size_t count_nonzero(const std::array<double, N>& w, std::size_t n) {
  std::size_t c = 0;
  for (std::size_t j = 0; j < n; ++j)
    if (w[j] != 0.0) ++c;
  return c;
}

// The indices j < n with w[j] != 0, in increasing order.
template <std::size_t Count, std::size_t N>
constexpr std::array<std::size_t, Count> nonzero_indices(const std::array<double, N>& w,
                                                         std::size_t n) {
  std::array<std::size_t, Count> idx{};
  std::size_t c = 0;
  for (std::size_t j = 0; j < n; ++j)
    if (w[j] != 0.0) idx[c++] = j;
  return idx;
}

// A row of weights named by a type (clang 14 takes no array element as a
// template argument).
template <const auto& Rows, std::size_t I>
struct RowAt {
  static constexpr const auto& w = Rows[I];
};
template <const auto& R>
struct RowRef {
  static constexpr const auto& w = R;
};

// Tag: a type local to the instantiating unit (see above).
template <class Sys, int W, class Tableau, class Tag>
struct EmbeddedKernel {
  static constexpr int D = Sys::dim;
  static constexpr int S = Tableau::stages;
  static constexpr int N = Tableau::total;
  using Lanes = EmbeddedLanes<D, W, Tableau>;
  using Block = double[D][W];
  using Stages = double[N][D][W];

  static constexpr bool error_needs_fsal = Tableau::e[S] != 0.0 || Tableau::e2[S] != 0.0;
  static constexpr std::size_t error_terms = error_needs_fsal ? S + 1 : S;

  template <class Row, std::size_t Nterms>
  struct Terms {
    static constexpr std::size_t count = count_nonzero(Row::w, Nterms);
    static_assert(count > 0, "weights must not all vanish");
    static constexpr std::array<std::size_t, count> idx = nonzero_indices<count>(Row::w, Nterms);
  };

  // Weights and index lists as constants, so that no std::array member is
  // called at run time (see above).
  template <class Row, std::size_t J>
  static constexpr double weight = Row::w[J];
  template <class Row, std::size_t Nterms, std::size_t... J>
  static std::index_sequence<Terms<Row, Nterms>::idx[J]...> nonzero(std::index_sequence<J...>);
  template <class Row, std::size_t Nterms>
  using Nonzero =
      decltype(nonzero<Row, Nterms>(std::make_index_sequence<Terms<Row, Nterms>::count>{}));

  // sum_j Row[j] k[j][i][l] over the nonzero weights, left to right.
  template <class Row, std::size_t J0, std::size_t... J>
  [[gnu::always_inline]] static inline double dot_seq(const Stages& k, int i, int l,
                                                      std::index_sequence<J0, J...>) {
    double sum = weight<Row, J0> * k[J0][i][l];
    ((sum += weight<Row, J> * k[J][i][l]), ...);
    return sum;
  }
  template <class Row, std::size_t Nterms>
  [[gnu::always_inline]] static inline double dot(const Stages& k, int i, int l) {
    return dot_seq<Row>(k, i, l, Nonzero<Row, Nterms>{});
  }

  // out = x0 + h sum_j Row[j] k[j] (the sum also into *sum_out when given).
  template <class Row, std::size_t Nterms>
  [[gnu::always_inline]] static inline void advance(Block& out, const Block& x0,
                                                    const double (&h)[W], const Stages& k,
                                                    Block* sum_out = nullptr) {
    for (int i = 0; i < D; ++i) {
      for (int l = 0; l < W; ++l) {
        const double s = dot<Row, Nterms>(k, i, l);
        if (sum_out) (*sum_out)[i][l] = s;
        out[i][l] = x0[i][l] + h[l] * s;
      }
    }
  }

  // Stages I... from base points (t, x) with steps h.
  template <std::size_t... I>
  [[gnu::always_inline]] static inline void stages_from(Lanes& L, const Sys& sys,
                                                        const double (&t)[W], const Block& x,
                                                        const double (&h)[W],
                                                        std::index_sequence<I...>) {
    (
        [&] {
          advance<RowAt<Tableau::a, I>, I>(L.tmp, x, h, L.k);
          constexpr double c = Tableau::c[I];
          for (int l = 0; l < W; ++l) L.tt[l] = t[l] + c * h[l];
          sys.template rhs<W>(L.tt, L.tmp, L.k[I]);
        }(),
        ...);
  }

  template <std::size_t Begin, std::size_t... J>
  static std::index_sequence<Begin + J...> offset(std::index_sequence<J...>);
  template <std::size_t Begin, std::size_t End>
  using Range = decltype(offset<Begin>(std::make_index_sequence<End - Begin>{}));

  [[gnu::always_inline]] static inline double abs(double v) { return __builtin_fabs(v); }
  // std::max's choice: b only when a < b.
  [[gnu::always_inline]] static inline double max(double a, double b) { return a < b ? b : a; }

  static void attempt(Lanes& L, const Sys& sys) {
    stages_from(L, sys, L.t, L.x, L.h, Range<1, S>{});
    advance<RowRef<Tableau::b>, S>(L.xnew, L.x, L.h, L.k, &L.acc);
    for (int l = 0; l < W; ++l) L.tt[l] = L.t[l] + L.h[l];
    sys.template rhs<W>(L.tt, L.xnew, L.k[S]);
    error_norm(L);
  }

  // Hairer's error norm, as EmbeddedRk::error_norm computes it.
  [[gnu::always_inline]] static inline void error_norm(Lanes& L) {
    double inv_sk[D][W];
    for (int i = 0; i < D; ++i)
      for (int l = 0; l < W; ++l)
        inv_sk[i][l] = 1.0 / (L.atol + L.rtol * max(abs(L.x[i][l]), abs(L.xnew[i][l])));
    constexpr double n = double(D);
    if constexpr (Tableau::two_estimators) {
      double q3[D][W], q5[D][W];
      for (int i = 0; i < D; ++i) {
        for (int l = 0; l < W; ++l) {
          const double e3 = (L.acc[i][l] - dot<RowRef<Tableau::bhh>, S>(L.k, i, l)) * inv_sk[i][l];
          const double e5 = dot<RowRef<Tableau::e2>, error_terms>(L.k, i, l) * inv_sk[i][l];
          q3[i][l] = e3 * e3;
          q5[i][l] = e5 * e5;
        }
      }
      for (int l = 0; l < W; ++l) {
        const double e3 = eigen_order_sum(q3, l), e5 = eigen_order_sum(q5, l);
        double deno = e5 + 0.01 * e3;
        if (deno <= 0.0) deno = 1.0;
        L.err[l] = abs(L.h[l]) * e5 / __builtin_sqrt(n * deno);
      }
    } else {
      double q[D][W];
      for (int i = 0; i < D; ++i) {
        for (int l = 0; l < W; ++l) {
          const double e = dot<RowRef<Tableau::e>, error_terms>(L.k, i, l) * inv_sk[i][l];
          q[i][l] = e * e;
        }
      }
      for (int l = 0; l < W; ++l)
        L.err[l] = abs(L.h[l]) * __builtin_sqrt(eigen_order_sum(q, l) / n);
    }
  }

  // As EmbeddedRk::prepare_dense.
  static void dense(Lanes& L, const Sys& sys) {
    stages_from(L, sys, L.t_prev, L.x_prev, L.h_last, Range<S + 1, N>{});
    for (int i = 0; i < D; ++i) {
      for (int l = 0; l < W; ++l) {
        const double h = L.h_last[l];
        const double c1 = L.x[i][l] - L.x_prev[i][l];
        const double c2 = h * L.k[0][i][l] - c1;
        L.cont[0][i][l] = L.x_prev[i][l];
        L.cont[1][i][l] = c1;
        L.cont[2][i][l] = c2;
        L.cont[3][i][l] = c1 - h * L.k[S][i][l] - c2;
      }
    }
    dense_rows(L, std::make_index_sequence<Tableau::dense_rows>{});
  }
  template <std::size_t... R>
  [[gnu::always_inline]] static inline void dense_rows(Lanes& L, std::index_sequence<R...>) {
    (
        [&] {
          for (int i = 0; i < D; ++i)
            for (int l = 0; l < W; ++l)
              L.cont[4 + R][i][l] = L.h_last[l] * dot<RowAt<Tableau::d, R>, N>(L.k, i, l);
        }(),
        ...);
  }

  static constexpr EmbeddedKernels<Sys, W, Tableau> table{&attempt, &dense};
};

// As Rk4::step, lane by lane.
template <class Sys, int W, class Tag>
struct Rk4KernelImpl {
  static constexpr int D = Sys::dim;
  using Lanes = Rk4Lanes<D, W>;

  [[gnu::always_inline]] static inline void stage(Lanes& L, const Sys& sys, int from,
                                                  const double (&f)[W], int into) {
    for (int i = 0; i < D; ++i)
      for (int l = 0; l < W; ++l) L.tmp[i][l] = L.x[i][l] + f[l] * L.k[from][i][l];
    sys.template rhs<W>(L.tt, L.tmp, L.k[into]);
  }

  static void step(Lanes& L, const Sys& sys) {
    double h2[W];
    for (int l = 0; l < W; ++l) h2[l] = 0.5 * L.h[l];
    sys.template rhs<W>(L.t, L.x, L.k[0]);
    for (int l = 0; l < W; ++l) L.tt[l] = L.t[l] + h2[l];
    stage(L, sys, 0, h2, 1);
    stage(L, sys, 1, h2, 2);
    for (int l = 0; l < W; ++l) L.tt[l] = L.t[l] + L.h[l];
    stage(L, sys, 2, L.h, 3);
    for (int i = 0; i < D; ++i) {
      for (int l = 0; l < W; ++l) {
        const double sum = L.k[0][i][l] + 2.0 * (L.k[1][i][l] + L.k[2][i][l]) + L.k[3][i][l];
        L.xnew[i][l] = L.x[i][l] + (L.h[l] / 6.0) * sum;
      }
    }
  }

  static constexpr Rk4Kernel<Sys, W> table{&step};
};

}  // namespace epviz::numerics::batch
