// Unit tests of the temperature dependence of the law (docs/model.md#temperature-dependence;
// the paper's data: docs/model.md#data).
#include <gtest/gtest.h>

#include <vector>

#include "core/material.hpp"

namespace {
const sma::ThermalLaw kNiTi{7900, 300, 3000, 210, 280};  // the paper's data (docs/model.md#data)
}

TEST(Material, AlphaIsPositiveBelowTcZeroAboveAndContinuous) {
  EXPECT_DOUBLE_EQ(kNiTi.alpha(196), 7900.0 * 300 * 84);  // 1.99e8 Pa
  EXPECT_GT(kNiTi.alpha(250), 0);
  EXPECT_DOUBLE_EQ(kNiTi.alpha(280), 0);
  EXPECT_DOUBLE_EQ(kNiTi.alpha(300), 0);
  EXPECT_NEAR(kNiTi.alpha(280 - 1e-9), 0, 1e-2);  // no jump at Tc
}

TEST(Material, CChangesSignAtT0) {
  EXPECT_LT(kNiTi.c(196), 0);
  EXPECT_DOUBLE_EQ(kNiTi.c(210), 0);
  EXPECT_NEAR(kNiTi.c(211), 7900.0 * 3000 / 210, 1e-6);
}

TEST(Material, ReverseTransformationOfAFreeRingNear212K) {
  // A stress-free martensite point has tr e = alpha/(lambda+mu) (plane strain); it turns back to
  // austenite when alpha tr e = c, i.e. alpha^2 = c (lambda + mu): T* = 212.75 K
  // (docs/model.md#thresholds).
  const double E = 85e9, nu = 0.3, bulk = E / (2 * (1 + nu) * (1 - 2 * nu));
  double lo = 210, hi = 280;
  for (int i = 0; i < 100; ++i) {
    const double T = 0.5 * (lo + hi);
    (kNiTi.alpha(T) * kNiTi.alpha(T) > kNiTi.c(T) * bulk ? lo : hi) = T;
  }
  EXPECT_GT(lo, 212.0);
  EXPECT_LT(lo, 213.0);
}

TEST(Material, ArrayVersionAndValidation) {
  std::vector<double> T{196, 250, 300}, alpha(3), c(3);
  sma::phase_coefficients(kNiTi, T, alpha, c);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(alpha[i], kNiTi.alpha(T[i]));
    EXPECT_EQ(c[i], kNiTi.c(T[i]));
  }
  sma::ThermalLaw bad = kNiTi;
  bad.T0 = 300;  // T0 > Tc
  EXPECT_THROW(sma::phase_coefficients(bad, T, alpha, c), std::invalid_argument);
  std::vector<double> short_alpha(2);
  EXPECT_THROW(sma::phase_coefficients(kNiTi, T, short_alpha, c), std::invalid_argument);
}
