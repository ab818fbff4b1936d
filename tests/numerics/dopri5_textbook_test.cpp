// Dopri5 against a textbook Dormand–Prince 5(4) written out here term by
// term, with Hairer's error norm and PI step-size control as DOPRI5 states
// them (Hairer, Nørsett & Wanner, Solving ODEs I, II.4). The stepper orders
// its sums for latency and controls the step by the square of the norm: it
// must take the same steps, rejections included, to round-off. (Round-off as
// the error estimate amplifies it: a difference of two solutions that agree
// to the tolerance, summed from stages far larger, whose last digits depend
// on the order of the sum; the step sizes agree to a few 1e-9.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "numerics/embedded_rk.hpp"
#include "test_systems.hpp"

namespace epviz::numerics {
namespace {

using testing::HeavyTop;
using testing::Kepler;

// Euler's free rigid body (3 dimensions: the odd case, summed one component
// at a time).
struct FreeRigidBody {
  static constexpr int dim = 3;
  using State = Vec<3>;
  void rhs(double, const State& w, State& dw) const {
    dw[0] = (2.0 - 3.0) / 1.0 * w[1] * w[2];
    dw[1] = (3.0 - 1.0) / 2.0 * w[2] * w[0];
    dw[2] = (1.0 - 2.0) / 3.0 * w[0] * w[1];
  }
};

template <class Sys>
class TextbookDopri5 {
 public:
  using State = typename Sys::State;
  TextbookDopri5(Sys sys, double tol, double t0, const State& x0, double h0)
      : sys_(sys), tol_(tol), t_(t0), h_(h0), x_(x0) {
    sys_.rhs(t_, x_, k1_);
  }

  // One accepted step, after as many rejected ones as it takes.
  void step() {
    for (;;) {
      const double h = h_;
      State k2, k3, k4, k5, k6, k7;
      sys_.rhs(t_ + h / 5, x_ + h * (k1_ / 5), k2);
      sys_.rhs(t_ + 3 * h / 10, x_ + h * (3.0 / 40 * k1_ + 9.0 / 40 * k2), k3);
      sys_.rhs(t_ + 4 * h / 5, x_ + h * (44.0 / 45 * k1_ - 56.0 / 15 * k2 + 32.0 / 9 * k3), k4);
      sys_.rhs(t_ + 8 * h / 9,
               x_ + h * (19372.0 / 6561 * k1_ - 25360.0 / 2187 * k2 + 64448.0 / 6561 * k3 -
                         212.0 / 729 * k4),
               k5);
      sys_.rhs(t_ + h,
               x_ + h * (9017.0 / 3168 * k1_ - 355.0 / 33 * k2 + 46732.0 / 5247 * k3 +
                         49.0 / 176 * k4 - 5103.0 / 18656 * k5),
               k6);
      const State y = x_ + h * (35.0 / 384 * k1_ + 500.0 / 1113 * k3 + 125.0 / 192 * k4 -
                                2187.0 / 6784 * k5 + 11.0 / 84 * k6);
      sys_.rhs(t_ + h, y, k7);
      // The 5th-order solution minus the embedded 4th-order one.
      const State e = h * (71.0 / 57600 * k1_ - 71.0 / 16695 * k3 + 71.0 / 1920 * k4 -
                           17253.0 / 339200 * k5 + 22.0 / 525 * k6 - 1.0 / 40 * k7);
      double sum = 0;
      for (int i = 0; i < Sys::dim; ++i) {
        const double sk = tol_ + tol_ * std::max(std::abs(x_[i]), std::abs(y[i]));
        sum += (e[i] / sk) * (e[i] / sk);
      }
      const double err = std::sqrt(sum / Sys::dim);
      // DOPRI5's defaults: safety 0.9, beta 0.04, exponent 1/5 - 0.75 beta,
      // factors within [0.2, 10], the previous error at least 1e-4.
      if (err <= 1.0) {
        double fac = 0.9 * std::pow(err, -0.17) * std::pow(err_old_, 0.04);
        fac = std::clamp(fac, 0.2, 10.0);
        if (last_rejected_) fac = std::min(fac, 1.0);
        err_old_ = std::max(err, 1e-4);
        t_ += h;
        h_last_ = h;
        x_ = y;
        k1_ = k7;
        h_ = h * fac;
        last_rejected_ = false;
        ++steps_;
        return;
      }
      h_ = h * std::max(0.2, 0.9 * std::pow(err, -0.17));
      last_rejected_ = true;
      ++rejected_;
    }
  }

  double t() const { return t_; }
  double h_last() const { return h_last_; }
  const State& state() const { return x_; }
  long steps() const { return steps_; }
  long rejected() const { return rejected_; }

 private:
  Sys sys_;
  double tol_, t_, h_, h_last_ = 0;
  State x_, k1_;
  double err_old_ = 1e-4;
  bool last_rejected_ = false;
  long steps_ = 0, rejected_ = 0;
};

// Both from (0, x0) with first trial step h0, accepted step by accepted step.
template <class Sys>
void expect_same_steps(const Sys& sys, const typename Sys::State& x0, double tol, double h0,
                       int steps) {
  AdaptiveOptions o;
  o.rtol = o.atol = tol;
  o.h_init = h0;
  Dopri5<Sys> ours(sys, o);
  ours.init(0.0, x0);
  TextbookDopri5<Sys> book(sys, tol, 0.0, x0, h0);
  for (int n = 1; n <= steps; ++n) {
    ours.step();
    book.step();
    ASSERT_EQ(ours.stats().rejected_steps, book.rejected()) << "step " << n;
    ASSERT_NEAR(ours.h_last(), book.h_last(), 1e-8 * book.h_last()) << "step " << n;
    // The states at the textbook's time (ours interpolated over the few
    // 1e-10 of a step between the two ends).
    const double scale = 1.0 + book.state().cwiseAbs().maxCoeff();
    ASSERT_LT((ours.dense(book.t()) - book.state()).cwiseAbs().maxCoeff(), 1e-12 * scale)
        << "step " << n;
  }
  EXPECT_GT(book.rejected(), 0);  // the large first trial step is rejected
}

TEST(Dopri5Textbook, SameStepsOnKepler) {
  const Kepler k{0.6};
  expect_same_steps(k, k.initial(), 1e-9, 0.5, 300);
}

TEST(Dopri5Textbook, SameStepsOnTheHeavyTop) {
  const HeavyTop top;
  expect_same_steps(top, top.initial(), 1e-10, 1.0, 300);
}

TEST(Dopri5Textbook, SameStepsInAnOddDimension) {
  expect_same_steps(FreeRigidBody{}, FreeRigidBody::State(1.0, 0.2, -0.5), 1e-8, 2.0, 300);
}

}  // namespace
}  // namespace epviz::numerics
