// The step's discrete heat balance (plugin/core/heat_balance.hpp): the stored heat against values
// worked out by hand, the differences formed before the products (the script's dT = T1 - T0 first),
// and the relative residual against its formula written out here, with and without dissipation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/heat_balance.hpp"

namespace hb = sma::heat_balance;

TEST(HeatBalance, StoredHeatIsTheCapacityTimesTheTemperatureChange) {
  const double c[3] = {2.0, 0.5, 4.0}, T0[3] = {300.0, 310.0, 320.0}, T1[3] = {301.0, 308.0, 320.25};
  EXPECT_EQ(hb::stored(c, T1, T0, 3), 2.0);  // 2 * 1 + 0.5 * (-2) + 4 * 0.25
  EXPECT_EQ(hb::stored(c, T1, T0, 0), 0.0);
}

TEST(HeatBalance, StoredHeatFormsEachTemperatureChangeFirst) {
  // c'T1 - c'T0 would round 1e16 + 3 to 1e16 + 4 and give 4; the changes [2, 1] give 3 exactly.
  const double c[2] = {1.0, 1.0}, T0[2] = {1e16, 0.0}, T1[2] = {1e16 + 2.0, 1.0};
  EXPECT_EQ(hb::stored(c, T1, T0, 2), 3.0);
}

TEST(HeatBalance, ResidualIsTheBudgetsRelativeMismatch) {
  EXPECT_EQ(hb::relative_residual(1.0, 0.75, 0.25, 0.0), 0.0);            // balanced
  EXPECT_DOUBLE_EQ(hb::relative_residual(1.25, 1.0, 0.0, 0.0), 0.2);      // 0.25 / 1.25
  EXPECT_DOUBLE_EQ(hb::relative_residual(3.0, 1.0, 1.0, 0.0), 1.0 / 3.0); // the dissipated heat missing
  EXPECT_EQ(hb::relative_residual(3.0, 1.0, 1.0, 1.0), 0.0);              // ... and counted
  EXPECT_DOUBLE_EQ(hb::relative_residual(-1.0, 2.0, -4.0, 0.0), 1.0 / 6.0);  // |-1 + 2| / (2 + 4)
  EXPECT_EQ(hb::relative_residual(0.0, 0.0, -0.0, 0.0), 0.0);             // nothing moved
}

TEST(HeatBalance, NoDissipationGivesTheFormulaWithoutItBitForBit) {
  // The time loop passes 0 without dissipation: the same bits as budget = entered + released,
  // scale = max(|stored|, |entered| + |released|), signed zeros included.
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  const double zeros[2] = {0.0, -0.0};
  for (int k = 0; k < 2000; ++k) {
    double s = value(gen), e = value(gen), r = value(gen);
    if (k % 10 == 0) e = zeros[k % 20 == 0];
    if (k % 15 == 0) r = zeros[k % 30 == 0];
    if (k % 7 == 0) s = e + r;
    const double scale = std::max(std::fabs(s), std::fabs(e) + std::fabs(r));
    const double expected = scale > 0 ? std::fabs(s - (e + r)) / scale : 0.0;
    const double got = hb::relative_residual(s, e, r, 0.0);
    EXPECT_EQ(std::signbit(got), std::signbit(expected));
    EXPECT_EQ(got, expected) << s << " " << e << " " << r;
  }
}
