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
