// Independent oracle for the friction solvers: Siconos numerics (Debian libsiconos-numerics-dev).
// On the same random Delassus problems (W SPD, free motion q):
//   Tresca (fixed thresholds g): our psor_condensed against Siconos' Relay solver (box-constrained
//     complementarity: r_n in [0, huge], r_t in [-g, g]) by Lemke pivoting;
//   Coulomb (mu): our fixed point on the slip threshold (coulomb_condensed) against Siconos' 2D
//     frictional-contact nonsmooth Gauss-Seidel (fc2d_nsgs_dense), which solves the Coulomb law
//     directly, contact by contact, with no threshold fixed point. (Debian's Siconos 4.4
//     fc2d_lexicolemke and fc2d_enum, which go through fc2d_tolcp, return answers that violate the
//     Coulomb law by 1e-2 relative as soon as there are two contacts: not usable as an oracle.)
// Siconos' convention is velocity = M r + q_s; ours is w = W r - q, so q_s = -q.
// Figures go to results/checks/siconos_oracle.json (written by the test itself).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include "core/psor.hpp"
#include "random_problems.hpp"

extern "C" {
#include <FrictionContactProblem.h>
#include <Friction_cst.h>
#include <NumericsMatrix.h>
#include <RelayProblem.h>
#include <Relay_Solvers.h>
#include <SolverOptions.h>
#include <fc2d_Solvers.h>
#include <relay_cst.h>
}

namespace {

NumericsMatrix* dense(const Eigen::MatrixXd& W) {
  const int n = (int)W.rows();
  NumericsMatrix* M = NM_create(NM_DENSE, n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) M->matrix0[i + j * n] = W(i, j);  // column-major
  return M;
}

Eigen::VectorXd siconos_tresca(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                               const Eigen::VectorXd& g) {
  const int n = (int)q.size();
  Eigen::VectorXd qs = -q, lb(n), ub(n), z = Eigen::VectorXd::Zero(n), w(n);
  for (int i = 0; i < n / 2; ++i) {
    lb[2 * i] = 0.0, ub[2 * i] = 1e6;  // never reached: |r| = O(1) here (checked below)
    lb[2 * i + 1] = -g[i], ub[2 * i + 1] = g[i];
  }
  RelayProblem problem;
  problem.size = n;
  problem.M = dense(W);
  problem.q = qs.data();
  problem.lb = lb.data();
  problem.ub = ub.data();
  SolverOptions* options = solver_options_create(SICONOS_RELAY_LEMKE);
  int info = -1;
  relay_lexicolemke(&problem, z.data(), w.data(), &info, options);
  solver_options_delete(options);
  NM_free(problem.M);
  EXPECT_EQ(info, 0) << "Siconos relay_lexicolemke failed";
  EXPECT_LT(z.lpNorm<Eigen::Infinity>(), 1e5);
  return z;
}

Eigen::VectorXd siconos_coulomb(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& mu) {
  const int n = (int)q.size();
  Eigen::VectorXd qs = -q, muv = mu, r = Eigen::VectorXd::Zero(n), v(n);
  FrictionContactProblem problem;
  problem.dimension = 2;
  problem.numberOfContacts = n / 2;
  problem.M = dense(W);
  problem.q = qs.data();
  problem.mu = muv.data();
  SolverOptions* options = solver_options_create(SICONOS_FRICTION_2D_NSGS);
  options->dparam[SICONOS_DPARAM_TOL] = 1e-15;
  options->iparam[SICONOS_IPARAM_MAX_ITER] = 1000000;
  int info = -1;
  fc2d_nsgs_dense(&problem, r.data(), v.data(), &info, options);
  solver_options_delete(options);
  NM_free(problem.M);
  EXPECT_EQ(info, 0) << "Siconos fc2d_nsgs_dense failed";
  return r;
}

struct Figures {
  double worst = 0;
  int cases = 0, sliding = 0, sticking = 0, separated = 0, fixed_point_iterations_max = 0;
};

// One file per test: ctest runs each test in its own process.
void write_figures(const char* name, const char* what, const Figures& f) {
  std::ofstream out(std::string(CHECKS_DIR "/") + name + ".json");
  out.precision(6);
  out << "{\n  \"name\": \"" << name << "\",\n  \"what\": \"" << what << "\",\n  \"cases\": "
      << f.cases << ", \"max_rel_diff\": " << f.worst << ", \"tolerance\": 1e-8,\n"
      << "  \"fixed_point_iterations_max\": " << f.fixed_point_iterations_max
      << ",\n  \"nodes_sliding\": " << f.sliding << ", \"nodes_sticking\": " << f.sticking
      << ", \"nodes_separated\": " << f.separated << ",\n  \"passed\": "
      << (f.worst <= 1e-8 ? "true" : "false") << "\n}\n";
}

void classify(const Eigen::VectorXd& r, const Eigen::VectorXd& g, Figures& f) {
  for (int i = 0; i < g.size(); ++i) {
    if (r[2 * i] <= 1e-12) f.separated++;
    else if (std::fabs(r[2 * i + 1]) >= g[i] - 1e-9) f.sliding++;
    else f.sticking++;
  }
}

}  // namespace

TEST(SiconosOracle, TrescaEqualsRelayLemke) {
  Figures figures;
  std::mt19937 rng(1998);
  for (int trial = 0; trial < 60; ++trial) {
    const int m = 1 + trial % 5;
    const sma_test::TrescaProblem p = sma_test::random_tresca(m, 0.5, true, rng);
    const Eigen::MatrixXd& W = p.W;
    const Eigen::VectorXd &q = p.q, &g = p.g;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * m);
    const sma::PsorResult res = sma::psor_condensed(W, q, g, 1.5, 1e-15, 100000, r);
    ASSERT_TRUE(res.converged);
    const Eigen::VectorXd ref = siconos_tresca(W, q, g);
    const double scale = std::max(ref.lpNorm<Eigen::Infinity>(), 1e-12);
    figures.worst = std::max(figures.worst, (r - ref).lpNorm<Eigen::Infinity>() / scale);
    figures.cases++;
    classify(r, g, figures);
  }
  EXPECT_LE(figures.worst, 1e-8);
  EXPECT_GT(figures.sliding, 10);
  EXPECT_GT(figures.sticking, 10);
  write_figures("siconos_tresca", "condensed PSOR (Tresca) against Siconos relay_lexicolemke", figures);
}

TEST(SiconosOracle, CoulombFixedPointEqualsFc2dLemke) {
  Figures figures;
  std::mt19937 rng(2026);
  for (int trial = 0; trial < 60; ++trial) {
    const int m = 1 + trial % 5;
    sma_test::TrescaProblem p = sma_test::random_tresca(m, 0.5, true, rng);  // g: the mu
    const Eigen::MatrixXd& W = p.W;
    Eigen::VectorXd& q = p.q;
    const Eigen::VectorXd& mu = p.g;
    for (int i = 0; i < m; ++i) q[2 * i] = std::fabs(q[2 * i]) + 0.2;  // mostly in contact
    Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * m);
    const sma::CoulombResult res = sma::coulomb_condensed(W, q, mu, 1.5, 1e-15, 100000, 1e-13, 500, r);
    ASSERT_TRUE(res.converged) << "trial " << trial << ": fixed point residual " << res.residual;
    figures.fixed_point_iterations_max = std::max(figures.fixed_point_iterations_max, res.iterations);
    const Eigen::VectorXd ref = siconos_coulomb(W, q, mu);
    {  // both answers must satisfy the laws themselves, so that agreement means correctness
      Eigen::VectorXd gref(m), gour(m);
      for (int i = 0; i < m; ++i) gref[i] = mu[i] * ref[2 * i], gour[i] = mu[i] * r[2 * i];
      EXPECT_LE(sma::contact_law_residual(W, q, gour, r), 1e-10);
      EXPECT_LE(sma::contact_law_residual(W, q, gref, ref), 1e-10);
    }
    const double scale = std::max(ref.lpNorm<Eigen::Infinity>(), 1e-12);
    figures.worst = std::max(figures.worst, (r - ref).lpNorm<Eigen::Infinity>() / scale);
    figures.cases++;
    Eigen::VectorXd g(m);
    for (int i = 0; i < m; ++i) g[i] = mu[i] * r[2 * i];
    classify(r, g, figures);
    // Coulomb cone at the converged state.
    for (int i = 0; i < m; ++i) EXPECT_LE(std::fabs(r[2 * i + 1]), mu[i] * r[2 * i] * (1 + 1e-8) + 1e-14);
  }
  EXPECT_LE(figures.worst, 1e-8);
  EXPECT_GT(figures.sliding, 5);
  EXPECT_GT(figures.sticking, 5);
  write_figures("siconos_coulomb", "slip-threshold fixed point (Coulomb) against Siconos fc2d_nsgs_dense (tol 1e-15)",
                figures);
}
