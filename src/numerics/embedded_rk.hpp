#pragma once
// Adaptive explicit Runge–Kutta methods with an embedded error estimate,
// step-size control (standard or PI), FSAL and dense output:
//
//   Dopri5<Sys>   Dormand–Prince 5(4), dense output of order 4
//   Dop853<Sys>   Hairer's DOP853, order 8, 5th/3rd-order error estimators
//                 combined as in DOP853, dense output of order 7
//
// Usage:
//   Dop853<Sys> s(sys, opts);
//   s.init(t0, x0);
//   while (s.t() < t_out) s.step();      // one accepted step each
//   x = s.dense(t_out);                   // valid on [s.t_prev(), s.t()]
//
// The error norm is Hairer's: the RMS over components of
// err_i / (atol + rtol max(|x_i|, |x_new_i|)); a step is accepted when it is <= 1.
// Only forward integration (h > 0) is supported: integrate the time-reversed
// system to go backwards.
//
// Dopri5 orders its sums and error norm for latency (Tableau::latency_ordered):
// a step waits on its stages one after the other and the next step on the
// error, so what shortens those chains shortens the step. DOP853 keeps the
// plain order, which the batch integrator (batch_*.hpp) reproduces bit for bit.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "numerics/rk_tableaus.hpp"
#include "numerics/stepper_common.hpp"

namespace epviz::numerics {

struct AdaptiveOptions {
  double rtol = 1e-8, atol = 1e-8;
  double h_init = 0;  // 0: automatic initial step (Hairer's hinit)
  double h_max = std::numeric_limits<double>::infinity();
  long max_steps = 100'000'000;  // step attempts (accepted + rejected) since init()
  int max_consecutive_rejects = 60;
  // Step-size control: h_new = h * clamp(safety * err^-(1/q - k beta) * err_old^beta,
  // fac_min, fac_max), q = 5, k = 0.75 for dopri5 and q = 8, k = 0.2 for dop853
  // (as in Hairer's codes). A negative value selects the method's default
  // (dopri5: fac_min 0.2, fac_max 10, beta 0.04; dop853: 1/3, 6, 0).
  double safety = 0.9;
  double fac_min = -1;
  double fac_max = -1;
  double beta = -1;
};

namespace detail {

template <std::size_t Begin, class F, std::size_t... J>
inline void static_for_impl(F&& f, std::index_sequence<J...>) {
  (f(std::integral_constant<std::size_t, Begin + J>{}), ...);
}

// Calls f(std::integral_constant<std::size_t, j>) for j = Begin .. End-1.
template <std::size_t Begin, std::size_t End, class F>
inline void static_for(F&& f) {
  if constexpr (End > Begin)
    static_for_impl<Begin>(std::forward<F>(f), std::make_index_sequence<End - Begin>{});
}

template <std::size_t Begin, std::size_t... J>
std::index_sequence<Begin + J...> offset_sequence(std::index_sequence<J...>);

// std::index_sequence<Begin, ..., End - 1>.
template <std::size_t Begin, std::size_t End>
using index_range =
    decltype(offset_sequence<Begin>(std::make_index_sequence<(End > Begin ? End - Begin : 0)>{}));

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

}  // namespace detail

template <OdeSystem Sys, class Tableau>
class EmbeddedRk {
 public:
  using System = Sys;
  using State = typename Sys::State;
  static constexpr const char* name = Tableau::name;
  static constexpr int order = Tableau::order;
  static constexpr int dense_order = Tableau::dense_order;

  explicit EmbeddedRk(Sys sys, AdaptiveOptions opts = {}) : sys_(std::move(sys)), opts_(opts) {
    fac_min_ = opts_.fac_min < 0 ? Tableau::default_fac_min : opts_.fac_min;
    fac_max_ = opts_.fac_max < 0 ? Tableau::default_fac_max : opts_.fac_max;
    beta_ = opts_.beta < 0 ? Tableau::default_beta : opts_.beta;
    expo_ = Tableau::error_exponent - Tableau::beta_coupling * beta_;
    if (!(opts_.rtol >= 0 && opts_.atol >= 0 && opts_.rtol + opts_.atol > 0))
      throw std::invalid_argument(std::string(name) + ": tolerances must be >= 0, not both 0");
    if (!(opts_.h_max > 0)) throw std::invalid_argument(std::string(name) + ": h_max must be > 0");
    if (!(opts_.safety > 0 && opts_.safety <= 1 && fac_min_ > 0 && fac_min_ < 1 && fac_max_ > 1))
      throw std::invalid_argument(std::string(name) + ": invalid step-size control factors");
  }

  // Starts an integration at (t0, x0); resets the statistics.
  void init(double t0, const State& x0) {
    t_ = t_prev_ = t0;
    x_ = x_prev_ = x0;
    h_ = opts_.h_init > 0 ? std::min(opts_.h_init, opts_.h_max) : 0.0;
    h_last_ = 0;
    log_err_old_ = kLogErrFloor;
    attempts_ = 0;
    consecutive_rejects_ = 0;
    fsal_pending_ = false;
    last_rejected_ = false;
    dense_ = DenseState::none;
    stats_ = Stats{};
    initialized_ = true;
  }

  // Takes one accepted step (retrying with smaller steps as needed). Throws
  // IntegrationError when it cannot.
  void step();

  double t() const { return t_; }
  double t_prev() const { return t_prev_; }
  double h_last() const { return h_last_; }  // size of the last accepted step
  double h_next() const { return h_; }       // size the next step will try
  const State& state() const { return x_; }

  // The continuous extension of the last accepted step, valid for t in
  // [t_prev(), t()] (outside it the polynomial is extrapolated). Must be called
  // before the next step(); the first call after a step evaluates the extra
  // stages the interpolant needs (DOP853: 3 right-hand sides).
  State dense(double t) const;

  // One step of size h without error control (for convergence-order studies).
  // Shares the work arrays with the adaptive integration: do not interleave.
  void step(State& x, double t, double h);

  Sys& system() { return sys_; }
  const Sys& system() const { return sys_; }
  const Stats& stats() const { return stats_; }
  const AdaptiveOptions& options() const { return opts_; }

 private:
  static constexpr int S = Tableau::stages;
  static constexpr int N = Tableau::total;
  using Row = typename Tableau::Row;
  using Stages = std::array<State, N>;
  template <std::size_t M>
  static std::array<State, M> filled() {
    std::array<State, M> a;
    a.fill(State::Zero());
    return a;
  }
  enum class DenseState { none, lazy, ready };

  static constexpr bool error_needs_fsal = Tableau::e[S] != 0.0 || Tableau::e2[S] != 0.0;
  static constexpr std::size_t error_terms = error_needs_fsal ? S + 1 : S;

  // The linear combinations of stages are plain loops over the components with
  // the tableau's weights as compile-time constants (zero weights skipped) and
  // forced inline, like the systems' rhs: with one Eigen statement per term
  // (acc = w k; acc += w k; ...) GCC left the sums out of line in the large
  // step() and they cost more than the right-hand sides. Each component is
  // still summed left to right over the nonzero weights and then combined as
  // x + h * sum: the very operations, hence the very roundings, of the former
  // code (results are bitwise unchanged).
  static constexpr int D = Sys::dim;

  // A row of weights as a template argument, named by a type whose member w
  // is the row: clang 14 takes neither an element of an array nor a double as
  // a template argument (GCC takes both), and the sanitizer builds use clang.
  template <const auto& Rows, std::size_t I>
  struct RowOf {
    static constexpr const Row& w = Rows[I];
  };
  template <const Row& R>
  struct RowIs {
    static constexpr const Row& w = R;
  };

  template <class W, std::size_t Nterms>
  struct Terms {
    static constexpr std::size_t count = detail::count_nonzero(W::w, Nterms);
    static_assert(count > 0, "weights must not all vanish");
    static constexpr std::array<std::size_t, count> idx =
        detail::nonzero_indices<count>(W::w, Nterms);
  };

  // sum_j W[j] k[j][i] over the nonzero weights, left to right.
  template <class W, std::size_t Nterms, std::size_t... J>
  [[gnu::always_inline]] static inline double dot_impl(const Stages& k, int i,
                                                       std::index_sequence<J...>) noexcept {
    constexpr const auto& idx = Terms<W, Nterms>::idx;
    double sum = W::w[idx[0]] * k[idx[0]].coeff(i);
    ((sum += W::w[idx[J + 1]] * k[idx[J + 1]].coeff(i)), ...);
    return sum;
  }
  template <class W, std::size_t Nterms>
  [[gnu::always_inline]] static inline double dot(const Stages& k, int i) noexcept {
    return dot_impl<W, Nterms>(k, i, std::make_index_sequence<Terms<W, Nterms>::count - 1>{});
  }
  // The same over the first M nonzero weights only.
  template <class W, std::size_t Nterms, std::size_t M>
  [[gnu::always_inline]] static inline double dot_first(const Stages& k, int i) noexcept {
    return dot_impl<W, Nterms>(k, i, std::make_index_sequence<M - 1>{});
  }

#if defined(__GNUC__)
  // Even dimensions: the same sums two components at a time (GCC's vector
  // extension; lane-wise the same multiplications and additions). Measured on
  // the 6-dimensional direct system: DOP853 step 185 -> 165 ns, since left to
  // itself GCC kept the stages in scalar registers across the inlined rhs. For
  // odd dimensions the packed loads of scalar-stored stages were slower (store
  // forwarding fails): they use the component loop.
  using V2 = double __attribute__((vector_size(16)));
  static constexpr bool packed = D % 2 == 0;
  [[gnu::always_inline]] static inline V2 load2(const double* p) noexcept {
    V2 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  template <class W, std::size_t J>
  [[gnu::always_inline]] static inline void add_term(V2* v, const State& kj) noexcept {
    constexpr double w = W::w[J];
    for (int p = 0; p < D / 2; ++p) v[p] += w * load2(kj.data() + 2 * p);
  }
  // Over the first J... + 1 nonzero weights.
  template <class W, std::size_t Nterms, std::size_t... J>
  [[gnu::always_inline]] static inline void sums_packed(double* s, const Stages& k,
                                                        std::index_sequence<J...>) noexcept {
    constexpr const auto& idx = Terms<W, Nterms>::idx;
    V2 v[D / 2];
    for (int p = 0; p < D / 2; ++p) v[p] = W::w[idx[0]] * load2(k[idx[0]].data() + 2 * p);
    (add_term<W, idx[J + 1]>(v, k[idx[J + 1]]), ...);
    std::memcpy(s, v, sizeof v);
  }
#else
  static constexpr bool packed = false;
#endif

  // s[i] = sum_{j < Nterms} W[j] k[j][i] for every component i, over the
  // first M nonzero weights (all by default).
  template <class W, std::size_t Nterms, std::size_t M = Terms<W, Nterms>::count>
  [[gnu::always_inline]] static inline void sums(double* s, const Stages& k) noexcept {
#if defined(__GNUC__)
    if constexpr (packed) {
      sums_packed<W, Nterms>(s, k, std::make_index_sequence<M - 1>{});
      return;
    }
#endif
    for (int i = 0; i < D; ++i) s[i] = dot_first<W, Nterms, M>(k, i);
  }

  // acc = sum_{j < Nterms} W[j] k[j].
  template <class W, std::size_t Nterms>
  [[gnu::always_inline]] static inline void weighted_sum(State& acc, const Stages& k) noexcept {
    double s[D];
    sums<W, Nterms>(s, k);
    for (int i = 0; i < D; ++i) acc.coeffRef(i) = s[i];
  }

  // out = x0 + h sum with sum = sum_{j < Nterms} W[j] k[j], also stored in
  // *sum_out when given (out may alias x0, not k).
  template <class W, std::size_t Nterms>
  [[gnu::always_inline]] static inline void advance(State& out, const State& x0, double h,
                                                    const Stages& k,
                                                    State* sum_out = nullptr) noexcept {
    double s[D];
    sums<W, Nterms>(s, k);
    for (int i = 0; i < D; ++i) {
      if (sum_out) sum_out->coeffRef(i) = s[i];
      out.coeffRef(i) = x0.coeff(i) + h * s[i];
    }
  }

  // The sums ordered for latency (Tableau::latency_ordered): out = (x0 + h sum
  // over the older stages) + (h w_last) k_last, with the newest stage k_last
  // (index Nterms - 1) passed in `fresh`, a local. The newest stage, which
  // everything else waits for, then reaches the next right-hand side through
  // one multiplication and one addition (the plain order takes four: the
  // sum's last term, h times the sum, x0 plus it), and from registers.
  template <class W, std::size_t Nterms>
  [[gnu::always_inline]] static inline void advance_fresh(State& out, const State& x0, double h,
                                                          const Stages& k,
                                                          const State& fresh) noexcept {
    using T = Terms<W, Nterms>;
    static_assert(T::idx[T::count - 1] == Nterms - 1, "the newest stage must have a weight");
    const double hw = h * W::w[Nterms - 1];
    double base[D];
    if constexpr (T::count > 1) {
      sums<W, Nterms, T::count - 1>(base, k);
      for (int i = 0; i < D; ++i) base[i] = x0.coeff(i) + h * base[i];
    } else {
      for (int i = 0; i < D; ++i) base[i] = x0.coeff(i);
    }
    for (int i = 0; i < D; ++i) out.coeffRef(i) = base[i] + hw * fresh.coeff(i);
  }

  // Stage I as `stage` computes it, with the sums ordered for latency: fresh
  // holds k[I - 1] on entry and k[I] on return.
  template <std::size_t I>
  [[gnu::always_inline]] inline void stage_fresh(double t0, const State& x0, double h, Stages& k,
                                                 State& fresh) const {
    State in;
    advance_fresh<RowOf<Tableau::a, I>, I>(in, x0, h, k, fresh);
    sys_.rhs(t0 + Tableau::c[I] * h, in, fresh);
    k[I] = fresh;
  }
  template <std::size_t... I>
  [[gnu::always_inline]] inline void stages_fresh(double t, const State& x, double h, Stages& k,
                                                  State& fresh, std::index_sequence<I...>) const {
    (stage_fresh<I>(t, x, h, k, fresh), ...);
  }

  // Stage I from base point (t0, x0) with step h: k[I] = f(t0 + c_I h, x0 + h sum a_Ij k_j).
  template <std::size_t I>
  [[gnu::always_inline]] inline void stage(double t0, const State& x0, double h, Stages& k,
                                           State& tmp) const {
    advance<RowOf<Tableau::a, I>, I>(tmp, x0, h, k);
    sys_.rhs(t0 + Tableau::c[I] * h, tmp, k[I]);
  }

  // Stages I... from base point (t, x) with step h.
  template <std::size_t... I>
  [[gnu::always_inline]] inline void stages_from([[maybe_unused]] double t, const State& x,
                                                 [[maybe_unused]] double h, Stages& k, State& tmp,
                                                 std::index_sequence<I...>) const {
    (stage<I>(t, x, h, k, tmp), ...);
  }
  // Stages 1 .. S-1 and x_new (into xnew_) from (t, x) with k_[0] set; leaves
  // acc_ = sum_j b_j k_j.
  [[gnu::always_inline]] inline void stages_and_solution(double t, const State& x, double h) {
    stages_from(t, x, h, k_, tmp_, detail::index_range<1, S>{});
    advance<RowIs<Tableau::b>, S>(xnew_, x, h, k_, &acc_);
  }
  // The same ordered for latency: leaves the last stage in `fresh` and x_new
  // in `xnew` as well, both locals.
  // (A template, as error_norm_squared, so that an explicit instantiation of
  // a plain-order stepper, which instantiates every other member, leaves the
  // latency-ordered ones, which it cannot compile, out.)
  template <class = Tableau>
  [[gnu::always_inline]] inline void stages_and_solution_fresh(double t, const State& x, double h,
                                                               State& xnew, State& fresh) {
    fresh = k_[0];
    stages_fresh(t, x, h, k_, fresh, detail::index_range<1, S>{});
    advance_fresh<RowIs<Tableau::b>, S>(xnew, x, h, k_, fresh);
    // One component at a time: a copy by pairs read xnew back from memory as
    // pairs it had just stored one by one, and a store is not forwarded to a
    // wider load (the load waits for the stores to complete).
    for (int i = 0; i < D; ++i) xnew_.coeffRef(i) = xnew.coeff(i);
  }

  // One attempted step of size h from (t_, x_) with k_[0] set: the stages,
  // x_new (into xnew_), f(t_ + h, x_new) when the error estimate needs it,
  // and the error: error_norm(h), or its square with latency_ordered.
  [[gnu::always_inline]] inline double attempt(double h) {
    if constexpr (Tableau::latency_ordered) {
      static_assert(error_needs_fsal && !Tableau::two_estimators);
      State xnew, fresh;
      stages_and_solution_fresh(t_, x_, h, xnew, fresh);
      sys_.rhs(t_ + h, xnew, fresh);
      k_[S] = fresh;
      stats_.rhs_evals += S;
      return error_norm_squared(h, xnew, fresh);
    } else {
      stages_and_solution(t_, x_, h);
      if constexpr (error_needs_fsal) {
        sys_.rhs(t_ + h, xnew_, k_[S]);
        stats_.rhs_evals += S;
      } else {
        stats_.rhs_evals += S - 1;
      }
      return error_norm(h);
    }
  }

  // q[Lo] + ... + q[Hi - 1], summed as a balanced tree (a short chain).
  template <int Lo, int Hi>
  [[gnu::always_inline]] static inline double tree_sum(const double* q) noexcept {
    if constexpr (Hi - Lo == 1) {
      return q[Lo];
    } else {
      constexpr int mid = Lo + (Hi - Lo) / 2;
      return tree_sum<Lo, mid>(q) + tree_sum<mid, Hi>(q);
    }
  }

  // The square of Hairer's error norm for one estimator (latency_ordered),
  // from x_new and its derivative `fsal` held in locals. The square root and
  // the division by the dimension are left off the chain the next step size
  // waits for (the control takes log(err) as log(err^2) / 2), the squares
  // are summed as a tree, and the reciprocal scales, which wait only for
  // x_new, are divided two at a time.
  template <class = Tableau>
  [[gnu::always_inline]] inline double error_norm_squared(double h, const State& xnew,
                                                          const State& fsal) const {
    using W = RowIs<Tableau::e>;
    using T = Terms<W, error_terms>;
    static_assert(T::idx[T::count - 1] == S, "the estimate must weigh f(t + h, x_new)");
    double older[D], q[D], inv_sk[D];
    sums<W, error_terms, T::count - 1>(older, k_);
    for (int i = 0; i < D; ++i)
      inv_sk[i] =
          opts_.atol + opts_.rtol * std::max(std::abs(x_.coeff(i)), std::abs(xnew.coeff(i)));
#if defined(__GNUC__)
    if constexpr (packed) {
      for (int p = 0; p < D / 2; ++p) {
        const V2 r = V2{1.0, 1.0} / V2{inv_sk[2 * p], inv_sk[2 * p + 1]};
        inv_sk[2 * p] = r[0];
        inv_sk[2 * p + 1] = r[1];
      }
    } else
#endif
    {
      for (int i = 0; i < D; ++i) inv_sk[i] = 1.0 / inv_sk[i];
    }
    for (int i = 0; i < D; ++i) {
      const double e = (older[i] + W::w[S] * fsal.coeff(i)) * inv_sk[i];
      q[i] = e * e;
    }
    return tree_sum<0, D>(q) * (h * h * (1.0 / double(D)));
  }
  // log(err) from what attempt() returned.
  static double log_error(double measure) {
    if constexpr (Tableau::latency_ordered) return 0.5 * std::log(measure);
    return std::log(measure);
  }

  // Hairer's error norm of the step from x_ to xnew_ (needs acc_ as left by
  // stages_and_solution).
  [[gnu::always_inline]] inline double error_norm(double h) const {
    using Arr = Eigen::Array<double, D, 1>;
    Arr inv_sk;
    for (int i = 0; i < D; ++i)
      inv_sk[i] = 1.0 / (opts_.atol +
                         opts_.rtol * std::max(std::abs(x_.coeff(i)), std::abs(xnew_.coeff(i))));
    constexpr double n = double(D);
    if constexpr (Tableau::two_estimators) {
      // 3rd-order estimator as b-sum minus the (sparse) embedded weights bhh.
      Arr q3, q5;
      for (int i = 0; i < D; ++i) {
        const double e3 = (acc_.coeff(i) - dot<RowIs<Tableau::bhh>, S>(k_, i)) * inv_sk[i];
        const double e5 = dot<RowIs<Tableau::e2>, error_terms>(k_, i) * inv_sk[i];
        q3[i] = e3 * e3;
        q5[i] = e5 * e5;
      }
      const double e3 = q3.sum(), e5 = q5.sum();
      double deno = e5 + 0.01 * e3;
      if (deno <= 0.0) deno = 1.0;
      return std::abs(h) * e5 / std::sqrt(n * deno);
    } else {
      Arr q;
      for (int i = 0; i < D; ++i) {
        const double e = dot<RowIs<Tableau::e>, error_terms>(k_, i) * inv_sk[i];
        q[i] = e * e;
      }
      return std::abs(h) * std::sqrt(q.sum() / n);
    }
  }

  // err^-expo_, with a fast path for DOP853's default exponent 1/8 (err == 0
  // gives +inf either way).
  inline double err_power(double err) const {
    if (expo_ == 0.125) return 1.0 / std::sqrt(std::sqrt(std::sqrt(err)));
    return std::exp(-expo_ * std::log(err));
  }
  // x^(1/n) for x > 0: by square roots for n = 8 (DOP853 then calls no libm
  // function with tables, which a process's first run pays for in page
  // faults), else by exp and log, which the dopri5 control uses anyway.
  static double order_root(double x, int n) {
    if (n == 8) return std::sqrt(std::sqrt(std::sqrt(x)));
    return std::exp(std::log(x) / double(n));
  }
  // log(1e-4): the previous step's error enters the PI control as at least 1e-4
  // (Hairer's FACOLD floor), and as 1e-4 before the first accepted step.
  static constexpr double kLogErrFloor = -9.210340371976182;

  double initial_step();
  void prepare_dense() const;
  [[noreturn]] void fail(FailureKind kind, std::string detail) const {
    detail::throw_failure(t_, name, kind, std::move(detail));
  }
  static std::string fmt(const char* f, double v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
  }

  Sys sys_;
  AdaptiveOptions opts_;
  double fac_min_, fac_max_, beta_, expo_;

  double t_ = 0, t_prev_ = 0, h_ = 0, h_last_ = 0, log_err_old_ = kLogErrFloor;
  long attempts_ = 0;
  int consecutive_rejects_ = 0;
  bool fsal_pending_ = false;  // k_[S] holds f(t_, x_)
  bool last_rejected_ = false;
  bool initialized_ = false;
  State x_ = State::Zero(), x_prev_ = State::Zero(), xnew_ = State::Zero();
  State acc_ = State::Zero(), tmp_ = State::Zero();
  // Stages of the last step. Mutable: dense() fills in the extra stages lazily.
  mutable Stages k_ = filled<N>();
  mutable std::array<State, 4 + Tableau::dense_rows> cont_ = filled<4 + Tableau::dense_rows>();
  mutable DenseState dense_ = DenseState::none;
  mutable Stats stats_;
};

template <OdeSystem Sys, class Tableau>
double EmbeddedRk<Sys, Tableau>::initial_step() {
  // Hairer, Nørsett & Wanner, Solving ODEs I, II.4 (subroutine HINIT).
  using Arr = Eigen::Array<double, Sys::dim, 1>;
  const Arr sk = opts_.atol + opts_.rtol * x_.array().abs();
  const double dnf = (k_[0].array() / sk).square().sum();
  const double dny = (x_.array() / sk).square().sum();
  double h = (dnf <= 1e-10 || dny <= 1e-10) ? 1e-6 : 0.01 * std::sqrt(dny / dnf);
  h = std::min(h, opts_.h_max);
  tmp_.noalias() = x_ + h * k_[0];
  sys_.rhs(t_ + h, tmp_, k_[1]);
  ++stats_.rhs_evals;
  const double der2 = std::sqrt(((k_[1] - k_[0]).array() / sk).square().sum()) / h;
  const double der12 = std::max(std::abs(der2), std::sqrt(dnf));
  if (!std::isfinite(der12)) return h * 1e-2;
  const double h1 =
      der12 <= 1e-15 ? std::max(1e-6, h * 1e-3) : order_root(0.01 / der12, Tableau::order);
  return std::min({100.0 * h, h1, opts_.h_max});
}

template <OdeSystem Sys, class Tableau>
void EmbeddedRk<Sys, Tableau>::step() {
  if (!initialized_) [[unlikely]]
    throw std::logic_error(std::string(name) + ": step() before init()");
  // The stages of the previous step are about to be overwritten.
  if (dense_ == DenseState::lazy) dense_ = DenseState::none;

  if (detail::regularize(sys_, x_)) {
    // Remapped: the cached derivative and the last interpolant are in the old chart.
    fsal_pending_ = false;
    dense_ = DenseState::none;
  }
  if (fsal_pending_) {
    k_[0] = k_[S];
  } else {
    sys_.rhs(t_, x_, k_[0]);
    ++stats_.rhs_evals;
    if (!k_[0].allFinite() || !x_.allFinite()) [[unlikely]]
      fail(FailureKind::non_finite, "state or derivative not finite (NaN or Inf)");
  }
  fsal_pending_ = false;
  if (h_ <= 0.0) h_ = initial_step();

  int nonfinite_trials = 0;
  for (;;) {
    double h = std::min(h_, opts_.h_max);
    if (attempts_ >= opts_.max_steps) [[unlikely]]
      fail(FailureKind::step_budget,
           "step budget of " + std::to_string(opts_.max_steps) + " steps exhausted");
    if (!(h >= 16.0 * std::numeric_limits<double>::epsilon() * std::abs(t_)) || h <= 0.0)
        [[unlikely]]
      fail(FailureKind::step_underflow, fmt("step size %.3g below the round-off limit", h));
    ++attempts_;

    // err: the error norm, or its square with latency_ordered (<= 1 either way
    // when the step is accepted).
    const double err = attempt(h);
    const bool finite = std::isfinite(err) && xnew_.allFinite();

    if (finite && err <= 1.0) [[likely]] {
      double fac;
      if (beta_ == 0.0 && !Tableau::latency_ordered) {
        fac = opts_.safety * err_power(err);
      } else {
        // err^-expo * err_old^beta as one exp of logs, the old error's log
        // kept from the previous step: two pow calls cost a fifth of a
        // dopri5 step on the 6-dimensional system. (Latency-ordered steppers
        // take this way whatever beta: they have the log of err^2 at hand.)
        const double log_err = log_error(err);
        const double y = beta_ * log_err_old_ - expo_ * log_err;
        fac = opts_.safety * std::exp(y);
        log_err_old_ = std::max(log_err, kLogErrFloor);
      }
      fac = std::clamp(fac, fac_min_, fac_max_);  // err == 0 gives +inf: clamped
      if (last_rejected_) fac = std::min(fac, 1.0);

      if constexpr (!error_needs_fsal) {
        sys_.rhs(t_ + h, xnew_, k_[S]);
        ++stats_.rhs_evals;
      }
      detail::check_issue(sys_, xnew_, t_ + h, name);
      t_prev_ = t_;
      x_prev_ = x_;
      t_ += h;
      x_ = xnew_;
      h_last_ = h;
      h_ = h * fac;
      fsal_pending_ = true;
      last_rejected_ = false;
      consecutive_rejects_ = 0;
      dense_ = DenseState::lazy;
      ++stats_.steps;
      return;
    }

    // Rejected.
    ++stats_.rejected_steps;
    last_rejected_ = true;
    double fac = fac_min_;
    if (finite) {
      const double power =
          Tableau::latency_ordered ? std::exp(-expo_ * log_error(err)) : err_power(err);
      fac = std::max(fac_min_, opts_.safety * power);
    } else {
      ++nonfinite_trials;
    }
    h_ = h * fac;
    if (++consecutive_rejects_ > opts_.max_consecutive_rejects) [[unlikely]] {
      // Trial states that are not finite even for tiny steps: the solution itself
      // blows up here, which is what the user needs to hear.
      if (nonfinite_trials > 0)
        fail(FailureKind::non_finite,
             fmt("trial states not finite (NaN or Inf) even with step size %.3g", h));
      fail(FailureKind::rejections,
           std::to_string(consecutive_rejects_) +
               fmt(" consecutive rejected steps (last step size %.3g)", h));
    }
  }
}

template <OdeSystem Sys, class Tableau>
void EmbeddedRk<Sys, Tableau>::prepare_dense() const {
  const double h = h_last_;
  State acc, tmp;
  stages_from(t_prev_, x_prev_, h, k_, tmp, detail::index_range<S + 1, N>{});
  stats_.rhs_evals += N - S - 1;
  cont_[0] = x_prev_;
  cont_[1] = x_ - x_prev_;
  cont_[2] = h * k_[0] - cont_[1];
  cont_[3] = cont_[1] - h * k_[S] - cont_[2];
  detail::static_for<0, Tableau::dense_rows>([&](auto r) {
    weighted_sum<RowOf<Tableau::d, r>, N>(acc, k_);
    cont_[4 + r] = h * acc;
  });
  dense_ = DenseState::ready;
}

template <OdeSystem Sys, class Tableau>
auto EmbeddedRk<Sys, Tableau>::dense(double t) const -> State {
  if (dense_ == DenseState::none) {
    if (t == t_) return x_;
    throw std::logic_error(std::string(name) +
                           ": dense output requested with no step to interpolate (call it "
                           "after step() and before the next one)");
  }
  if (dense_ == DenseState::lazy) prepare_dense();
  const double s = (t - t_prev_) / h_last_;
  const double s1 = 1.0 - s;
  constexpr int M = 4 + Tableau::dense_rows;
  State r = cont_[M - 1];
  for (int j = M - 2; j >= 0; --j) r = cont_[j] + ((j % 2 == 0) ? s : s1) * r;
  return r;
}

template <OdeSystem Sys, class Tableau>
void EmbeddedRk<Sys, Tableau>::step(State& x, double t, double h) {
  fsal_pending_ = false;
  dense_ = DenseState::none;
  detail::regularize(sys_, x);
  sys_.rhs(t, x, k_[0]);
  if constexpr (Tableau::latency_ordered) {
    State xnew, fresh;
    stages_and_solution_fresh(t, x, h, xnew, fresh);
  } else {
    stages_and_solution(t, x, h);
  }
  stats_.rhs_evals += S;
  detail::check_accepted(sys_, xnew_, t + h, name);
  x = xnew_;
  ++stats_.steps;
}

template <OdeSystem Sys>
using Dopri5 = EmbeddedRk<Sys, Dopri5Tableau>;
template <OdeSystem Sys>
using Dop853 = EmbeddedRk<Sys, Dop853Tableau>;

}  // namespace epviz::numerics
