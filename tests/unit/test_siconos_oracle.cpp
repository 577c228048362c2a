// Independent oracle for the friction solvers: Siconos numerics (Debian libsiconos-numerics-dev).
// On the same random Delassus problems (W SPD, free motion q):
//   Tresca (fixed thresholds g): our psor_condensed against Siconos' Relay solver (box-constrained
//     complementarity: r_n in [0, huge], r_t in [-g, g]) by Lemke pivoting;
//   Coulomb (mu): the scenes' fixed point on the slip threshold (edp/lib/contact.idp
//     ElasticContactSolve, edp/lib/dc.idp SlipThresholdSolve: g = mu r_n of the previous iterate,
//     a warm-started psor_condensed with the scenes' default settings, as the plugin's
//     PsorCondensed calls it, until max |g_new - g| <= tol max |g_new|), written out here as a
//     test-local loop, against Siconos' 2D frictional-contact nonsmooth Gauss-Seidel
//     (fc2d_nsgs_dense), which solves the Coulomb law directly, contact by contact, with no
//     threshold fixed point;
//   the 3D cone (mu, two tangential components per contact: plugin/core/psor_cone.hpp): the same
//     fixed point around psor_cone against Siconos' 3D nonsmooth Gauss-Seidel (fc3d_nsgs), whose
//     local solver projects on the cone itself. (Debian's Siconos 4.4
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
#include "core/psor_cone.hpp"
#include "random_problems.hpp"

extern "C" {
#include <FrictionContactProblem.h>
#include <Friction_cst.h>
#include <NumericsMatrix.h>
#include <RelayProblem.h>
#include <Relay_Solvers.h>
#include <SolverOptions.h>
#include <fc2d_Solvers.h>
#include <fc3d_Solvers.h>
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

// Siconos' frictional-contact nonsmooth Gauss-Seidel in `dimension` 2 (fc2d_nsgs_dense) or 3
// (fc3d_nsgs), tolerance 1e-15: the reactions, (n, t) or (n, t1, t2) per contact.
Eigen::VectorXd siconos_coulomb(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, const Eigen::VectorXd& mu,
                                int dimension = 2) {
  const int n = (int)q.size();
  Eigen::VectorXd qs = -q, muv = mu, r = Eigen::VectorXd::Zero(n), v(n);
  FrictionContactProblem problem;
  problem.dimension = dimension;
  problem.numberOfContacts = n / dimension;
  problem.M = dense(W);
  problem.q = qs.data();
  problem.mu = muv.data();
  SolverOptions* options = solver_options_create(dimension == 2 ? SICONOS_FRICTION_2D_NSGS : SICONOS_FRICTION_3D_NSGS);
  options->dparam[SICONOS_DPARAM_TOL] = 1e-15;
  options->iparam[SICONOS_IPARAM_MAX_ITER] = 1000000;
  int info = -1;
  if (dimension == 2) fc2d_nsgs_dense(&problem, r.data(), v.data(), &info, options);
  else fc3d_nsgs(&problem, r.data(), v.data(), &info, options);
  solver_options_delete(options);
  NM_free(problem.M);
  EXPECT_EQ(info, 0) << "Siconos " << (dimension == 2 ? "fc2d_nsgs_dense" : "fc3d_nsgs") << " failed";
  return r;
}

// PSOR settings as the plugin's PsorCondensed takes them: [omega, tol, sweep limit, polish].
struct PsorSettings {
  double omega, tol;
  int maxit, polish;
};
// The scenes' defaults (edp/lib/contact.idp contactPsorSettings; -psoromega etc. in sleeve.idp).
constexpr PsorSettings kScenePsor{1.88, 1e-10, 100000, 10};

// The scenes' slip-threshold fixed point (contact.idp ElasticContactSolve with
// ContactUpdateThresholds and ContactGlobalStep's condensed branch; dc.idp SlipThresholdSolve has
// the same loop around a DC solve), on a condensed problem: thresholds g = mu max(0, r_n) from the
// warm start r; then, each iterate, a Tresca solve by psor_condensed (the core function the
// plugin's PsorCondensed calls) warm-started from r with the thresholds of the previous iterate,
// and new thresholds, until the relative change max |g_new - g| / max |g_new| is <= slip_tol.
// Returns the iteration count, or -1 when it does not converge (a PSOR failure is a test failure).
int slip_threshold_fixed_point(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                               const Eigen::VectorXd& mu, const PsorSettings& psor,
                               double slip_tol, int slip_maxit, Eigen::VectorXd& r,
                               double& change) {
  const Eigen::Index m = mu.size();
  Eigen::VectorXd g(m), g_new(m);
  for (Eigen::Index i = 0; i < m; ++i) g[i] = mu[i] * std::max(0.0, r[2 * i]);
  change = 0.0;
  for (int it = 1; it <= slip_maxit; ++it) {
    const sma::PsorResult res =
        sma::psor_condensed(W, q, g, psor.omega, psor.tol, psor.maxit, r, psor.polish);
    EXPECT_TRUE(res.converged) << "PSOR: " << res.iterations << " sweeps, residual " << res.residual;
    if (!res.converged) return -1;
    for (Eigen::Index i = 0; i < m; ++i) g_new[i] = mu[i] * std::max(0.0, r[2 * i]);
    const double size = std::max(0.0, g_new.maxCoeff());
    change = (g_new - g).lpNorm<Eigen::Infinity>();
    if (size > 0) change /= size;
    g = g_new;
    if (change <= slip_tol) return it;
  }
  return -1;
}

struct Figures {
  double worst = 0, law_residual_max = 0;  // the latter: our answer's natural-map residual
  int cases = 0, sliding = 0, sticking = 0, separated = 0, fixed_point_iterations_max = 0;
};

// One file per test: ctest runs each test in its own process.
void write_figures(const char* name, const char* what, const Figures& f) {
  std::ofstream out(std::string(CHECKS_DIR "/") + name + ".json");
  out.precision(6);
  out << "{\n  \"name\": \"" << name << "\",\n  \"what\": \"" << what << "\",\n  \"cases\": "
      << f.cases << ", \"max_rel_diff\": " << f.worst << ", \"tolerance\": 1e-8,\n"
      << "  \"law_residual_max\": " << f.law_residual_max << ",\n"
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
    figures.law_residual_max = std::max(figures.law_residual_max, sma::contact_law_residual(W, q, g, r));
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

// The Coulomb oracle on 60 random problems, mostly in contact. With `exact_laws`, our answer must
// also satisfy the Coulomb law itself (natural-map residual <= 1e-10, cone to 1e-8 relative); the
// scenes' default tolerances stop the fixed point earlier than that (at the stop, |r_t| - mu r_n
// is bounded by slip_tol max_j g_j, not by slip_tol g_i), so there only the distance to Siconos'
// answer is checked.
Figures coulomb_against_siconos(const PsorSettings& psor, double slip_tol, bool exact_laws) {
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
    double change = 0.0;
    const int iterations = slip_threshold_fixed_point(W, q, mu, psor, slip_tol, 500, r, change);
    EXPECT_GT(iterations, 0) << "trial " << trial << ": fixed point residual " << change;
    if (iterations <= 0) return figures;
    figures.fixed_point_iterations_max = std::max(figures.fixed_point_iterations_max, iterations);
    const Eigen::VectorXd ref = siconos_coulomb(W, q, mu);
    Eigen::VectorXd gref(m), gour(m);
    for (int i = 0; i < m; ++i) gref[i] = mu[i] * ref[2 * i], gour[i] = mu[i] * r[2 * i];
    // Siconos' answer must satisfy the laws itself, so that agreement means correctness.
    EXPECT_LE(sma::contact_law_residual(W, q, gref, ref), 1e-10);
    const double law = sma::contact_law_residual(W, q, gour, r);
    figures.law_residual_max = std::max(figures.law_residual_max, law);
    if (exact_laws) {
      EXPECT_LE(law, 1e-10) << "trial " << trial;
      // Coulomb cone at the converged state.
      for (int i = 0; i < m; ++i)
        EXPECT_LE(std::fabs(r[2 * i + 1]), mu[i] * r[2 * i] * (1 + 1e-8) + 1e-14) << "trial " << trial;
    }
    const double scale = std::max(ref.lpNorm<Eigen::Infinity>(), 1e-12);
    figures.worst = std::max(figures.worst, (r - ref).lpNorm<Eigen::Infinity>() / scale);
    figures.cases++;
    classify(r, gour, figures);
  }
  return figures;
}

// What both Coulomb runs assert: all 60 problems solved, every reaction within 1e-8 of Siconos',
// and both regimes exercised (more than 5 sliding and 5 sticking nodes).
void expect_coulomb_agreement(const Figures& figures) {
  EXPECT_EQ(figures.cases, 60);
  EXPECT_LE(figures.worst, 1e-8);
  EXPECT_GT(figures.sliding, 5);
  EXPECT_GT(figures.sticking, 5);
}

// Tight tolerances (PSOR 1e-15, slip 1e-13) on the scenes' omega and polish: the fixed point's
// limit is the Coulomb solution.
TEST(SiconosOracle, CoulombFixedPointEqualsFc2dNsgs) {
  const Figures figures = coulomb_against_siconos({kScenePsor.omega, 1e-15, kScenePsor.maxit,
                                                   kScenePsor.polish}, 1e-13, true);
  expect_coulomb_agreement(figures);
  write_figures("siconos_coulomb",
                "scenes' slip-threshold fixed point around psor_condensed (omega 1.88, polish 10, "
                "PSOR tol 1e-15, slip tol 1e-13) against Siconos fc2d_nsgs_dense (tol 1e-15)",
                figures);
}

// The scenes' own defaults: PSOR [1.88, 1e-10, 100000, 10] and the sleeves' -sliptol 1e-9. (The
// fixed point cannot go much below the PSOR tolerance: with PSOR tol 1e-10 its change stalls near
// 1e-10, so ring-lame's slip tol 1e-10 would be a coin toss here; measured: one trial stops at
// 9.1e-11, and at slip tol 1e-11 that trial does not converge.)
TEST(SiconosOracle, CoulombSceneDefaultsNearFc2dNsgs) {
  const Figures figures = coulomb_against_siconos(kScenePsor, 1e-9, false);
  expect_coulomb_agreement(figures);
  write_figures("siconos_coulomb_scene_defaults",
                "scenes' slip-threshold fixed point around psor_condensed at the scenes' defaults "
                "(PSOR [1.88, 1e-10, 100000, 10], slip tol 1e-9) against Siconos fc2d_nsgs_dense",
                figures);
}

// The 3D cone on 60 random problems, mostly in contact: the slip-threshold fixed point around
// psor_cone (omega 1.3, PSOR tol 1e-15, slip tol 1e-13) against fc3d_nsgs (tol 1e-15); Siconos'
// answer must satisfy the laws itself (natural-map residual with g = mu r_n), and ours too.
TEST(SiconosOracle, ConeFixedPointEqualsFc3dNsgs) {
  Figures figures;
  std::mt19937 rng(49);
  for (int trial = 0; trial < 60; ++trial) {
    const int m = 1 + trial % 5;
    Eigen::MatrixXd W = sma_test::random_spd(3 * m, rng) / (3.0 * m);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    Eigen::VectorXd q(3 * m), mu(m);
    for (int k = 0; k < 3 * m; ++k) q[k] = normal(rng);
    for (int i = 0; i < m; ++i) q[3 * i] = std::fabs(q[3 * i]) + 0.2, mu[i] = uniform(rng);
    Eigen::VectorXd r = Eigen::VectorXd::Zero(3 * m);
    const sma::ConeFixedPointResult res = sma::coulomb_cone_fixed_point(W, q, mu, 1.3, 1e-15, 200000, 1e-13, 500, r);
    ASSERT_TRUE(res.converged) << "trial " << trial;
    figures.fixed_point_iterations_max = std::max(figures.fixed_point_iterations_max, res.iterations);
    const Eigen::VectorXd ref = siconos_coulomb(W, q, mu, 3);
    Eigen::VectorXd gref(m), gour(m);
    for (int i = 0; i < m; ++i) gref[i] = mu[i] * ref[3 * i], gour[i] = mu[i] * r[3 * i];
    EXPECT_LE(sma::cone_law_residual(W, q, gref, ref), 1e-10) << "trial " << trial;
    const double law = sma::cone_law_residual(W, q, gour, r);
    figures.law_residual_max = std::max(figures.law_residual_max, law);
    EXPECT_LE(law, 1e-10) << "trial " << trial;
    const double scale = std::max(ref.lpNorm<Eigen::Infinity>(), 1e-12);
    figures.worst = std::max(figures.worst, (r - ref).lpNorm<Eigen::Infinity>() / scale);
    figures.cases++;
    for (int i = 0; i < m; ++i) {
      const double rt = std::hypot(r[3 * i + 1], r[3 * i + 2]);
      if (r[3 * i] <= 1e-12) figures.separated++;
      else if (rt >= gour[i] * (1 - 1e-9)) figures.sliding++;
      else figures.sticking++;
    }
  }
  EXPECT_LE(figures.worst, 1e-8);
  EXPECT_GT(figures.sliding, 5);
  EXPECT_GT(figures.sticking, 5);
  write_figures("siconos_cone_3d",
                "slip-threshold fixed point around psor_cone (omega 1.3, PSOR tol 1e-15, slip tol 1e-13) against "
                "Siconos fc3d_nsgs (tol 1e-15), the 3D Coulomb cone",
                figures);
}
