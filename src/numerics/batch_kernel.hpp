#pragma once
// The arithmetic of the batch steppers on W lanes (batch_lanes.hpp): stages,
// trial solution, error norm, dense output coefficients, RK4 steps. Included
// only by the translation units that compile it for one instruction set each
// (e.g. sim/ensemble_avx2.cpp), and instantiated there with a tag type
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
// No standard library templates called here (only builtins): an inline function of
// the standard library instantiated in an AVX-512 unit could be chosen by the
// linker for every caller.
#include <array>
#include <cstddef>
#include <utility>

#include "numerics/batch_lanes.hpp"

namespace epviz::numerics::batch {

// The nonzero weights of a row, as embedded_rk.hpp's detail:: helpers find
// them; repeated here because that header brings Eigen, which must stay out of
// these units (it refuses -mavx512f without -mfma, and its inline functions
// would be compiled for the unit's instruction set).
template <std::size_t N>
constexpr std::size_t count_nonzero(const std::array<double, N>& w, std::size_t n) {
  std::size_t c = 0;
  for (std::size_t j = 0; j < n; ++j) c += w[j] != 0.0;
  return c;
}

template <std::size_t Count, std::size_t N>
constexpr std::array<std::size_t, Count> nonzero_indices(const std::array<double, N>& w,
                                                         std::size_t n) {
  std::array<std::size_t, Count> idx{};
  for (std::size_t j = 0, c = 0; j < n; ++j)
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

// W lanes of doubles as one value: GCC's and clang's vector extension (one
// register, or several on a narrower instruction set), a plain double for one
// lane. Written with these rather than loops over the lanes, which GCC
// vectorised across the components instead, with a transpose per stage.
template <int W>
struct LaneVector {
  typedef double type __attribute__((vector_size(8 * W)));
  typedef long long mask __attribute__((vector_size(8 * W)));
};
template <>
struct LaneVector<1> {
  using type = double;
  using mask = long long;
};

// Tag: a type local to the instantiating unit (see above).
template <int W, class Tag>
struct Lanewise {
  using V = typename LaneVector<W>::type;
  using Mask = typename LaneVector<W>::mask;

  [[gnu::always_inline]] static inline V load(const double (&row)[W]) {
    V v;
    __builtin_memcpy(&v, row, sizeof v);
    return v;
  }
  [[gnu::always_inline]] static inline void store(double (&row)[W], V v) {
    __builtin_memcpy(row, &v, sizeof v);
  }
  [[gnu::always_inline]] static inline V abs(V a) {
    if constexpr (W == 1) {
      return __builtin_fabs(a);
    } else {
      return (V)((Mask)a & (Mask{} + 0x7fffffffffffffffLL));
    }
  }
  // std::min's choice, lane by lane: b only where b < a.
  [[gnu::always_inline]] static inline V min(V a, V b) {
    if constexpr (W == 1) {
      return b < a ? b : a;
    } else {
      return select(b < a, b, a);
    }
  }
  // std::max's choice, lane by lane: b only where a < b.
  [[gnu::always_inline]] static inline V max(V a, V b) {
    if constexpr (W == 1) {
      return a < b ? b : a;
    } else {
      return select(a < b, b, a);
    }
  }
  // a where m is set (all ones), b elsewhere.
  [[gnu::always_inline]] static inline V select(Mask m, V a, V b) {
    if constexpr (W == 1) {
      return m ? a : b;
    } else {
      return (V)((m & (Mask)a) | (~m & (Mask)b));
    }
  }
  [[gnu::always_inline]] static inline Mask load_mask(const long long (&row)[W]) {
    Mask m;
    __builtin_memcpy(&m, row, sizeof m);
    return m;
  }
  [[gnu::always_inline]] static inline void store_mask(long long (&row)[W], Mask m) {
    __builtin_memcpy(row, &m, sizeof m);
  }
  // All ones where a is NaN or infinite: a - a is NaN there and 0 elsewhere.
  [[gnu::always_inline]] static inline Mask not_finite(V a) {
    if constexpr (W == 1) {
      return __builtin_isfinite(a) ? 0 : -1;
    } else {
      const V z = a - a;
      return z != z;
    }
  }
  // The correctly rounded square root lane by lane, as a loop the compiler
  // makes one vector instruction (the units have -fno-math-errno).
  [[gnu::always_inline]] static inline V sqrt(V a) {
    if constexpr (W == 1) {
      return __builtin_sqrt(a);
    } else {
      double r[W];
      store(r, a);
      for (int l = 0; l < W; ++l) r[l] = __builtin_sqrt(r[l]);
      return load(r);
    }
  }
};

template <class Sys, int W, class Tableau, class Tag>
struct EmbeddedKernel : Lanewise<W, Tag> {
  using Base = Lanewise<W, Tag>;
  using Base::abs, Base::load, Base::load_mask, Base::max, Base::min, Base::not_finite,
      Base::select, Base::sqrt, Base::store, Base::store_mask;
  using typename Base::Mask;
  using typename Base::V;
  static constexpr int D = Sys::dim;
  static constexpr int S = Tableau::stages;
  static constexpr int N = Tableau::total;
  using Lanes = EmbeddedLanes<D, W, Tableau>;
  using Stages = double[N][D][W];

  static constexpr bool error_needs_fsal = error_needs_fsal_v<Tableau>;
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

  // sum_j Row[j] k[j][i] over the nonzero weights, left to right.
  template <class Row, std::size_t J0, std::size_t... J>
  [[gnu::always_inline]] static inline V dot_seq(const Stages& k, int i,
                                                 std::index_sequence<J0, J...>) {
    V sum = weight<Row, J0> * load(k[J0][i]);
    ((sum += weight<Row, J> * load(k[J][i])), ...);
    return sum;
  }
  template <class Row, std::size_t Nterms>
  [[gnu::always_inline]] static inline V dot(const Stages& k, int i) {
    return dot_seq<Row>(k, i, Nonzero<Row, Nterms>{});
  }

  // Stages I... from base points (t, x) with steps h.
  template <std::size_t... I>
  [[gnu::always_inline]] static inline void stages_from(Lanes& L, const Sys& sys,
                                                        const double (&t)[W],
                                                        const double (&x)[D][W],
                                                        const double (&h)[W],
                                                        std::index_sequence<I...>) {
    const V tv = load(t), hv = load(h);
    (
        [&] {
          V y[D], dy[D];
          for (int i = 0; i < D; ++i) y[i] = load(x[i]) + hv * dot<RowAt<Tableau::a, I>, I>(L.k, i);
          constexpr double c = Tableau::c[I];
          sys.rhs(tv + c * hv, y, dy);
          for (int i = 0; i < D; ++i) store(L.k[I][i], dy[i]);
        }(),
        ...);
  }

  template <std::size_t Begin, std::size_t... J>
  static std::index_sequence<Begin + J...> offset(std::index_sequence<J...>);
  template <std::size_t Begin, std::size_t End>
  using Range = decltype(offset<Begin>(std::make_index_sequence<End - Begin>{}));

  static void attempt(Lanes& L, const Sys& sys) {
    stages_from(L, sys, L.t, L.x, L.h, Range<1, S>{});
    const V h = load(L.h);
    V xnew[D], dx[D];
    for (int i = 0; i < D; ++i) {
      const V s = dot<RowRef<Tableau::b>, S>(L.k, i);
      store(L.acc[i], s);
      xnew[i] = load(L.x[i]) + h * s;
      store(L.xnew[i], xnew[i]);
    }
    sys.rhs(load(L.t) + h, xnew, dx);
    for (int i = 0; i < D; ++i) store(L.k[S][i], dx[i]);
    error_norm(L);
  }

  // As EmbeddedRk::init's first derivative and initial_step (HINIT), whose
  // sums, branches and std::min / std::max choices it follows lane by lane.
  static void start(StartLanes<D, W>& S0, const Sys& sys) {
    static_assert(Tableau::order == 8, "the initial step's root is the eighth root");
    const V t = load(S0.t);
    V x[D], k0[D], x1[D], k1[D], sk[D], q[D];
    for (int i = 0; i < D; ++i) x[i] = load(S0.x[i]);
    sys.rhs(t, x, k0);
    for (int i = 0; i < D; ++i) store(S0.k0[i], k0[i]);
    for (int i = 0; i < D; ++i) sk[i] = S0.atol + S0.rtol * abs(x[i]);
    for (int i = 0; i < D; ++i) {
      const V d = k0[i] / sk[i];
      q[i] = d * d;
    }
    const V dnf = eigen_order_sum(q);
    for (int i = 0; i < D; ++i) {
      const V d = x[i] / sk[i];
      q[i] = d * d;
    }
    const V dny = eigen_order_sum(q);
    const V h_max = V{} + S0.h_max;
    V h = select((dnf <= 1e-10) | (dny <= 1e-10), V{} + 1e-6, 0.01 * sqrt(dny / dnf));
    h = min(h, h_max);
    for (int i = 0; i < D; ++i) x1[i] = x[i] + h * k0[i];
    sys.rhs(t + h, x1, k1);
    for (int i = 0; i < D; ++i) {
      const V d = (k1[i] - k0[i]) / sk[i];
      q[i] = d * d;
    }
    const V der2 = sqrt(eigen_order_sum(q)) / h;
    const V der12 = max(abs(der2), sqrt(dnf));
    const V h1 = select(der12 <= 1e-15, max(V{} + 1e-6, h * 1e-3), sqrt(sqrt(sqrt(0.01 / der12))));
    const V h0 = min(min(100.0 * h, h1), h_max);
    store(S0.h0, select(not_finite(der12), h * 1e-2, h0));
  }

  // Hairer's error norm, as EmbeddedRk::error_norm computes it, then what the
  // driver's decision needs of it (EmbeddedLanes).
  [[gnu::always_inline]] static inline void error_norm(Lanes& L) {
    constexpr double n = double(D);
    const V h = load(L.h);
    V err;
    if constexpr (Tableau::two_estimators) {
      V q3[D], q5[D];
      for (int i = 0; i < D; ++i) {
        const V inv_sk = 1.0 / (L.atol + L.rtol * max(abs(load(L.x[i])), abs(load(L.xnew[i]))));
        const V e3 = (load(L.acc[i]) - dot<RowRef<Tableau::bhh>, S>(L.k, i)) * inv_sk;
        const V e5 = dot<RowRef<Tableau::e2>, error_terms>(L.k, i) * inv_sk;
        q3[i] = e3 * e3;
        q5[i] = e5 * e5;
      }
      const V e3 = eigen_order_sum(q3), e5 = eigen_order_sum(q5);
      V deno = e5 + 0.01 * e3;
      deno = select(deno <= 0.0, V{} + 1.0, deno);
      err = abs(h) * e5 / sqrt(n * deno);
    } else {
      V q[D];
      for (int i = 0; i < D; ++i) {
        const V inv_sk = 1.0 / (L.atol + L.rtol * max(abs(load(L.x[i])), abs(load(L.xnew[i]))));
        const V e = dot<RowRef<Tableau::e>, error_terms>(L.k, i) * inv_sk;
        q[i] = e * e;
      }
      err = abs(h) * sqrt(eigen_order_sum(q) / n);
    }
    store(L.err, err);
    store(L.err_root8, 1.0 / sqrt(sqrt(sqrt(err))));
    Mask bad = not_finite(err);
    for (int i = 0; i < D; ++i) bad |= not_finite(load(L.xnew[i]));
    store_mask(L.trial_finite, ~bad);
  }

  static void commit(Lanes& L) {
    const Mask m = load_mask(L.accept);
    const V t = load(L.t), h = load(L.h);
    store(L.t_prev, select(m, t, load(L.t_prev)));
    store(L.t, select(m, t + h, t));
    store(L.h_last, select(m, h, load(L.h_last)));
    for (int i = 0; i < D; ++i) {
      const V x = load(L.x[i]);
      store(L.x_prev[i], select(m, x, load(L.x_prev[i])));
      store(L.x[i], select(m, load(L.xnew[i]), x));
    }
  }

  static void fsal(Lanes& L) {
    const Mask m = load_mask(L.accept);
    for (int i = 0; i < D; ++i) store(L.k[0][i], select(m, load(L.k[S][i]), load(L.k[0][i])));
  }

  // As EmbeddedRk::prepare_dense.
  static void dense(Lanes& L, const Sys& sys) {
    stages_from(L, sys, L.t_prev, L.x_prev, L.h_last, Range<S + 1, N>{});
    const V h = load(L.h_last);
    for (int i = 0; i < D; ++i) {
      const V c1 = load(L.x[i]) - load(L.x_prev[i]);
      const V c2 = h * load(L.k[0][i]) - c1;
      store(L.cont[0][i], load(L.x_prev[i]));
      store(L.cont[1][i], c1);
      store(L.cont[2][i], c2);
      store(L.cont[3][i], c1 - h * load(L.k[S][i]) - c2);
    }
    dense_rows(L, h, std::make_index_sequence<Tableau::dense_rows>{});
  }
  template <std::size_t... R>
  [[gnu::always_inline]] static inline void dense_rows(Lanes& L, V h, std::index_sequence<R...>) {
    (
        [&] {
          for (int i = 0; i < D; ++i)
            store(L.cont[4 + R][i], h * dot<RowAt<Tableau::d, R>, N>(L.k, i));
        }(),
        ...);
  }

  static constexpr EmbeddedKernels<Sys, W, Tableau> table{&start, &attempt, &commit, &dense, &fsal};
};

// As Rk4::step, lane by lane.
template <class Sys, int W, class Tag>
struct Rk4KernelImpl : Lanewise<W, Tag> {
  using Base = Lanewise<W, Tag>;
  using Base::load, Base::store;
  using typename Base::V;
  static constexpr int D = Sys::dim;
  using Lanes = Rk4Lanes<D, W>;

  static void step(Lanes& L, const Sys& sys) {
    const V t = load(L.t), h = load(L.h), h2 = 0.5 * h;
    V x[D], k1[D], k2[D], k3[D], k4[D], y[D];
    for (int i = 0; i < D; ++i) x[i] = load(L.x[i]);
    sys.rhs(t, x, k1);
    for (int i = 0; i < D; ++i) y[i] = x[i] + h2 * k1[i];
    sys.rhs(t + h2, y, k2);
    for (int i = 0; i < D; ++i) y[i] = x[i] + h2 * k2[i];
    sys.rhs(t + h2, y, k3);
    for (int i = 0; i < D; ++i) y[i] = x[i] + h * k3[i];
    sys.rhs(t + h, y, k4);
    for (int i = 0; i < D; ++i)
      store(L.xnew[i], x[i] + (h / 6.0) * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]));
  }

  static constexpr Rk4Kernel<Sys, W> table{&step};
};

}  // namespace epviz::numerics::batch
