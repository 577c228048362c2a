// The per-step records of the contact nodes (plugin/core/contact_history.hpp), on hand-made nodes.
#include <gtest/gtest.h>

#include "core/contact_history.hpp"

namespace ch = sma::contact_history;

TEST(ContactHistory, TouchingCountsPositiveNormalReactions) {
  const double r[] = {1.5, -3, 0, 2, -0.0, 0, 1e-300, 0};  // (n, t) per node
  EXPECT_EQ(ch::touching(r, 4), 2);
  EXPECT_EQ(ch::touching(r, 0), 0);
}

TEST(ContactHistory, PeaksKeepTheHighestPressureAndItsStep) {
  double peak[] = {1, 5, 2};
  long step[] = {3, 4, 7};
  const double p1[] = {2, 5, 1};  // node 0 rises, node 1 equals its peak (no new step), node 2 falls
  ch::record_peaks(p1, 3, 10, peak, step);
  EXPECT_EQ(peak[0], 2); EXPECT_EQ(step[0], 10);
  EXPECT_EQ(peak[1], 5); EXPECT_EQ(step[1], 4);
  EXPECT_EQ(peak[2], 2); EXPECT_EQ(step[2], 7);
}

TEST(ContactHistory, SlipCountsOnlyAboveNoiseWhileTouching) {
  const double slip[] = {2e-12, -2e-12, 5e-13, 3e-12};
  const double r[] = {1, 0, 1, 0, 1, 0, 0, 0};  // node 3 not touching
  long last[] = {0, 0, 0, 0};
  ch::record_slip(slip, r, 4, 1e-12, 8, last);
  EXPECT_EQ(last[0], 8);
  EXPECT_EQ(last[1], 8);  // |slip|
  EXPECT_EQ(last[2], 0);  // below the noise
  EXPECT_EQ(last[3], 0);  // free
}

TEST(ContactHistory, HeatExchangeByContactStatus) {
  // 3 contact nodes on heat nodes 4, 0, 2 of 5; node 0 presses, node 1 has r_n = 0, node 2 pulls.
  const long node[] = {4, 0, 2};
  const double r[] = {3.0, 1.0, 0.0, 5.0, -1e-9, 0.0};
  double g[] = {10, 10, 10, 10, 10}, Text[] = {293, 293, 293, 293, 293};
  EXPECT_EQ(ch::heat_exchange(node, r, 3, 2000, 500, 300, g, Text), 1);
  const double gWant[] = {500, 10, 500, 10, 2000}, TWant[] = {300, 293, 300, 293, 300};
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(g[k], gWant[k]) << k;
    EXPECT_EQ(Text[k], TWant[k]) << k;
  }
}
