// Unit tests of the 3D contact sweeps (plugin/core/psor_cone.hpp): the Tresca disk's local problem
// against its optimality conditions and a brute-force minimum; the sweeps' answer against the laws
// (Signorini complementarity, the disk, stick and slip directions) on random problems; the 2D
// problem embedded in 3D against psor_condensed; invariance under a rotation of each node's
// tangent frame (which no pair of scalar clamps has); the Coulomb fixed point's cone.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "core/psor.hpp"
#include "core/psor_cone.hpp"
#include "random_problems.hpp"

namespace {

using sma_test::random_spd;

struct ConeProblem {
  Eigen::MatrixXd W;
  Eigen::VectorXd q, g;
};

// W = random_spd(3m) / 3m (diagonal about 2), q ~ N(0, 1), g ~ U(0, g_max), in that order.
ConeProblem random_cone(int m, double g_max, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, g_max);
  ConeProblem p;
  p.W = random_spd(3 * m, rng) / (3.0 * m);
  p.q.resize(3 * m);
  p.g.resize(m);
  for (int k = 0; k < 3 * m; ++k) p.q[k] = normal(rng);
  for (int i = 0; i < m; ++i) p.g[i] = uniform(rng);
  return p;
}

// Every law at every node, to `tol` (scaled by the largest reaction): r_n >= 0, w_n >= 0,
// r_n w_n = 0; |r_t| <= g; inside the disk w_t = 0; on its circle w_t = -k r_t with k >= 0.
// Counts the nodes separated, sticking and sliding.
struct Statuses {
  int separated = 0, sticking = 0, sliding = 0;
};
void expect_laws(const ConeProblem& p, const Eigen::VectorXd& r, double tol, Statuses& count, double disk_tol = 1e-12) {
  const Eigen::VectorXd w = p.W * r - p.q;
  const double scale = std::max(r.lpNorm<Eigen::Infinity>(), 1.0);
  for (int i = 0; i < p.g.size(); ++i) {
    const double rn = r[3 * i], wn = w[3 * i];
    const Eigen::Vector2d rt(r[3 * i + 1], r[3 * i + 2]), wt(w[3 * i + 1], w[3 * i + 2]);
    EXPECT_GE(rn, 0.0);
    EXPECT_GE(wn, -tol * scale) << "node " << i;
    EXPECT_LE(std::fabs(rn * wn), tol * scale * scale) << "node " << i;
    EXPECT_LE(rt.norm(), p.g[i] * (1 + disk_tol) + 1e-300) << "node " << i;
    if (rn <= tol * scale) count.separated++;
    // (the slip's laws at a pressing node: a separated one, r_n 0 to round-off, may move as it
    // will, its r_t within round-off's disk, already checked)
    if (rn <= tol * scale) continue;
    if (rt.norm() < p.g[i] * (1 - std::max(1e-9, disk_tol))) {
      EXPECT_LE(wt.norm(), tol * scale) << "node " << i << " sticks but slips";
      count.sticking++;
    } else if (p.g[i] > 0) {
      // sliding: w_t antiparallel to r_t (its component along r_t <= 0, across it 0)
      const Eigen::Vector2d dir = rt / rt.norm();
      EXPECT_LE(wt.dot(dir), tol * scale) << "node " << i;
      EXPECT_LE(std::fabs(wt[0] * dir[1] - wt[1] * dir[0]), tol * scale) << "node " << i;
      count.sliding++;
    }
  }
}


// The local problem: inside the disk A x = b; on the circle the KKT conditions A x - b = -lambda x
// with lambda >= 0 and |x| = g; and no point of a fine polar grid of the disk does better.
TEST(PsorCone, DiskLocalProblemIsOptimal) {
  std::mt19937 rng(49);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.01, 2.0);
  int inside = 0, on_circle = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Eigen::Matrix2d A = random_spd(2, rng) / 2;
    if (trial % 4 == 0) A(1, 1) *= 1e4;  // badly conditioned blocks too
    A(1, 0) = A(0, 1);
    const Eigen::Vector2d b(normal(rng), normal(rng));
    const double g = uniform(rng);
    const Eigen::Vector2d x = sma::tresca_disk_local(A, b, g);
    const auto energy = [&](const Eigen::Vector2d& y) { return 0.5 * y.dot(A * y) - b.dot(y); };
    ASSERT_LE(x.norm(), g * (1 + 1e-14));
    const Eigen::Vector2d residual = A * x - b;
    if (x.norm() < g * (1 - 1e-12)) {
      ++inside;
      EXPECT_LE(residual.norm(), 1e-10 * (b.norm() + A.norm() * x.norm()));
    } else {
      ++on_circle;
      const double lambda = -residual.dot(x) / x.squaredNorm();
      EXPECT_GE(lambda, -1e-12 * A.norm());
      EXPECT_LE((residual + lambda * x).norm(), 1e-9 * (b.norm() + A.norm() * x.norm())) << "trial " << trial;
    }
    double best = 0.0;  // the grid's best, x = 0 included
    for (int a = 0; a < 720; ++a)
      for (int k = 1; k <= 40; ++k) {
        const double rho = g * k / 40.0, angle = 2 * M_PI * a / 720.0;
        best = std::min(best, energy(Eigen::Vector2d(rho * std::cos(angle), rho * std::sin(angle))));
      }
    EXPECT_LE(energy(x), best + 1e-12 * (1 + std::fabs(best))) << "trial " << trial;
  }
  EXPECT_GT(inside, 50);
  EXPECT_GT(on_circle, 50);
}

// The sweeps solve random problems: the natural-map residual ~ 0 and every law at every node, with
// nodes separated, sticking and sliding among them.
TEST(PsorCone, RandomProblemsSatisfyTheLaws) {
  std::mt19937 rng(1998);
  Statuses count;
  for (int trial = 0; trial < 80; ++trial) {
    const int m = 1 + trial % 6;
    const ConeProblem p = random_cone(m, 0.6, rng);
    Eigen::VectorXd r = Eigen::VectorXd::Zero(3 * m);
    const sma::PsorResult res = sma::psor_cone(p.W, p.q, p.g, 1.3, 1e-14, 200000, r);
    ASSERT_TRUE(res.converged) << "trial " << trial << ": " << res.iterations << " sweeps, " << res.residual;
    EXPECT_LE(sma::cone_law_residual(p.W, p.q, p.g, r), 1e-11) << "trial " << trial;
    expect_laws(p, r, 1e-9, count);
  }
  EXPECT_GT(count.separated, 10);
  EXPECT_GT(count.sticking, 10);
  EXPECT_GT(count.sliding, 10);
}

// A 2D problem (n, t) embedded in 3D with a decoupled, unloaded second tangent (W_t2t2 = 1, no
// coupling, q_t2 = 0): r_t2 = 0 and the rest is psor_condensed's answer.
// The same with the second tangent blocked (its row and column 0, as a support makes them): the
// disk is then the segment [-g, g] of the first.
TEST(PsorCone, TwoDimensionalProblemEmbedded) {
  std::mt19937 rng(2026);
  for (int trial = 0; trial < 80; ++trial) {
    const bool blocked = trial >= 40;
    const int m = 1 + trial % 5;
    const sma_test::TrescaProblem p2 = sma_test::random_tresca(m, 0.5, true, rng);
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(3 * m, 3 * m);
    Eigen::VectorXd q = Eigen::VectorXd::Zero(3 * m);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j)
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) W(3 * i + a, 3 * j + b) = p2.W(2 * i + a, 2 * j + b);
      W(3 * i + 2, 3 * i + 2) = blocked ? 0.0 : 1.0;
      q[3 * i] = p2.q[2 * i];
      q[3 * i + 1] = p2.q[2 * i + 1];
    }
    Eigen::VectorXd r3 = Eigen::VectorXd::Zero(3 * m), r2 = Eigen::VectorXd::Zero(2 * m);
    ASSERT_TRUE(sma::psor_cone(W, q, p2.g, 1.0, 1e-15, 200000, r3).converged);
    ASSERT_TRUE(sma::psor_condensed(p2.W, p2.q, p2.g, 1.0, 1e-15, 200000, r2).converged);
    const double scale = std::max(r2.lpNorm<Eigen::Infinity>(), 1e-12);
    for (int i = 0; i < m; ++i) {
      EXPECT_EQ(r3[3 * i + 2], 0.0);
      EXPECT_LE(std::fabs(r3[3 * i] - r2[2 * i]), 1e-10 * scale) << "trial " << trial;
      EXPECT_LE(std::fabs(r3[3 * i + 1] - r2[2 * i + 1]), 1e-10 * scale) << "trial " << trial;
    }
  }
}

// Rotating each node's tangent frame by its own angle (W -> R W R', q -> R q) rotates the answer:
// the disk is round. Clamping the two components in turn (a square instead of a disk) fails this.
TEST(PsorCone, TangentFrameRotationInvariance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 2 * M_PI);
  double worst = 0.0;
  int sliding = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const int m = 1 + trial % 5;
    const ConeProblem p = random_cone(m, 0.4, rng);
    Eigen::MatrixXd R = Eigen::MatrixXd::Identity(3 * m, 3 * m);
    for (int i = 0; i < m; ++i) {
      const double a = angle(rng);
      R(3 * i + 1, 3 * i + 1) = std::cos(a), R(3 * i + 1, 3 * i + 2) = -std::sin(a);
      R(3 * i + 2, 3 * i + 1) = std::sin(a), R(3 * i + 2, 3 * i + 2) = std::cos(a);
    }
    const Eigen::MatrixXd Wr = R * p.W * R.transpose();
    const Eigen::VectorXd qr = R * p.q;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(3 * m), rr = Eigen::VectorXd::Zero(3 * m);
    ASSERT_TRUE(sma::psor_cone(p.W, p.q, p.g, 1.2, 1e-15, 200000, r).converged);
    ASSERT_TRUE(sma::psor_cone(Wr, qr, p.g, 1.2, 1e-15, 200000, rr).converged);
    worst = std::max(worst, (R * r - rr).lpNorm<Eigen::Infinity>() / std::max(r.lpNorm<Eigen::Infinity>(), 1e-12));
    for (int i = 0; i < m; ++i)
      sliding += r[3 * i] > 1e-9 && std::hypot(r[3 * i + 1], r[3 * i + 2]) >= p.g[i] * (1 - 1e-9) && p.g[i] > 0;
  }
  EXPECT_LE(worst, 1e-10);
  EXPECT_GT(sliding, 10);  // the disk's circle is where a square would differ
}

// Coulomb by the slip-threshold fixed point: the cone |r_t| <= mu r_n at every node, equality
// where the node slides, and the laws with g = mu r_n.
TEST(PsorCone, CoulombFixedPointReachesTheCone) {
  std::mt19937 rng(1);
  Statuses count;
  for (int trial = 0; trial < 60; ++trial) {
    const int m = 1 + trial % 5;
    ConeProblem p = random_cone(m, 1.0, rng);  // g: the mu
    for (int i = 0; i < m; ++i) p.q[3 * i] = std::fabs(p.q[3 * i]) + 0.2;  // mostly in contact
    const Eigen::VectorXd mu = p.g;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(3 * m);
    const sma::ConeFixedPointResult res = sma::coulomb_cone_fixed_point(p.W, p.q, mu, 1.3, 1e-15, 200000, 1e-13, 500, r);
    ASSERT_TRUE(res.converged) << "trial " << trial << ": change " << res.change;
    for (int i = 0; i < m; ++i) {
      p.g[i] = mu[i] * r[3 * i];
      EXPECT_LE(std::hypot(r[3 * i + 1], r[3 * i + 2]), mu[i] * r[3 * i] * (1 + 1e-9) + 1e-14) << "trial " << trial;
    }
    EXPECT_LE(sma::cone_law_residual(p.W, p.q, p.g, r), 1e-10) << "trial " << trial;
    // (the thresholds of the last iterate differ from mu r_n by at most slip_tol of the largest)
    expect_laws(p, r, 1e-9, count, 1e-9);
  }
  EXPECT_GT(count.sticking, 5);
  EXPECT_GT(count.sliding, 5);
}

// Coulomb at once (psor_cone's coulomb_mu: the radius mu r_n inside the sweeps and the polish,
// Alart and Curnier's) gives the fixed point's answer: on the random problems above (sticking and
// sliding nodes) and on badly conditioned ones (W's eigenvalues from 1e-6 to 1), where it needs
// the polish, with its derivative of the radius; one call, a law residual of 1e-10 with
// g = mu r_n.
TEST(PsorCone, CoulombAtOnceIsTheFixedPoint) {
  std::mt19937 rng(1);
  std::normal_distribution<double> normal;
  Statuses count;
  for (int trial = 0; trial < 64; ++trial) {
    const int m = trial < 60 ? 1 + trial % 5 : 12;
    ConeProblem p;
    if (trial < 60) {
      p = random_cone(m, 1.0, rng);
      for (int i = 0; i < m; ++i) p.q[3 * i] = std::fabs(p.q[3 * i]) + 0.2;
    } else {
      Eigen::VectorXd eigen(3 * m);
      for (int k = 0; k < 3 * m; ++k) eigen[k] = std::pow(10.0, -6.0 * k / (3 * m - 1));
      p.W = sma_test::random_symmetric(eigen, rng, normal);
      p.q.resize(3 * m);
      p.g = Eigen::VectorXd::Constant(m, 0.3);
      for (int k = 0; k < 3 * m; ++k) p.q[k] = 0.01 * normal(rng);
      for (int i = 0; i < m; ++i) p.q[3 * i] = std::fabs(p.q[3 * i]) + 0.01;
    }
    const Eigen::VectorXd mu = p.g;
    Eigen::VectorXd fixed = Eigen::VectorXd::Zero(3 * m), once = fixed;
    const sma::ConeFixedPointResult fp = sma::coulomb_cone_fixed_point(p.W, p.q, mu, 1.3, 1e-15, 200000, 1e-13, 500, fixed);
    ASSERT_TRUE(fp.converged) << "trial " << trial;
    const Eigen::VectorXd start = Eigen::VectorXd::Zero(m);
    const sma::PsorResult res = sma::psor_cone(p.W, p.q, start, 1.3, 1e-12, 200000, once, 10, &mu);
    ASSERT_TRUE(res.converged) << "trial " << trial;
    for (int i = 0; i < m; ++i) p.g[i] = mu[i] * once[3 * i];
    EXPECT_LE(sma::cone_law_residual(p.W, p.q, p.g, once), 1e-10) << "trial " << trial;
    EXPECT_LE((once - fixed).lpNorm<Eigen::Infinity>(), 1e-8 * fixed.lpNorm<Eigen::Infinity>()) << "trial " << trial;
    if (trial >= 60) { EXPECT_GE(res.polishes, 1) << "trial " << trial; }
    expect_laws(p, once, 1e-8, count, 1e-9);
  }
  EXPECT_GT(count.sticking, 5);
  EXPECT_GT(count.sliding, 5);
}

// Inconsistent input is refused with the culprit named.
TEST(PsorCone, RefusesInconsistentInput) {
  std::mt19937 rng(3);
  ConeProblem p = random_cone(2, 0.5, rng);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(6);
  EXPECT_THROW(sma::psor_cone(p.W, p.q, p.g, 2.0, 1e-10, 10, r), std::invalid_argument);
  Eigen::VectorXd short_r = Eigen::VectorXd::Zero(4);
  EXPECT_THROW(sma::psor_cone(p.W, p.q, p.g, 1.0, 1e-10, 10, short_r), std::invalid_argument);
  p.g[1] = -1;
  EXPECT_THROW(sma::psor_cone(p.W, p.q, p.g, 1.0, 1e-10, 10, r), std::invalid_argument);
  p.g[1] = 0.3;
  // both tangential motions blocked (rows and columns 0) with a positive threshold
  for (int k : {4, 5}) {
    p.W.row(k).setZero();
    p.W.col(k).setZero();
  }
  try {
    sma::psor_cone(p.W, p.q, p.g, 1.0, 1e-10, 10, r);
    ADD_FAILURE() << "two blocked tangents with g > 0 were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("contact node 1"), std::string::npos) << e.what();
  }
  p.g[1] = 0.0;  // allowed with threshold 0: the pair stays 0
  EXPECT_TRUE(sma::psor_cone(p.W, p.q, p.g, 1.0, 1e-13, 100000, r).converged);
  EXPECT_EQ(r[4], 0.0);
  EXPECT_EQ(r[5], 0.0);
}

// A tangential motion held but for round-off (a row of H 6e-17 on a free dof beside its held one:
// sleeve-3d's nodes 6e-17 off the plane x = 0, whose compliance 4e-33 the sweeps took for a free
// motion and whose reaction was then anything in the disk) is refused, naming the node and tangent;
// at 1e-6 of the normal's compliance (a stiff but real motion) it is solved.
TEST(PsorCone, RefusesARoundOffCompliance) {
  std::mt19937 rng(5);
  ConeProblem p = random_cone(3, 0.5, rng);
  for (double tiny : {4e-33, 1e-13}) {
    ConeProblem q = p;
    const double scale = std::sqrt(tiny / q.W(7, 7));  // node 2's first tangent, its row scaled down
    q.W.row(7) *= scale;
    q.W.col(7) *= scale;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(9);
    try {
      sma::psor_cone(q.W, q.q, q.g, 1.0, 1e-10, 10, r);
      ADD_FAILURE() << "a tangential compliance of " << q.W(7, 7) / q.W(6, 6) << " of the normal's was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("contact node 2 (tangent 1)"), std::string::npos) << e.what();
    }
  }
  ConeProblem stiff = p;
  const double scale = std::sqrt(1e-6 * stiff.W(6, 6) / stiff.W(7, 7));
  stiff.W.row(7) *= scale;
  stiff.W.col(7) *= scale;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(9);
  EXPECT_TRUE(sma::psor_cone(stiff.W, stiff.q, stiff.g, 1.0, 1e-10, 200000, r, 10).converged);
  EXPECT_LE(sma::cone_law_residual(stiff.W, stiff.q, stiff.g, r), 1e-8);
}

// The polish (a semismooth Newton method on the natural map) finishes what the sweeps alone take
// long to: on badly conditioned problems (W's eigenvalues from 1e-6 to 1) the sweeps with the
// polish every 10 reach a law residual of 1e-10 in at most 500 sweeps, satisfying every law, where
// as many sweeps alone leave a residual above 1e-7.
TEST(PsorCone, PolishFinishesBadlyConditionedProblems) {
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  int plain_short = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const int m = 12, n = 3 * m;
    Eigen::VectorXd eigen(n);
    for (int k = 0; k < n; ++k) eigen[k] = std::pow(10.0, -6.0 * k / (n - 1));
    ConeProblem p;
    p.W = sma_test::random_symmetric(eigen, rng, normal);
    p.q.resize(n);
    p.g.resize(m);
    for (int k = 0; k < n; ++k) p.q[k] = 0.01 * normal(rng);
    for (int i = 0; i < m; ++i) p.q[3 * i] = std::fabs(p.q[3 * i]) + 0.01, p.g[i] = 0.02;
    Eigen::VectorXd plain = Eigen::VectorXd::Zero(n), polished = Eigen::VectorXd::Zero(n);
    const sma::PsorResult res = sma::psor_cone(p.W, p.q, p.g, 1.5, 1e-10, 20000, polished, 10);
    // the sweeps alone, as many as the polished run took: their answer is still far off
    sma::psor_cone(p.W, p.q, p.g, 1.5, 0.0, res.iterations, plain);
    plain_short += sma::cone_law_residual(p.W, p.q, p.g, plain) > 1e3 * 1e-10;
    ASSERT_TRUE(res.converged) << "trial " << trial;
    EXPECT_LE(res.iterations, 500) << "trial " << trial;
    // the polishes: after 10 sweeps, then waits doubling after each failure (10, 30, 70, ...)
    EXPECT_LE(res.polishes, 1 + std::log2(res.iterations / 10.0 + 1)) << "trial " << trial;
    EXPECT_GE(res.polishes, 1) << "trial " << trial;
    EXPECT_LE(sma::cone_law_residual(p.W, p.q, p.g, polished), 1e-10) << "trial " << trial;
    Statuses count;
    expect_laws(p, polished, 1e-8, count);
  }
  EXPECT_GE(plain_short, 5);  // the problems are hard for the sweeps alone
}

// The polish's Newton step on the rows that are not the identity's (cone_detail::reduced_newton_step)
// is the whole system's solution: a random J whose open nodes' rows (D = 0) are those of the
// identity, one tangential row with Coulomb's slope kept, against a dense LU of the whole J.
TEST(PsorCone, ReducedNewtonStepIsTheWholeSystemsStep) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::Index m = 12, n = 3 * m;
  Eigen::MatrixXd J = Eigen::MatrixXd::Identity(n, n), D = Eigen::MatrixXd::Zero(n, 3);
  Eigen::VectorXd F(n), slope = Eigen::VectorXd::Zero(n);
  int reduced = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    F[k] = u(rng);
    const Eigen::Index node = k / 3;
    const bool open = node % 3 == 0;  // a third of the nodes open: identity rows
    const bool slope_only = k == 3 * 3 + 1;  // node 3 (open) but its row 1 with a slope: kept
    if (open && !slope_only) continue;
    ++reduced;
    if (slope_only) {
      slope[k] = 0.2;
      J(k, k - 1) -= slope[k];
      continue;
    }
    D(k, k % 3) = 1.0;
    for (Eigen::Index j = 0; j < n; ++j) J(k, j) = (j == k ? 2.0 + n : 0.0) + u(rng);
  }
  ASSERT_GT(reduced, 0);
  ASSERT_LT(reduced, n);
  const Eigen::VectorXd whole = J.partialPivLu().solve(-F);
  const Eigen::VectorXd step = sma::cone_detail::reduced_newton_step(J, D, F, &slope);
  EXPECT_LE((step - whole).lpNorm<Eigen::Infinity>(), 1e-12 * whole.lpNorm<Eigen::Infinity>());
  // without the slope the row with it would be taken as the identity's: then not the whole step
  const Eigen::VectorXd wrong = sma::cone_detail::reduced_newton_step(J, D, F, nullptr);
  EXPECT_GT((wrong - whole).lpNorm<Eigen::Infinity>(), 1e-6);

  // With a memory: the first step factorises; a later one on a nearby matrix with the same kept
  // rows (a sliding direction turned) is solved by GMRES on the kept factor, the whole LU's step to
  // 1e-10; other kept rows factorise again.
  sma::ConePolishMemory memory;
  const Eigen::VectorXd first = sma::cone_detail::reduced_newton_step(J, D, F, &slope, &memory);
  EXPECT_LE((first - whole).lpNorm<Eigen::Infinity>(), 1e-12 * whole.lpNorm<Eigen::Infinity>());
  EXPECT_EQ(memory.factorisations, 1);
  EXPECT_EQ(memory.reuses, 0);
  Eigen::MatrixXd nearby = J;
  for (Eigen::Index k = 0; k < n; ++k)
    if (!D.row(k).isZero(0.0))
      for (Eigen::Index j = 0; j < n; ++j) nearby(k, j) += 0.05 * u(rng);
  const Eigen::VectorXd reused = sma::cone_detail::reduced_newton_step(nearby, D, F, &slope, &memory);
  const Eigen::VectorXd nearby_whole = nearby.partialPivLu().solve(-F);
  EXPECT_EQ(memory.factorisations, 1);
  EXPECT_EQ(memory.reuses, 1);
  EXPECT_LE((reused - nearby_whole).lpNorm<Eigen::Infinity>(), 1e-10 * nearby_whole.lpNorm<Eigen::Infinity>());
  Eigen::MatrixXd fewer = D;
  fewer.row(3).setZero();  // node 1's normal row opens: the identity's too
  Eigen::MatrixXd J_fewer = nearby;
  J_fewer.row(3) = Eigen::RowVectorXd::Unit(n, 3);
  const Eigen::VectorXd refactored = sma::cone_detail::reduced_newton_step(J_fewer, fewer, F, &slope, &memory);
  EXPECT_EQ(memory.factorisations, 2);
  EXPECT_LE((refactored - J_fewer.partialPivLu().solve(-F)).lpNorm<Eigen::Infinity>(), 1e-10 * refactored.lpNorm<Eigen::Infinity>());
}

}  // namespace
