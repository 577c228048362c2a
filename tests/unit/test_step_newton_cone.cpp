// The step solver on Coulomb's cone (StepProblem::contact_rows 3, plugin/core/step_newton.hpp):
// its linearisation of the contact against finite differences on a state where nodes stick, slide
// with both tangential motions free (the direction turning with the slip) and slide along one
// (the other blocked by a support); a whole step on the cone whose nodes have one tangential
// motion blocked equals the same step on the 2D layout (n, t); and a tolerance below the floor
// the contact solves' own tolerances leave the residual stops the step at that floor, named as
// such, not as a hard step for a shorter trial.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "core/step_newton.hpp"
#include "random_problems.hpp"

namespace {

// A small body pressed onto a rigid obstacle at m contact nodes: dofs (x, y, z) of 2m vertices,
// the first m in contact (rows n = x, t1 = y, t2 = z), a random symmetric positive definite
// stiffness; `points` phase points, each loading the dofs through a random column of B, with a
// temperature of its own (heat nodes = points: a lumped capacity, no conduction). `blocked`:
// the dofs a support holds (tgv rows), so that the contact rows through them carry nothing.
struct ConeBody {
  int m = 3, points = 6;
  double dt = 0.1, capacity = 7900 * 837.0;  // rho C0 (J/m^3/K)
  sma::SparseMatrix K, B, latent, interp, heat_matrix;
  sma::SpdFactor stiffness, heat;
  sma::DelassusFactor contact;
  Eigen::VectorXd force, free, area;
  std::vector<int> blocked;

  int dofs() const { return 6 * m; }

  // Rows of the contact operator for `rows` per node: (x, y, z) of vertex i, or (x, z) with 2.
  sma::SparseMatrix contact_rows(int rows) const {
    sma::SparseMatrix H(rows * m, dofs());
    for (int i = 0; i < m; ++i) {
      H.insert(rows * i, 3 * i) = 1.0;
      if (rows == 3) H.insert(3 * i + 1, 3 * i + 1) = 1.0;
      H.insert(rows * i + rows - 1, 3 * i + 2) = 1.0;
    }
    return H;
  }

  void build(unsigned seed, int rows) {
    std::mt19937 rng(seed);
    const Eigen::MatrixXd k = sma_test::random_spd(dofs(), rng) * 1e8;
    std::normal_distribution<double> normal;
    K = k.sparseView();
    free = Eigen::VectorXd::Ones(dofs());
    for (int j : blocked) {
      free[j] = 0;
      K.coeffRef(j, j) = 1e30;
    }
    Eigen::MatrixXd b(dofs(), points);
    for (int j = 0; j < dofs(); ++j)
      for (int e = 0; e < points; ++e) b(j, e) = 1e-6 * normal(rng);
    B = b.sparseView();
    area = Eigen::VectorXd::Constant(points, 1e-6);
    // Pressed along x (the contact's normal) with tangential loads of either sign along y and z.
    force = Eigen::VectorXd::Zero(dofs());
    for (int i = 0; i < 2 * m; ++i) {
      force[3 * i] = -1e3 * (1 + 0.5 * normal(rng));
      force[3 * i + 1] = 4e2 * normal(rng);
      force[3 * i + 2] = 4e2 * normal(rng);
    }
    stiffness.factorize(K);
    std::vector<double> mask(free.data(), free.data() + dofs());
    contact = sma::delassus_factor(stiffness, contact_rows(rows), mask, false);
    latent = (Eigen::MatrixXd(area.asDiagonal())).sparseView();
    interp = Eigen::MatrixXd::Identity(points, points).sparseView();
    heat_matrix = (Eigen::MatrixXd::Identity(points, points) * (capacity * 1e-6 / dt)).sparseView();
    heat.factorize(heat_matrix);
  }

  sma::StepProblem problem(int rows, double mu) const {
    sma::StepProblem p;
    p.heat = &heat;
    p.heat_rhs = Eigen::VectorXd::Constant(points, capacity * 1e-6 / dt * 250.0);
    p.heat_mask = Eigen::VectorXd::Ones(points);
    p.latent = latent;
    p.latent_scale = 7900 * 3000 / dt;
    p.interp = interp;
    p.stiffness = &stiffness;
    p.contact = &contact;
    p.contact_rows = rows;
    p.load = B;
    p.area = area;
    p.force = force.cwiseProduct(free);
    p.free = free;
    p.gap = Eigen::VectorXd::Constant(m, -2e-7);  // an interference
    p.slip_reference = Eigen::VectorXd::Zero((rows - 1) * m);
    p.tangent_free = Eigen::VectorXd::Ones(m);
    p.mu = Eigen::VectorXd::Constant(m, mu);
    p.psor.omega = 1.0;
    p.psor.tol = 1e-14;
    p.psor.maxit = 100000;
    p.psor.polish = 10;
    p.slip_tol = 1e-14;
    p.slip_maxit = 2000;
    p.law = sma::ThermalLaw{7900, 300, 3000, 210, 280};
    p.laminate = 1e11;
    p.kappa = Eigen::VectorXd::Constant(points, 3000 / 837.0);  // L / C0
    p.chi_start = Eigen::VectorXd::Zero(points);
    p.b_start = Eigen::VectorXd::Zero(points);
    return p;
  }
};

// What each node does at the state s of a cone problem: 0 open, 1 stick, 2 slide with both
// tangential motions free (and a slip), 3 slide along one.
std::vector<int> cone_statuses(const sma::StepState& s, const ConeBody& body) {
  std::vector<int> status;
  for (int i = 0; i < body.m; ++i) {
    const double rn = s.r[3 * i], rt = std::hypot(s.r[3 * i + 1], s.r[3 * i + 2]);
    const bool both = body.contact.w(3 * i + 1, 3 * i + 1) != 0 && body.contact.w(3 * i + 2, 3 * i + 2) != 0;
    status.push_back(!(rn > 0) ? 0 : rt < s.threshold[i] * (1 - 1e-9) ? 1 : both ? 2 : 3);
  }
  return status;
}

TEST(StepNewtonCone, LinearisationMatchesFiniteDifferences) {
  // The first body (by seed) whose state holds a sticking node, a node sliding with both
  // tangential motions free and a node sliding along its one free motion (vertex 2's y held).
  // No latent heat (T stays where the heat right side puts it): the contact's share alone.
  for (unsigned seed = 1; seed <= 60; ++seed) {
    ConeBody body;
    body.blocked = {3 * 2 + 1};
    body.build(seed, 3);
    sma::StepProblem p = body.problem(3, 0.3);
    p.latent_scale = 0;
    sma::StepResult stats;
    sma::StepSolver solver(p, stats);
    const Eigen::VectorXd r0 = Eigen::VectorXd::Zero(3 * body.m), g0 = Eigen::VectorXd::Zero(body.m);
    // Fractions of the sign the state gives them (force_derivative holds the sign of the strain).
    Eigen::VectorXd beta(body.points);
    for (int e = 0; e < body.points; ++e) beta[e] = 0.2 + 0.1 * e;
    sma::StepState s = solver.evaluate(beta, r0, g0);
    for (int pass = 0; pass < 3; ++pass) s = solver.evaluate(s.sign.cwiseProduct(beta), r0, g0);
    if (s.chi != s.sign.cwiseProduct(beta)) continue;
    const std::vector<int> status = cone_statuses(s, body);
    const bool stick = std::count(status.begin(), status.end(), 1) > 0;
    const bool turn = std::count(status.begin(), status.end(), 2) > 0;
    const bool line = std::count(status.begin(), status.end(), 3) > 0;
    if (!(stick && turn && line)) continue;
    // The cone's law at the state: |r_t| <= mu r_n at every node.
    for (int i = 0; i < body.m; ++i)
      EXPECT_LE(std::hypot(s.r[3 * i + 1], s.r[3 * i + 2]), 0.3 * s.r[3 * i] * (1 + 1e-12)) << "node " << i;
    Eigen::VectorXd w(body.points);
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int e = 0; e < body.points; ++e) w[e] = unit(gen);
    std::vector<char> upper((std::size_t)body.points, 0);
    const Eigen::VectorXd analytic = solver.force_derivative(s, w, upper);
    auto forces = [&](double t) {
      const Eigen::VectorXd moved = beta + t * w;
      const sma::StepState st = solver.evaluate(s.sign.cwiseProduct(moved), r0, g0);
      EXPECT_EQ(cone_statuses(st, body), status) << "the statuses changed within the difference's step";
      return Eigen::VectorXd(st.drive - st.q.cwiseProduct(moved));
    };
    const double h = 1e-4;
    const Eigen::VectorXd fd = (forces(h) - forces(-h)) / (2 * h);
    EXPECT_LE((fd - analytic).lpNorm<Eigen::Infinity>(), 1e-7 * analytic.lpNorm<Eigen::Infinity>()) << "seed " << seed;
    return;
  }
  FAIL() << "no seed gave a state with a sticking node and nodes sliding in the plane and along a line";
}

// The cone whose every node has its y motion held is the 2D layout (n, z): the same step.
TEST(StepNewtonCone, ConeWithOneTangentialMotionHeldIsThe2dLayout) {
  for (unsigned seed : {3u, 11u}) {
    ConeBody cone, plane;
    for (int i = 0; i < cone.m; ++i) cone.blocked.push_back(3 * i + 1);
    plane.blocked = cone.blocked;
    cone.build(seed, 3);
    plane.build(seed, 2);
    const sma::StepProblem pc = cone.problem(3, 0.2), pp = plane.problem(2, 0.2);
    Eigen::VectorXd chi_c = Eigen::VectorXd::Zero(cone.points), chi_p = chi_c;
    Eigen::VectorXd rc = Eigen::VectorXd::Zero(3 * cone.m), rp = Eigen::VectorXd::Zero(2 * cone.m);
    Eigen::VectorXd gc = Eigen::VectorXd::Zero(cone.m), gp = gc;
    Eigen::VectorXd Tc(cone.points), Tp(cone.points), uc(cone.dofs()), up(cone.dofs());
    const sma::StepResult a = sma::solve_fraction_step(pc, sma::StepSettings{}, chi_c, rc, gc, Tc, uc);
    const sma::StepResult b = sma::solve_fraction_step(pp, sma::StepSettings{}, chi_p, rp, gp, Tp, up);
    ASSERT_TRUE(a.converged && b.converged) << a.failure << " / " << b.failure;
    int sliding = 0;
    for (int i = 0; i < cone.m; ++i) {
      EXPECT_EQ(rc[3 * i + 1], 0.0);
      EXPECT_NEAR(rc[3 * i], rp[2 * i], 1e-10 * rp.lpNorm<Eigen::Infinity>());
      EXPECT_NEAR(rc[3 * i + 2], rp[2 * i + 1], 1e-10 * rp.lpNorm<Eigen::Infinity>());
      sliding += rp[2 * i] > 0 && std::fabs(rp[2 * i + 1]) >= gp[i] * (1 - 1e-9);
    }
    EXPECT_GT(sliding, 0) << "seed " << seed << ": no node slides, the friction is not tested";
    EXPECT_LE((chi_c - chi_p).lpNorm<Eigen::Infinity>(), 1e-9);
    EXPECT_LE((uc - up).lpNorm<Eigen::Infinity>(), 1e-9 * up.lpNorm<Eigen::Infinity>());
    EXPECT_LE((Tc - Tp).lpNorm<Eigen::Infinity>(), 1e-9 * Tp.lpNorm<Eigen::Infinity>());
  }
}

// How many points are part-transformed (0 < |chi| < 1): where the law's residual is not exact.
int partly_transformed_points(const Eigen::VectorXd& chi) {
  int n = 0;
  for (Eigen::Index e = 0; e < chi.size(); ++e) n += std::fabs(chi[e]) > 0 && std::fabs(chi[e]) < 1;
  return n;
}

// A step asked for a residual below what it can reach (tol 1e-15, below round-off, which the
// scripts refuse as -steptol; its contact solves, PSOR and the slip threshold, to 1e-5 without the
// polish) stops at that floor: at_floor, the noise the probe measured (the same fractions, the
// contact solved again from the step's start) within floor_factor of the residual, and never a
// trial given up (a shorter step meets the same floor: sleeve-3d -steptol 1e-11 crawled;
// tests/step_solver_test.py runs that scene).
// The noise follows the contact's tolerance; a step stopped short of a tolerance above the floor
// (one iteration) is a hard step, not a floor.
TEST(StepNewtonCone, ToleranceBelowTheContactsFloorStopsThere) {
  struct Outcome {
    sma::StepResult result;
    double residual = 0;
  };
  const auto step = [](unsigned seed, double contact_tol, double tol, int maxit) {
    ConeBody body;
    body.build(seed, 3);
    sma::StepProblem p = body.problem(3, 0.3);
    // (1 K below T0 = 210 K, where c(T) is small: the strains hold the points part-transformed, so the
    // law's residual feels every change of the contact)
    p.heat_rhs *= 209.0 / 250.0;
    p.psor.tol = contact_tol;
    p.psor.polish = 0;
    p.slip_tol = contact_tol;
    sma::StepSettings set;
    set.tol = tol;
    set.maxit = maxit;
    set.product_budget = 100000;  // a trial: a hard step would be given up for a shorter one
    Eigen::VectorXd chi = Eigen::VectorXd::Zero(body.points), r = Eigen::VectorXd::Zero(3 * body.m);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(body.m), T(body.points), u(body.dofs());
    Outcome out;
    out.result = sma::solve_fraction_step(p, set, chi, r, g, T, u);
    out.residual = out.result.residual;
    return out;
  };
  int floors = 0, hard = 0;
  for (unsigned seed = 1; seed <= 20 && floors < 3; ++seed) {
    const Outcome coarse = step(seed, 1e-5, 1e-15, 50);
    if (coarse.result.converged) continue;  // (a state whose fractions the contact's noise does not reach)
    ++floors;
    EXPECT_TRUE(coarse.result.at_floor) << "seed " << seed << ": " << coarse.result.failure << ", residual "
                                        << coarse.residual << ", noise " << coarse.result.residual_noise;
    EXPECT_TRUE(coarse.result.floor_is_noise) << "seed " << seed;
    EXPECT_FALSE(coarse.result.trial_given_up) << "seed " << seed;
    EXPECT_GT(coarse.result.residual_noise, 0.0);
    EXPECT_LE(coarse.residual, sma::StepSettings{}.floor_factor * coarse.result.residual_noise);
    // A thousand times tighter contact solves: a noise at least ten times lower.
    const Outcome fine = step(seed, 1e-8, 1e-15, 50);
    EXPECT_FALSE(fine.result.converged) << "seed " << seed;
    EXPECT_LE(fine.result.residual_noise, 0.1 * coarse.result.residual_noise) << "seed " << seed;
    // A tolerance far above the floor (1e-6) not reached in one iteration: a hard step, no floor.
    const Outcome short_of = step(seed, 1e-5, 1e-6, 1);
    if (!short_of.result.converged) {
      ++hard;
      EXPECT_FALSE(short_of.result.at_floor) << "seed " << seed << ": residual " << short_of.residual << ", noise "
                                             << short_of.result.residual_noise;
    }
  }
  EXPECT_GE(floors, 3) << "fewer than three states met the floor: the case tests nothing";
  EXPECT_GE(hard, 1) << "no step stopped short of a tolerance above the floor: the other side is not tested";
  // Without contact there is no noise to probe: the floor is round-off's (roundoff_floor, 1e-12):
  // tol 1e-17 stops there, at_floor, not given up; tol 1e-10 is met.
  for (const double tol : {1e-17, 1e-10}) {
    ConeBody body;
    body.build(1, 3);
    sma::StepProblem p = body.problem(3, 0.3);
    p.heat_rhs *= 209.0 / 250.0;
    p.contact = nullptr;
    sma::StepSettings set;
    set.tol = tol;
    set.product_budget = 100000;
    Eigen::VectorXd chi = Eigen::VectorXd::Zero(body.points), r(0), g(0), T(body.points), u(body.dofs());
    const sma::StepResult res = sma::solve_fraction_step(p, set, chi, r, g, T, u);
    if (tol > 1e-12) {
      EXPECT_TRUE(res.converged) << res.failure;
      continue;
    }
    EXPECT_FALSE(res.converged);
    EXPECT_TRUE(res.at_floor) << res.failure << ", residual " << res.residual;
    EXPECT_FALSE(res.trial_given_up);
    EXPECT_EQ(res.residual_noise, 0.0);
    EXPECT_FALSE(res.floor_is_noise);
    EXPECT_LE(res.residual, set.roundoff_floor);
    EXPECT_GT(partly_transformed_points(chi), 0) << "no point part-transformed: the law's residual is exact";
  }
}

// The step on solvers the caller provides (sparse_spd.hpp ExternalSolver, delassus_from_caller_columns:
// the distributed run's ffddm solves, edp/solvers/distributed.idp) equals the step on the plugin's
// factors: here the caller's solves are dense LDL' of the supports-eliminated matrices (an
// independent computation), C = S K^-1 S H' and W = H C from them, the columns' product C' z the
// sum of two slices of their rows, as two MPI ranks give it. On the cone with friction (a support
// blocking one tangential motion) and on the frictionless 2D layout (normal rows only).
TEST(StepNewtonCone, ExternalSolversGiveTheFactorsStep) {
  for (const int rows : {3, 2}) {
    const double mu = rows == 3 ? 0.3 : 0.0;
    ConeBody body;
    body.blocked = {3 * 2 + 1};
    body.build(7, rows);
    const bool normal_only = mu == 0;
    std::vector<double> mask(body.free.data(), body.free.data() + body.dofs());
    if (normal_only) body.contact = sma::delassus_factor(body.stiffness, body.contact_rows(rows), mask, true);
    // S K S + (I - S): the supports' rows and columns those of the identity
    const Eigen::VectorXd s = body.free;
    Eigen::MatrixXd eliminated = s.asDiagonal() * Eigen::MatrixXd(body.K) * s.asDiagonal();
    eliminated.diagonal() += (Eigen::VectorXd::Ones(body.dofs()) - s);
    const Eigen::LDLT<Eigen::MatrixXd> k_dense(eliminated);
    const Eigen::LDLT<Eigen::MatrixXd> heat_dense{Eigen::MatrixXd(body.heat_matrix)};
    int stiffness_calls = 0;
    sma::ExternalSolver stiffness(body.dofs(), [&](const Eigen::VectorXd& b, sma::span<double> x) {
      ++stiffness_calls;
      EXPECT_EQ(b.cwiseProduct(Eigen::VectorXd::Ones(body.dofs()) - s).lpNorm<Eigen::Infinity>(), 0.0)
          << "a right side nonzero on a support row";
      Eigen::Map<Eigen::VectorXd>(x.begin(), body.dofs()) = k_dense.solve(b);
    });
    sma::ExternalSolver heat(body.points, [&](const Eigen::VectorXd& b, sma::span<double> x) {
      Eigen::Map<Eigen::VectorXd>(x.begin(), body.points) = heat_dense.solve(b);
    });
    const sma::SparseMatrix H = body.contact_rows(rows);
    const Eigen::MatrixXd Ht = Eigen::MatrixXd(H).transpose();
    std::vector<int> formed;
    for (int r = 0; r < H.rows(); r += normal_only ? 2 : 1) formed.push_back(r);
    Eigen::MatrixXd columns(body.dofs(), (Eigen::Index)formed.size());
    for (std::size_t j = 0; j < formed.size(); ++j)
      columns.col((Eigen::Index)j) = s.asDiagonal() * k_dense.solve(s.asDiagonal() * Ht.col(formed[j]));
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(H.rows(), H.rows());
    for (std::size_t j = 0; j < formed.size(); ++j)
      for (std::size_t i = 0; i < formed.size(); ++i)
        W(formed[i], formed[j]) = (Eigen::MatrixXd(H).row(formed[i]) * columns.col((Eigen::Index)j))(0, 0);
    EXPECT_LE((W - body.contact.w).lpNorm<Eigen::Infinity>(), 1e-10 * body.contact.w.lpNorm<Eigen::Infinity>());

    sma::DelassusFactor caller_contact = sma::delassus_from_caller_columns(H, mask, W, normal_only);
    EXPECT_TRUE(caller_contact.caller_columns);
    const Eigen::Index half = body.dofs() / 2, rest = body.dofs() - half;
    int motion_calls = 0;
    caller_contact.motion = [&](const Eigen::VectorXd& z, sma::span<double> out) {
      ++motion_calls;
      Eigen::Map<Eigen::VectorXd>(out.begin(), columns.cols()) =
          columns.topRows(half).transpose() * z.head(half) + columns.bottomRows(rest).transpose() * z.tail(rest);
    };
    const auto step = [&](bool external, Eigen::VectorXd& chi, Eigen::VectorXd& r, Eigen::VectorXd& T, Eigen::VectorXd& u) {
      sma::StepProblem p = body.problem(rows, mu);
      p.heat_rhs *= 209.0 / 250.0;  // (1 K below T0: the points part-transform, as in the floor's case)
      if (external) {
        p.stiffness = &stiffness;
        p.heat = &heat;
        p.contact = &caller_contact;
      }
      sma::StepSettings set;
      set.tol = 1e-10;
      chi = Eigen::VectorXd::Zero(body.points);
      r = Eigen::VectorXd::Zero(rows * body.m);
      Eigen::VectorXd g = Eigen::VectorXd::Zero(body.m);
      T.resize(body.points);
      u.resize(body.dofs());
      return sma::solve_fraction_step(p, set, chi, r, g, T, u);
    };
    Eigen::VectorXd chi_f, r_f, T_f, u_f, chi_e, r_e, T_e, u_e;
    const sma::StepResult factors = step(false, chi_f, r_f, T_f, u_f);
    const sma::StepResult external = step(true, chi_e, r_e, T_e, u_e);
    ASSERT_TRUE(factors.converged) << factors.failure;
    ASSERT_TRUE(external.converged) << external.failure;
    EXPECT_GT(chi_f.lpNorm<Eigen::Infinity>(), 0.0) << "rows " << rows << ": nothing transforms, the law is not tested";
    EXPECT_GT(r_f.lpNorm<Eigen::Infinity>(), 0.0) << "rows " << rows << ": no contact";
    EXPECT_LE((chi_e - chi_f).lpNorm<Eigen::Infinity>(), 1e-8) << "rows " << rows;
    EXPECT_LE((u_e - u_f).lpNorm<Eigen::Infinity>(), 1e-8 * u_f.lpNorm<Eigen::Infinity>()) << "rows " << rows;
    EXPECT_LE((r_e - r_f).lpNorm<Eigen::Infinity>(), 1e-8 * r_f.lpNorm<Eigen::Infinity>()) << "rows " << rows;
    EXPECT_LE((T_e - T_f).lpNorm<Eigen::Infinity>(), 1e-10 * T_f.lpNorm<Eigen::Infinity>()) << "rows " << rows;
    EXPECT_GT(stiffness_calls, 0);
    EXPECT_GT(motion_calls, 0) << "rows " << rows << ": the caller's product never asked";
  }
}

// An external solver called with no solve bound, or with a vector of the wrong size, says so.
TEST(StepNewtonCone, ExternalSolverRefusesWhatItCannotSolve) {
  sma::ExternalSolver unbound(3);
  Eigen::VectorXd z = Eigen::VectorXd::Ones(3), x(3);
  EXPECT_THROW(unbound.backward_in_place(z, sma::span<double>(x.data(), 3)), std::logic_error);
  Eigen::VectorXd wrong = Eigen::VectorXd::Ones(2);
  EXPECT_THROW(unbound.forward_into(sma::span<const double>(wrong.data(), 2), z), std::invalid_argument);
  const sma::SparseMatrix H(2, 3);
  std::vector<double> free(3, 1.0);
  EXPECT_THROW(sma::delassus_from_caller_columns(H, free, Eigen::MatrixXd::Zero(3, 3), false),
               std::invalid_argument);  // W of 3 rows for 2
  // columns the caller keeps, used with no product bound
  const sma::SparseMatrix H2 = Eigen::MatrixXd::Identity(2, 3).sparseView();
  const sma::DelassusFactor caller = sma::delassus_from_caller_columns(H2, free, Eigen::MatrixXd::Identity(2, 2), false);
  EXPECT_THROW(sma::contact_motion(caller, Eigen::VectorXd::Ones(3)), std::logic_error);
}

}  // namespace
