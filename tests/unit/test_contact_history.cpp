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

TEST(ContactHistory, ProbeColumnsAreTemperaturePressureAndGapInTheScriptsOrder) {
  // two probe points: contact node 1 on vertex 2, node 0 on vertex 0; 3 vertices, u interleaved
  const ch::ProbePoint points[] = {{1, 2, 0.6, 0.8, 1e-5}, {0, 0, -1.0, 0.0, -1.0}};
  const double T[] = {250, 260, 270}, pressure[] = {7e6, 8e6};
  const double u[] = {-1.5e-16, 0, 0, 0, 1e-6, 2e-6};
  const double motion[] = {-1.0, 2e-7};
  double row[6];
  ch::probe_columns(points, 2, T, pressure, u, nullptr, row);
  EXPECT_EQ(row[0], 270);
  EXPECT_EQ(row[1], 8e6);
  EXPECT_EQ(row[2], (0.6 * 1e-6 + 0.8 * 2e-6) + 1e-5);
  EXPECT_EQ(row[3], 250);
  EXPECT_EQ(row[4], 7e6);
  EXPECT_EQ(row[5], 1.5e-16 + -1.0);
  ch::probe_columns(points, 2, T, pressure, u, motion, row);
  EXPECT_EQ(row[2], ((0.6 * 1e-6 + 0.8 * 2e-6) - 2e-7) + 1e-5);
  // (n.u - motion) + gap0: 1 + 1.5e-16 rounds up to 1 + 2^-52 first; n.u + (gap0 - motion) would
  // be 1.5e-16
  EXPECT_EQ(row[5], 0x1p-52);
  EXPECT_NE(row[5], 1.5e-16 + (-1.0 - -1.0));
}
