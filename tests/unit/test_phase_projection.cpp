// Unit tests of the pointwise phase projection (the paper's cases i-v, docs/model.md#thresholds).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/phase_projection.hpp"

using sma::Phase;
using sma::project_phase;

namespace {
// Intermediate temperature: alpha > 0, c > 0, thresholds at +-c/alpha = +-0.0125 (the beam's data).
constexpr double kAlpha = 0.8e9, kC = 0.01e9, kThreshold = kC / kAlpha;

// phi2(t) = max(alpha |t| - c, 0): its difference quotient brackets any subgradient s.
double phi2(double t, double alpha, double c) { return std::fmax(alpha * std::fabs(t) - c, 0.0); }
}  // namespace

TEST(PhaseProjection, CaseI_BelowMinusThresholdIsMartensite2) {
  EXPECT_EQ(project_phase(-1.01 * kThreshold, kAlpha, kC, Phase::Austenite), Phase::Martensite2);
  EXPECT_EQ(sma::spherical_stress(Phase::Martensite2, kAlpha), -kAlpha);
}

TEST(PhaseProjection, CaseII_AboveThresholdIsMartensite1) {
  EXPECT_EQ(project_phase(1.01 * kThreshold, kAlpha, kC, Phase::Austenite), Phase::Martensite1);
  EXPECT_EQ(project_phase(1.01 * kThreshold, kAlpha, kC, Phase::Martensite2), Phase::Martensite1);
  EXPECT_EQ(sma::spherical_stress(Phase::Martensite1, kAlpha), kAlpha);
}

TEST(PhaseProjection, CaseIII_BetweenThresholdsIsAustenite) {
  for (double t : {-0.99 * kThreshold, 0.0, 0.5 * kThreshold, 0.99 * kThreshold})
    for (Phase prev : {Phase::Austenite, Phase::Martensite1, Phase::Martensite2})
      EXPECT_EQ(project_phase(t, kAlpha, kC, prev), Phase::Austenite) << "t=" << t;
}

TEST(PhaseProjection, CaseIV_ExactTieAtPlusThresholdKeepsAdmissiblePreviousPhase) {
  // Pick t, alpha, c exactly representable so that alpha*t == c with no rounding.
  const double alpha = 4.0, c = 1.0, t = 0.25;
  ASSERT_EQ(alpha * t, c);
  EXPECT_EQ(project_phase(t, alpha, c, Phase::Austenite), Phase::Austenite);
  EXPECT_EQ(project_phase(t, alpha, c, Phase::Martensite1), Phase::Martensite1);
  // Martensite 2 is not a minimiser there: first minimiser in order is austenite.
  EXPECT_EQ(project_phase(t, alpha, c, Phase::Martensite2), Phase::Austenite);
}

TEST(PhaseProjection, CaseV_ExactTieAtMinusThresholdKeepsAdmissiblePreviousPhase) {
  const double alpha = 4.0, c = 1.0, t = -0.25;
  EXPECT_EQ(project_phase(t, alpha, c, Phase::Austenite), Phase::Austenite);
  EXPECT_EQ(project_phase(t, alpha, c, Phase::Martensite2), Phase::Martensite2);
  EXPECT_EQ(project_phase(t, alpha, c, Phase::Martensite1), Phase::Austenite);
}

TEST(PhaseProjection, BelowT0AusteniteIsNeverStable) {
  // T < T0 makes c < 0: every trace gives a martensite, the sign of t choosing which.
  const double alpha = 2.0e8, c = -1.58e6;
  for (double t : {-1e-2, -1e-9, 1e-9, 1e-2}) {
    const Phase p = project_phase(t, alpha, c, Phase::Austenite);
    EXPECT_NE(p, Phase::Austenite) << "t=" << t;
    EXPECT_EQ(p, t > 0 ? Phase::Martensite1 : Phase::Martensite2) << "t=" << t;
  }
  // t = 0 exactly ties the two martensites: keep the previous one, else martensite 1.
  EXPECT_EQ(project_phase(0.0, alpha, c, Phase::Martensite2), Phase::Martensite2);
  EXPECT_EQ(project_phase(0.0, alpha, c, Phase::Martensite1), Phase::Martensite1);
  EXPECT_EQ(project_phase(0.0, alpha, c, Phase::Austenite), Phase::Martensite1);
}

TEST(PhaseProjection, AboveTcOnlyAustenite) {
  // T >= Tc makes alpha = 0 and c > 0.
  for (double t : {-1.0, -1e-3, 0.0, 1e-3, 1.0})
    for (Phase prev : {Phase::Austenite, Phase::Martensite1, Phase::Martensite2})
      EXPECT_EQ(project_phase(t, 0.0, 7.5e6, prev), Phase::Austenite);
  // T0 = Tc = T: alpha = c = 0, everything ties: nothing moves, austenite by default; s = 0 anyway.
  EXPECT_EQ(project_phase(0.3, 0.0, 0.0, Phase::Austenite), Phase::Austenite);
  EXPECT_EQ(sma::spherical_stress(project_phase(0.3, 0.0, 0.0, Phase::Martensite1), 0.0), 0.0);
}

TEST(PhaseProjection, SelectionIsASubgradientOfPhi2) {
  // s in d phi2(t) <=> phi2(t') >= phi2(t) + s (t' - t) for all t'. Check on a grid and all regimes.
  const double regimes[][2] = {{kAlpha, kC}, {2e8, -1.58e6}, {0.0, 7.5e6}, {4.0, 1.0}};
  for (auto& r : regimes) {
    const double alpha = r[0], c = r[1];
    for (int i = -40; i <= 40; ++i) {
      const double t = i * 0.001;
      for (Phase prev : {Phase::Austenite, Phase::Martensite1, Phase::Martensite2}) {
        const double s = sma::spherical_stress(project_phase(t, alpha, c, prev), alpha);
        for (int j = -50; j <= 50; ++j) {
          const double tp = j * 0.00093;
          EXPECT_GE(phi2(tp, alpha, c) - phi2(t, alpha, c) - s * (tp - t),
                    -1e-9 * (std::fabs(alpha) + std::fabs(c)))
              << "alpha=" << alpha << " c=" << c << " t=" << t << " t'=" << tp;
        }
      }
    }
  }
}

TEST(PhaseProjection, ArrayVersionCountsChangesAndWritesStress) {
  std::vector<double> t{-0.02, 0.0, 0.02, 0.02, 0.001};
  std::vector<double> alpha(5, kAlpha), c(5, kC), s(5, 123.0);
  std::vector<double> phase{0, 0, 1, 0, 2};
  const std::size_t changed = sma::project_phases(t, alpha, c, s, phase);
  EXPECT_EQ(changed, 3u);  // 0->2, unchanged, unchanged, 0->1, 2->0
  EXPECT_EQ(phase, (std::vector<double>{2, 0, 1, 1, 0}));
  EXPECT_EQ(s, (std::vector<double>{-kAlpha, 0, kAlpha, kAlpha, 0}));
  // A second call with the same strains is a fixed point: nothing changes.
  EXPECT_EQ(sma::project_phases(t, alpha, c, s, phase), 0u);
}

TEST(PhaseProjection, RejectsBadInput) {
  std::vector<double> t(3, 0.0), alpha(3, 1.0), c(3, 0.1), s(3), phase(2);
  EXPECT_THROW(sma::project_phases(t, alpha, c, s, phase), std::invalid_argument);
  std::vector<double> phase3(3, 0.0), negative_alpha{1.0, -1.0, 1.0};
  EXPECT_THROW(sma::project_phases(t, negative_alpha, c, s, phase3), std::domain_error);
  EXPECT_THROW(project_phase(std::numeric_limits<double>::quiet_NaN(), 1.0, 0.1, Phase::Austenite),
               std::domain_error);
}

TEST(Phi2Conjugate, MatchesFenchelSupremumNumerically) {
  // phi2*(s) = sup_t (s t - phi2(t)); evaluate the sup on a fine grid and compare.
  const double regimes[][2] = {{kAlpha, kC}, {2e8, -1.58e6}};
  for (auto& r : regimes) {
    const double alpha = r[0], c = r[1];
    for (double frac : {-1.0, -0.6, 0.0, 0.3, 1.0}) {
      const double s = frac * alpha;
      double sup = -INFINITY;
      for (int j = -200000; j <= 200000; ++j) {
        const double t = j * 1e-6;
        sup = std::fmax(sup, s * t - phi2(t, alpha, c));
      }
      EXPECT_NEAR(sma::phi2_conjugate(s, alpha, c), sup, 1e-9 * (alpha + std::fabs(c)))
          << "alpha=" << alpha << " c=" << c << " s=" << s;
    }
    EXPECT_EQ(sma::phi2_conjugate(1.01 * alpha, alpha, c), INFINITY);
  }
}

TEST(AuchmutyLocal, ProjectionMinimisesTheLocalPart) {
  // The local DC step minimises w (phi2*(s) - t s) over s: no other admissible s does better.
  std::vector<double> t{-0.03, -0.0125, 0.0, 0.004, 0.02}, alpha(5, kAlpha), c(5, kC), w(5, 0.7);
  std::vector<double> s(5), phase(5, 0.0);
  sma::project_phases(t, alpha, c, s, phase);
  const double best = sma::auchmuty_local_part(t, alpha, c, s, w);
  for (int trial = -10; trial <= 10; ++trial) {
    std::vector<double> other(5, trial / 10.0 * kAlpha);
    EXPECT_LE(best, sma::auchmuty_local_part(t, alpha, c, other, w) + 1e-6);
  }
}

TEST(QuadratureWeights, P1OnePointP2ThreeMidEdgePoints) {
  std::vector<double> area{0.5, 1.5}, w1(2), w3(6);
  sma::quadrature_weights(area, 1, w1);
  EXPECT_EQ(w1, area);
  sma::quadrature_weights(area, 3, w3);
  EXPECT_DOUBLE_EQ(w3[0] + w3[1] + w3[2], 0.5);
  EXPECT_DOUBLE_EQ(w3[3], 0.5);
  std::vector<double> wrong(5);
  EXPECT_THROW(sma::quadrature_weights(area, 3, wrong), std::invalid_argument);
  EXPECT_THROW(sma::quadrature_weights(area, 2, w3), std::invalid_argument);
}

TEST(QuadratureWeights, P2PointsProjectIndependently) {
  // Three mid-edge points of one P2 triangle with an affine strain crossing the threshold:
  // each point gets its own phase (the local step never couples points).
  std::vector<double> t{-0.02, 0.0, 0.02}, alpha(3, kAlpha), c(3, kC), s(3), phase(3, 0.0);
  EXPECT_EQ(sma::project_phases(t, alpha, c, s, phase), 2u);
  EXPECT_EQ(phase, (std::vector<double>{2, 0, 1}));
}
