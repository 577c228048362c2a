// Unit tests of the projected SOR on the full stiffness system (plugin/core/psor_full.hpp):
// on random stiffness-like SPD systems with Dirichlet rows marked by a huge diagonal (FreeFEM's
// tgv), contact nodes with random frames, gaps, Tresca thresholds and slip references, the full
// sweeps (mode a) give the same displacement and reactions as the condensed Delassus sweeps
// (mode b) built from an exact elimination of the Dirichlet dofs.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "core/psor_full.hpp"

namespace {

struct Problem {
  int nv = 0;
  Eigen::MatrixXd K;  // with tgv on Dirichlet diagonals
  Eigen::VectorXd b;
  std::vector<char> dirichlet;
  std::vector<int> vertex;
  std::vector<double> nx, ny, gap, g, p;
};

Problem random_problem(std::mt19937& rng, bool blocked_contact_node) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Problem P;
  P.nv = 6;
  const int n = 2 * P.nv;
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j) = normal(rng);
  P.K = A.transpose() * A + 0.5 * n * Eigen::MatrixXd::Identity(n, n);
  P.b.resize(n);
  for (int i = 0; i < n; ++i) P.b[i] = normal(rng);
  P.dirichlet.assign(n, 0);
  P.dirichlet[2 * 5] = 1;  // vertex 5 fixed in x (not a contact node)
  P.vertex = {0, 2, 3};
  for (int v : P.vertex) {
    const double a = 2 * M_PI * uniform(rng);
    P.nx.push_back(std::cos(a));
    P.ny.push_back(std::sin(a));
    P.gap.push_back(normal(rng));
    P.g.push_back(uniform(rng));
    P.p.push_back(0.3 * normal(rng));
    (void)v;
  }
  if (blocked_contact_node) {  // vertex 3 on a symmetry cut: y blocked, normal along x
    P.dirichlet[2 * 3 + 1] = 1;
    P.nx[2] = -1.0;
    P.ny[2] = 0.0;
    P.g[2] = 0.0;
  }
  for (int i = 0; i < n; ++i)
    if (P.dirichlet[i]) P.K(i, i) = 1e30, P.b[i] = 0.0;  // FreeFEM: homogeneous Dirichlet
  return P;
}

struct Csr {
  std::vector<int> row, col;
  std::vector<double> val;
  sma::CsrView view(int n) const { return {n, row.data(), col.data(), val.data()}; }
};

Csr to_csr(const Eigen::MatrixXd& K) {
  Csr c;
  c.row.push_back(0);
  for (int i = 0; i < K.rows(); ++i) {
    for (int j = 0; j < K.cols(); ++j)
      if (K(i, j) != 0.0) c.col.push_back(j), c.val.push_back(K(i, j));
    c.row.push_back((int)c.col.size());
  }
  return c;
}

// Mode (b) on the system with the Dirichlet dofs eliminated exactly.
void condensed_reference(const Problem& P, Eigen::VectorXd& u, Eigen::VectorXd& r) {
  const int n = 2 * P.nv, m = (int)P.vertex.size();
  std::vector<int> freeDofs;
  for (int i = 0; i < n; ++i)
    if (!P.dirichlet[i]) freeDofs.push_back(i);
  const int nf = (int)freeDofs.size();
  Eigen::MatrixXd Kf(nf, nf), H = Eigen::MatrixXd::Zero(2 * m, nf);
  Eigen::VectorXd bf(nf);
  for (int a = 0; a < nf; ++a) {
    bf[a] = P.b[freeDofs[a]];
    for (int c = 0; c < nf; ++c) Kf(a, c) = P.K(freeDofs[a], freeDofs[c]);
  }
  for (int i = 0; i < m; ++i)
    for (int a = 0; a < nf; ++a) {
      const int v = P.vertex[i];
      const bool blocked = P.dirichlet[2 * v] || P.dirichlet[2 * v + 1];
      if (freeDofs[a] == 2 * v) H(2 * i, a) = P.nx[i], H(2 * i + 1, a) = blocked ? 0 : -P.ny[i];
      if (freeDofs[a] == 2 * v + 1) H(2 * i, a) = P.ny[i], H(2 * i + 1, a) = blocked ? 0 : P.nx[i];
    }
  const Eigen::LDLT<Eigen::MatrixXd> Kinv(Kf);
  const Eigen::MatrixXd G = Kinv.solve(H.transpose());
  const Eigen::MatrixXd W = H * G;
  const Eigen::VectorXd ufree = Kinv.solve(bf), Hu = H * ufree;
  Eigen::VectorXd q(2 * m), g(m);
  for (int i = 0; i < m; ++i) {
    q[2 * i] = -(Hu[2 * i] + P.gap[i]);
    q[2 * i + 1] = W(2 * i + 1, 2 * i + 1) == 0 ? 0 : -(Hu[2 * i + 1] - P.p[i]);
    g[i] = P.g[i];
  }
  r = Eigen::VectorXd::Zero(2 * m);
  const sma::PsorResult res = sma::psor_condensed(W, q, g, 1.2, 1e-15, 200000, r);
  ASSERT_TRUE(res.converged);
  const Eigen::VectorXd uf = ufree + G * r;
  u = Eigen::VectorXd::Zero(n);
  for (int a = 0; a < nf; ++a) u[freeDofs[a]] = uf[a];
}

void check_agreement(bool blocked_contact_node, double omega) {
  std::mt19937 rng(blocked_contact_node ? 7 : 11);
  double worst_u = 0, worst_r = 0;
  int active = 0, sliding = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Problem P = random_problem(rng, blocked_contact_node);
    const int n = 2 * P.nv, m = (int)P.vertex.size();
    Eigen::VectorXd uref, rref;
    condensed_reference(P, uref, rref);
    const Csr K = to_csr(P.K);
    std::vector<double> u(n, 0.0), rn(m), rt(m);
    sma::ContactNodesView c{P.vertex, P.nx, P.ny, P.gap, P.g, P.p};
    sma::FullPsorSettings set;
    set.omega = omega;
    set.tol = 1e-15;
    set.maxit = 200000;
    const sma::PsorResult res =
        sma::psor_full(K.view(n), sma::span<const double>(P.b.data(), n), c, set, u, rn, rt);
    ASSERT_TRUE(res.converged) << "trial " << trial << " residual " << res.residual;
    double du = 0, dr = 0;
    for (int i = 0; i < n; ++i) du = std::max(du, std::fabs(u[i] - uref[i]));
    for (int i = 0; i < m; ++i) {
      dr = std::max({dr, std::fabs(rn[i] - rref[2 * i]), std::fabs(rt[i] - rref[2 * i + 1])});
      active += rn[i] > 1e-12;
      sliding += P.g[i] > 0 && std::fabs(std::fabs(rt[i]) - P.g[i]) < 1e-9;
    }
    worst_u = std::max(worst_u, du / uref.lpNorm<Eigen::Infinity>());
    worst_r = std::max(worst_r, dr / std::max(1e-300, rref.lpNorm<Eigen::Infinity>()));
    EXPECT_EQ(u[2 * 5], 0.0) << "the Dirichlet dof moved";
  }
  EXPECT_LE(worst_u, 1e-10);
  EXPECT_LE(worst_r, 1e-9);
  EXPECT_GT(active, 20) << "too few active contacts for the test to mean anything";
  EXPECT_GT(sliding, 5) << "too few sliding contacts for the test to mean anything";
  std::printf("full vs condensed (omega %.2f%s): max rel. diff u %.2e, r %.2e; %d active, %d sliding\n",
              omega, blocked_contact_node ? ", node on a cut" : "", worst_u, worst_r, active, sliding);
}

}  // namespace

TEST(PsorFull, EqualsCondensedOnRandomProblems) { check_agreement(false, 1.0); }
TEST(PsorFull, EqualsCondensedOverRelaxed) { check_agreement(false, 1.5); }
TEST(PsorFull, ContactNodeOnASymmetryCut) { check_agreement(true, 1.3); }

TEST(PsorFull, RejectsBadInput) {
  std::mt19937 rng(3);
  Problem P = random_problem(rng, false);
  const int n = 2 * P.nv, m = 3;
  const Csr K = to_csr(P.K);
  std::vector<double> u(n, 0.0), rn(m), rt(m);
  sma::ContactNodesView c{P.vertex, P.nx, P.ny, P.gap, P.g, P.p};
  sma::FullPsorSettings set;
  set.omega = 2.0;
  EXPECT_THROW(sma::psor_full(K.view(n), sma::span<const double>(P.b.data(), n), c, set, u, rn, rt),
               std::invalid_argument);
  set.omega = 1.0;
  P.g[1] = -1.0;
  sma::ContactNodesView bad{P.vertex, P.nx, P.ny, P.gap, P.g, P.p};
  EXPECT_THROW(sma::psor_full(K.view(n), sma::span<const double>(P.b.data(), n), bad, set, u, rn, rt),
               std::invalid_argument);
  P.g[1] = 0.0;
  P.dirichlet[2 * 0] = 1;  // contact vertex 0 blocked in x with a generic normal
  P.K(0, 0) = 1e30;
  const Csr K2 = to_csr(P.K);
  sma::ContactNodesView c2{P.vertex, P.nx, P.ny, P.gap, P.g, P.p};
  EXPECT_THROW(sma::psor_full(K2.view(n), sma::span<const double>(P.b.data(), n), c2, set, u, rn, rt),
               std::invalid_argument);
}
