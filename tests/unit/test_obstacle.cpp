// Unit tests of the rigid obstacles' gap and normal (plugin/core/obstacle.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/obstacle.hpp"

TEST(Obstacle, CircleGapAndNormal) {
  const sma::ContactGeometry g = sma::circle_gap(0.0, 0.05, 0.0, 0.0005, 0.0505);
  EXPECT_NEAR(g.gap, 0.05 - 0.0005 - 0.0505, 1e-15);  // offset pipe, point on the y axis
  EXPECT_DOUBLE_EQ(g.nx, 0.0);
  EXPECT_DOUBLE_EQ(g.ny, 1.0);
  EXPECT_THROW(sma::circle_gap(1, 1, 1, 1, 1), std::invalid_argument);
  EXPECT_THROW(sma::circle_gap(1, 0, 0, 0, -1), std::invalid_argument);
}

TEST(Obstacle, EllipseWithEqualAxesIsTheCircle) {
  for (double angle = 0.0; angle < 2 * M_PI; angle += 0.3) {
    for (double r : {0.049, 0.0505, 0.052}) {
      const double px = r * std::cos(angle), py = r * std::sin(angle);
      const sma::ContactGeometry e = sma::ellipse_gap(px, py, 0, 0, 0.0505, 0.0505);
      const sma::ContactGeometry c = sma::circle_gap(px, py, 0, 0, 0.0505);
      EXPECT_NEAR(e.gap, c.gap, 1e-14);
      EXPECT_NEAR(e.nx, c.nx, 1e-12);
      EXPECT_NEAR(e.ny, c.ny, 1e-12);
    }
  }
}

TEST(Obstacle, EllipseClosestPointMatchesBruteForce) {
  // The paper's ellipse (5.04 x 5.05 cm, major axis vertical) and a flat one, points inside and
  // outside, all quadrants: the distance equals the minimum over a fine sampling of the curve, and
  // p - gap * n lies on the ellipse.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), radius(0.6, 1.6);
  const double axes[][2] = {{0.0504, 0.0505}, {0.05, 0.02}};
  for (auto& ab : axes) {
    const double A = ab[0], B = ab[1];
    for (int trial = 0; trial < 200; ++trial) {
      const double th = angle(rng), rr = radius(rng);
      const double px = 0.001 + rr * A * std::cos(th), py = -0.002 + rr * B * std::sin(th);
      const sma::ContactGeometry g = sma::ellipse_gap(px, py, 0.001, -0.002, A, B);
      // Independent: sample the curve, then refine around the best sample by ternary search.
      auto dist = [&](double t) { return std::hypot(px - 0.001 - A * std::cos(t), py + 0.002 - B * std::sin(t)); };
      const int n = 20000;
      int kbest = 0;
      for (int k = 1; k < n; ++k)
        if (dist(2 * M_PI * k / n) < dist(2 * M_PI * kbest / n)) kbest = k;
      double lo = 2 * M_PI * (kbest - 1) / n, hi = 2 * M_PI * (kbest + 1) / n;
      for (int it = 0; it < 200; ++it) {
        const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        (dist(m1) < dist(m2) ? hi : lo) = (dist(m1) < dist(m2) ? m2 : m1);
      }
      const double best = dist(0.5 * (lo + hi));
      EXPECT_NEAR(std::fabs(g.gap), best, 1e-12 * A) << "A=" << A << " B=" << B << " trial " << trial;
      const double qx = px - g.gap * g.nx - 0.001, qy = py - g.gap * g.ny + 0.002;
      EXPECT_NEAR((qx / A) * (qx / A) + (qy / B) * (qy / B), 1.0, 1e-10);
      EXPECT_NEAR(std::hypot(g.nx, g.ny), 1.0, 1e-14);
    }
  }
}

TEST(Obstacle, EllipseNormalOnAnAxisIsExact) {
  // On an axis, outside the evolute's cusp, the closest point is the vertex: the normal is the
  // axis itself, with no round-off component across it (Newton's t for pi / 2 gave 6e-17).
  const double axes[][2] = {{0.0504, 0.0505}, {0.0505, 0.0504}, {0.05, 0.02}, {0.02, 0.05}};
  for (auto& ab : axes) {
    const double A = ab[0], B = ab[1];
    for (double scale : {0.9999, 1.0, 1.03, 2.0}) {
      for (double sign : {1.0, -1.0}) {
        // (inside the evolute's cusp the closest points are off the axis: not this case)
        const double y = sign * scale * B;
        if (B * std::fabs(y) >= B * B - A * A) {
          const sma::ContactGeometry g = sma::ellipse_gap(0.003, 0.004 + y, 0.003, 0.004, A, B);
          EXPECT_EQ(g.nx, 0.0) << A << " " << B << " y " << y;
          EXPECT_EQ(g.ny, sign);
          EXPECT_NEAR(g.gap, std::fabs(y) - B, 1e-15);
        }
        const double x = sign * scale * A;
        if (A * std::fabs(x) >= A * A - B * B) {
          const sma::ContactGeometry h = sma::ellipse_gap(0.003 + x, 0.004, 0.003, 0.004, A, B);
          EXPECT_EQ(h.ny, 0.0) << A << " " << B << " x " << x;
          EXPECT_EQ(h.nx, sign);
          EXPECT_NEAR(h.gap, std::fabs(x) - A, 1e-15);
        }
      }
    }
  }
  // Inside the cusp on the major axis: the closest points are off the axis, as the sampling finds.
  const sma::ContactGeometry c = sma::ellipse_gap(0.0, 0.005, 0.0, 0.0, 0.02, 0.05);
  EXPECT_NE(c.nx, 0.0);
  EXPECT_LT(std::fabs(c.gap), 0.05 - 0.005);
}
