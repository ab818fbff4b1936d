// Consistency of the Butcher tableaus: row sums and the order conditions that
// can be checked directly from the coefficients (an independent check of the
// transcribed numbers; the convergence tests check the rest).
#include <gtest/gtest.h>

#include <cmath>

#include "numerics/gauss_legendre.hpp"
#include "numerics/rk_tableaus.hpp"

namespace epviz::numerics {
namespace {

template <class T>
void expect_row_sums() {
  for (int i = 0; i < T::total; ++i) {
    double s = 0;
    for (int j = 0; j < T::total; ++j) {
      s += T::a[i][j];
      if (j >= i) {
        EXPECT_EQ(T::a[i][j], 0.0) << "explicit: a[" << i << "][" << j << "]";
      }
    }
    EXPECT_NEAR(s, T::c[i], 1e-14) << T::name << " row " << i;
  }
}

// sum_i b_i c_i^(k-1) = 1/k for k = 1..q (quadrature order q).
template <class Row>
void expect_quadrature(const Row& b, const Row& c, int n, int q, const char* what) {
  for (int k = 1; k <= q; ++k) {
    double s = 0;
    for (int i = 0; i < n; ++i) s += b[i] * std::pow(c[i], k - 1);
    EXPECT_NEAR(s, 1.0 / k, 1e-14) << what << " k = " << k;
  }
}

// sum_ij b_i c_i^m a_ij c_j^l = 1/((l+1)(l+m+2)) (bushy-tree conditions with one
// extra level), for l + m + 2 <= q.
template <class T>
void expect_second_level(int q) {
  for (int l = 0; l + 2 <= q; ++l)
    for (int m = 0; l + m + 2 <= q; ++m) {
      double s = 0;
      for (int i = 0; i < T::stages; ++i)
        for (int j = 0; j < i; ++j)
          s += T::b[i] * std::pow(T::c[i], m) * T::a[i][j] * std::pow(T::c[j], l);
      EXPECT_NEAR(s, 1.0 / ((l + 1.0) * (l + m + 2.0)), 1e-13)
          << T::name << " l=" << l << " m=" << m;
    }
}

TEST(Tableau, Dopri5RowSumsAndOrderConditions) {
  using T = Dopri5Tableau;
  expect_row_sums<T>();
  expect_quadrature(T::b, T::c, T::total, 5, "dopri5 b");
  expect_second_level<T>(5);
  // The embedded 4th-order weights b - e are a quadrature of order 4, not 5.
  T::Row bhat{};
  for (int i = 0; i < T::total; ++i) bhat[i] = T::b[i] - T::e[i];
  expect_quadrature(bhat, T::c, T::total, 4, "dopri5 bhat");
  double s5 = 0;
  for (int i = 0; i < T::total; ++i) s5 += bhat[i] * std::pow(T::c[i], 4);
  EXPECT_GT(std::abs(s5 - 0.2), 1e-6);
  // The dense rows vanish on constants (the interpolant is exact at both ends).
  double sd = 0;
  for (double v : T::d[0]) sd += v;
  EXPECT_NEAR(sd, 0.0, 1e-13);
}

TEST(Tableau, Dop853RowSumsAndOrderConditions) {
  using T = Dop853Tableau;
  expect_row_sums<T>();
  expect_quadrature(T::b, T::c, T::stages, 8, "dop853 b");
  expect_second_level<T>(8);
  double se = 0, se2 = 0;
  for (int i = 0; i < T::total; ++i) {
    se += T::e[i];
    se2 += T::e2[i];
  }
  EXPECT_NEAR(se, 0.0, 1e-14);
  EXPECT_NEAR(se2, 0.0, 1e-14);
  // The dense rows vanish on constants (the interpolant reproduces linear solutions).
  for (const auto& row : T::d) {
    double sd = 0;
    for (double v : row) sd += v;
    EXPECT_NEAR(sd, 0.0, 1e-11);
  }
}

template <int S>
void expect_gauss() {
  using T = GaussTableau<S>;
  // B(2s): quadrature of order 2s; C(s): sum_j a_ij c_j^(k-1) = c_i^k / k.
  for (int k = 1; k <= 2 * S; ++k) {
    double s = 0;
    for (int i = 0; i < S; ++i) s += T::b[i] * std::pow(T::c[i], k - 1);
    EXPECT_NEAR(s, 1.0 / k, 1e-15) << T::name << " B k=" << k;
  }
  for (int i = 0; i < S; ++i)
    for (int k = 1; k <= S; ++k) {
      double s = 0;
      for (int j = 0; j < S; ++j) s += T::a[i][j] * std::pow(T::c[j], k - 1);
      EXPECT_NEAR(s, std::pow(T::c[i], k) / k, 1e-15) << T::name << " C i=" << i << " k=" << k;
    }
  // Symplecticity: b_i a_ij + b_j a_ji = b_i b_j.
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < S; ++j)
      EXPECT_NEAR(T::b[i] * T::a[i][j] + T::b[j] * T::a[j][i], T::b[i] * T::b[j], 1e-15);
}

TEST(Tableau, GaussLegendreConditions) {
  expect_gauss<1>();
  expect_gauss<2>();
  expect_gauss<3>();
}

}  // namespace
}  // namespace epviz::numerics
