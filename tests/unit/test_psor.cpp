// Unit tests of the condensed projected SOR (plugin/core/psor.hpp).
// Frictionless: the PSOR solution equals the exact LCP solution found by enumerating every active
// set (<= 1e-10 relative) on random SPD problems. Tresca: the result satisfies the contact laws
// (natural-map residual ~ 0), the Coulomb-cone bound |r_t| <= g and complementarity.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "core/psor.hpp"
#include "random_problems.hpp"

namespace {

using sma_test::random_spd;

// Frictionless Signorini on the normal components only: LCP  r >= 0, W r - q >= 0, r'(W r - q) = 0,
// solved exactly by trying every active set (components with r > 0).
Eigen::VectorXd lcp_by_enumeration(const Eigen::MatrixXd& W, const Eigen::VectorXd& q) {
  const int n = static_cast<int>(q.size());
  for (int mask = 0; mask < (1 << n); ++mask) {
    std::vector<int> active;
    for (int i = 0; i < n; ++i)
      if (mask & (1 << i)) active.push_back(i);
    Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
    if (!active.empty()) {
      const int k = static_cast<int>(active.size());
      Eigen::MatrixXd Wa(k, k);
      Eigen::VectorXd qa(k);
      for (int a = 0; a < k; ++a) {
        qa[a] = q[active[a]];
        for (int b = 0; b < k; ++b) Wa(a, b) = W(active[a], active[b]);
      }
      const Eigen::VectorXd ra = Wa.ldlt().solve(qa);
      bool ok = true;
      for (int a = 0; a < k; ++a) ok = ok && ra[a] >= 0;
      if (!ok) continue;
      for (int a = 0; a < k; ++a) r[active[a]] = ra[a];
    }
    const Eigen::VectorXd w = W * r - q;
    bool feasible = true;
    for (int i = 0; i < n; ++i) feasible = feasible && w[i] >= -1e-12 * q.norm();
    if (feasible) return r;
  }
  throw std::runtime_error("no active set solves the LCP");
}

}  // namespace

TEST(PsorCondensed, FrictionlessEqualsActiveSetEnumeration) {
  std::mt19937 rng(20261121);
  std::normal_distribution<double> normal;
  double worst = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const int m = 1 + trial % 6;  // contact nodes
    const Eigen::MatrixXd W = random_spd(2 * m, rng);
    Eigen::VectorXd q(2 * m);
    for (int k = 0; k < 2 * m; ++k) q[k] = normal(rng);
    const Eigen::VectorXd g = Eigen::VectorXd::Zero(m);  // frictionless: r_t = 0
    Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * m);
    const sma::PsorResult res = sma::psor_condensed(W, q, g, 1.5, 1e-14, 100000, r);
    ASSERT_TRUE(res.converged) << "trial " << trial << " residual " << res.residual;
    // Exact: the normal block alone (tangential reactions are zero).
    Eigen::MatrixXd Wn(m, m);
    Eigen::VectorXd qn(m);
    for (int i = 0; i < m; ++i) {
      qn[i] = q[2 * i];
      for (int j = 0; j < m; ++j) Wn(i, j) = W(2 * i, 2 * j);
    }
    const Eigen::VectorXd exact = lcp_by_enumeration(Wn, qn);
    Eigen::VectorXd rn(m);
    for (int i = 0; i < m; ++i) rn[i] = r[2 * i];
    const double err = (rn - exact).norm() / std::max(exact.norm(), 1e-300);
    worst = std::max(worst, exact.norm() > 0 ? err : rn.norm());
    EXPECT_LE(exact.norm() > 0 ? err : rn.norm(), 1e-10) << "trial " << trial;
  }
  std::cout << "largest relative difference to the enumerated LCP solution: " << worst << "\n";
}

TEST(PsorCondensed, TrescaSatisfiesTheContactLaws) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    const int m = 1 + trial % 5;
    const sma_test::TrescaProblem p = sma_test::random_tresca(m, 1.0, false, rng);
    const Eigen::MatrixXd& W = p.W;
    const Eigen::VectorXd &q = p.q, &g = p.g;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * m);
    for (double omega : {1.0, 1.88}) {
      const sma::PsorResult res = sma::psor_condensed(W, q, g, omega, 1e-14, 200000, r);
      ASSERT_TRUE(res.converged);
      EXPECT_LE(sma::contact_law_residual(W, q, g, r), 1e-10);
      const Eigen::VectorXd w = W * r - q;
      for (int i = 0; i < m; ++i) {
        EXPECT_GE(r[2 * i], 0.0);
        EXPECT_GE(w[2 * i], -1e-10);
        EXPECT_LE(std::fabs(r[2 * i] * w[2 * i]), 1e-10);
        EXPECT_LE(std::fabs(r[2 * i + 1]), g[i] * (1 + 1e-12));
        if (std::fabs(r[2 * i + 1]) < g[i] * (1 - 1e-9)) {
          EXPECT_NEAR(w[2 * i + 1], 0.0, 1e-9);  // stick
        }
      }
    }
  }
}

TEST(PsorCondensed, WarmStartFromTheSolutionTakesOneSweep) {
  std::mt19937 rng(3);
  const Eigen::MatrixXd W = random_spd(6, rng);
  Eigen::VectorXd q(6);
  q << 1, 0.2, -0.5, 0.1, 0.7, -0.3;
  Eigen::VectorXd g = Eigen::VectorXd::Constant(3, 0.2), r = Eigen::VectorXd::Zero(6);
  sma::psor_condensed(W, q, g, 1.88, 1e-15, 100000, r);
  const sma::PsorResult again = sma::psor_condensed(W, q, g, 1.88, 1e-12, 100, r);
  EXPECT_EQ(again.iterations, 1);
}

TEST(PsorCondensed, RejectsBadInput) {
  Eigen::MatrixXd W = Eigen::MatrixXd::Identity(2, 2);
  Eigen::VectorXd q = Eigen::VectorXd::Ones(2), g = Eigen::VectorXd::Zero(1), r = Eigen::VectorXd::Zero(2);
  EXPECT_THROW(sma::psor_condensed(W, q, g, 2.0, 1e-10, 10, r), std::invalid_argument);
  EXPECT_THROW(sma::psor_condensed(W, q, g, 0.0, 1e-10, 10, r), std::invalid_argument);
  Eigen::VectorXd negative = Eigen::VectorXd::Constant(1, -1.0);
  EXPECT_THROW(sma::psor_condensed(W, q, negative, 1.5, 1e-10, 10, r), std::invalid_argument);
  Eigen::VectorXd wrong = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(sma::psor_condensed(W, q, g, 1.5, 1e-10, 10, wrong), std::invalid_argument);
  // A blocked tangential motion (W_tt = 0) is accepted only with g = 0.
  Eigen::MatrixXd blocked(2, 2);
  blocked << 1, 0, 0, 0;
  Eigen::VectorXd gz = Eigen::VectorXd::Zero(1), rz = Eigen::VectorXd::Zero(2);
  EXPECT_TRUE(sma::psor_condensed(blocked, q, gz, 1.0, 1e-12, 10, rz).converged);
  EXPECT_DOUBLE_EQ(rz[0], 1.0);
  EXPECT_DOUBLE_EQ(rz[1], 0.0);
  Eigen::VectorXd gpos = Eigen::VectorXd::Constant(1, 0.5);
  EXPECT_THROW(sma::psor_condensed(blocked, q, gpos, 1.5, 1e-12, 10, rz), std::invalid_argument);
  // Not converging in the allowed sweeps is reported, not hidden.
  Eigen::MatrixXd hard(2, 2);
  hard << 1, 0.999, 0.999, 1;
  Eigen::VectorXd qh(2);
  qh << 1, -1;
  Eigen::VectorXd gh = Eigen::VectorXd::Constant(1, 10.0), rh = Eigen::VectorXd::Zero(2);
  const sma::PsorResult res = sma::psor_condensed(hard, qh, gh, 1.0, 1e-15, 3, rh);
  EXPECT_FALSE(res.converged);
  EXPECT_EQ(res.iterations, 3);
  EXPECT_GT(res.residual, 1e-15);
}

// The active-set polish: on ill-conditioned Delassus operators (a 1D chain's compliance, the
// shape of a ring's: cond ~ m^2) plain PSOR needs thousands of sweeps; with the polish every 10
// sweeps it ends within a few tens with the same answer as plain PSOR run to 1e-14.
TEST(PsorCondensed, ActiveSetPolishGivesThePlainAnswerInFewSweeps) {
  std::mt19937 rng(77);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double worst = 0;
  int maxPolished = 0, minPlain = 1 << 30;
  for (int trial = 0; trial < 20; ++trial) {
    const int m = 20 + trial;
    Eigen::MatrixXd L = Eigen::MatrixXd::Zero(2 * m, 2 * m);  // stiffness of a chain, both components
    for (int i = 0; i < 2 * m; ++i) {
      L(i, i) = 2.0 + 1e-3;
      if (i + 2 < 2 * m) L(i, i + 2) = L(i + 2, i) = -1.0;
    }
    const Eigen::MatrixXd W = L.inverse();  // compliance: smooth, ill-conditioned
    Eigen::VectorXd q(2 * m), g(m);
    for (int k = 0; k < 2 * m; ++k) q[k] = 10 * normal(rng) + (k % 2 == 0 ? 30.0 : 0.0);
    for (int i = 0; i < m; ++i) g[i] = 5 * uniform(rng);
    Eigen::VectorXd plain = Eigen::VectorXd::Zero(2 * m), polished = plain;
    const sma::PsorResult a = sma::psor_condensed(W, q, g, 1.88, 1e-14, 2000000, plain);
    const sma::PsorResult b = sma::psor_condensed(W, q, g, 1.88, 1e-10, 2000000, polished, 10);
    ASSERT_TRUE(a.converged && b.converged);
    worst = std::max(worst, (plain - polished).lpNorm<Eigen::Infinity>() / plain.lpNorm<Eigen::Infinity>());
    maxPolished = std::max(maxPolished, b.iterations);
    minPlain = std::min(minPlain, a.iterations);
    EXPECT_LE(sma::contact_law_residual(W, q, g, polished), 1e-8);
  }
  std::printf("polish: max rel. diff %.2e; sweeps with polish <= %d, plain >= %d\n", worst,
              maxPolished, minPlain);
  EXPECT_LE(worst, 1e-8);
  EXPECT_LE(maxPolished, 100);
  EXPECT_GE(minPlain, 10 * maxPolished) << "the problems are too easy to show anything";
}
