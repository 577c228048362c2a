// The coarse space of plugin/core/coarse_space.hpp: the aggregation of points by shared nodes, and
// the two-level preconditioner on an operator whose small eigenvalues have smooth eigenvectors
// (as the step's linearisation on a wide transformation front): A = D^-1 (eps D + L), L the
// points' graph Laplacian on a grid, D-self-adjoint like newton_direction's operator.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

#include "core/coarse_space.hpp"
#include "core/step_newton.hpp"

namespace {

// An m x m grid of cells (the points), each reading its 4 corner nodes (interp: points x nodes).
struct Grid {
  int m;
  Eigen::SparseMatrix<double> interp;  // column-major
  Eigen::SparseMatrix<double, Eigen::RowMajor> rows;
  Eigen::MatrixXd a;
  Eigen::VectorXd weight;
  explicit Grid(int m_, double eps = 1e-4) : m(m_) {
    const int n = m * m, nodes = (m + 1) * (m + 1);
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j)
        for (int di = 0; di < 2; ++di)
          for (int dj = 0; dj < 2; ++dj) t.emplace_back(i * m + j, (i + di) * (m + 1) + j + dj, 0.25);
    interp.resize(n, nodes);
    interp.setFromTriplets(t.begin(), t.end());
    rows = interp;
    weight.resize(n);
    for (int p = 0; p < n; ++p) weight[p] = 1.0 + 0.5 * std::sin(p);
    Eigen::MatrixXd s = eps * Eigen::MatrixXd(weight.asDiagonal());
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        const int p = i * m + j;
        auto link = [&](int q) { s(p, p) += 0.125, s(q, q) += 0.125, s(p, q) -= 0.125, s(q, p) -= 0.125; };
        if (i + 1 < m) link(p + m);
        if (j + 1 < m) link(p + 1);
      }
    a = weight.cwiseInverse().asDiagonal() * s;
  }
};

// Every point in one aggregate; aggregates connected (through shared nodes), of size/2 to 2 size
// points, about k / size of them.
TEST(CoarseSpace, AggregatesAreConnectedAndSized) {
  const Grid g(30);
  const int size = 16, n = g.m * g.m;
  const sma::Aggregates agg = sma::aggregate_points(g.rows, g.interp, sma::step_detail::all_points(n), size);
  ASSERT_EQ((int)agg.of.size(), n);
  std::vector<std::vector<int>> members((std::size_t)agg.count);
  for (int p = 0; p < n; ++p) {
    ASSERT_GE(agg.of[(std::size_t)p], 0);
    ASSERT_LT(agg.of[(std::size_t)p], agg.count);
    members[(std::size_t)agg.of[(std::size_t)p]].push_back(p);
  }
  EXPECT_GE(agg.count, n / (2 * size));
  EXPECT_LE(agg.count, 2 * n / size);
  for (const auto& mem : members) {
    EXPECT_GE((int)mem.size(), size / 2);
    EXPECT_LE((int)mem.size(), 2 * size);
    // Connected: a walk over neighbours (cells sharing a corner) inside the aggregate reaches all.
    std::vector<int> seen{mem[0]};
    for (std::size_t h = 0; h < seen.size(); ++h)
      for (int q : mem) {
        const int pi = seen[h] / g.m, pj = seen[h] % g.m, qi = q / g.m, qj = q % g.m;
        if (std::abs(pi - qi) <= 1 && std::abs(pj - qj) <= 1 && std::find(seen.begin(), seen.end(), q) == seen.end())
          seen.push_back(q);
      }
    EXPECT_EQ(seen.size(), mem.size());
  }
}

// The preconditioned solve (coarse products counted) takes fewer products than plain GMRES (measured
// 112 and 113, 64 of them the coarse space's, against 225), and its
// solution is the plain one's within GMRES's tolerance: both residuals below rtol, true residuals.
TEST(CoarseSpace, PreconditionedSolveGivesTheSameSolutionInFewerProducts) {
  const Grid g(32);
  const int n = g.m * g.m;
  const std::vector<Eigen::Index> sub = sma::step_detail::all_points(n);
  Eigen::VectorXd b(n);
  for (int p = 0; p < n; ++p) b[p] = std::cos(0.05 * p) + 0.3 * std::sin(0.7 * p);
  const double rtol = 1e-8;
  int plain_products = 0;
  auto plain = [&](const Eigen::VectorXd& x) { ++plain_products; return Eigen::VectorXd(g.a * x); };
  const sma::step_detail::GmresResult p = sma::step_detail::gmres(plain, b, rtol, 1000);
  ASSERT_TRUE(p.converged);
  for (bool additive : {false, true}) {
    int products = 0;
    auto apply = [&](const Eigen::VectorXd& x) { ++products; return Eigen::VectorXd(g.a * x); };
    const sma::CoarseSpace space = sma::build_coarse(sub, sma::coarse_vectors(g.rows, sub, sma::aggregate_points(g.rows, g.interp, sub, 16), 0), apply);
    EXPECT_EQ(products, space.count);  // one product an aggregate
    const sma::DeflationPreconditioner pre = sma::coarse_on(space, sub, g.weight, additive);
    auto preconditioned = [&](const Eigen::VectorXd& y) { return apply(pre.apply(y)); };
    const sma::step_detail::GmresResult c = sma::step_detail::gmres(preconditioned, b, rtol, 1000);
    ASSERT_TRUE(c.converged);
    const Eigen::VectorXd x = pre.apply(c.x);
    EXPECT_LE((g.a * x - b).norm(), 1.01 * rtol * b.norm()) << additive;
    EXPECT_LE((g.a * (x - p.x)).norm(), 2.02 * rtol * b.norm()) << additive;
    EXPECT_LE((x - p.x).norm(), 1e-3 * p.x.norm()) << additive;  // condition number about 1e4
    EXPECT_LT(products, 0.6 * p.iterations) << additive << ": " << products << " against " << p.iterations;
    EXPECT_GT(c.smallest_ritz_real, 10 * p.smallest_ritz_real) << additive;
  }
}

// On a subset of the points the space was built on (later active-set rounds), the restricted
// preconditioner is still self-adjoint and positive in D.
TEST(CoarseSpace, RestrictedPreconditionerIsPositive) {
  const Grid g(16);
  const int n = g.m * g.m;
  const std::vector<Eigen::Index> sub = sma::step_detail::all_points(n);
  auto apply = [&](const Eigen::VectorXd& x) { return Eigen::VectorXd(g.a * x); };
  const sma::CoarseSpace space = sma::build_coarse(sub, sma::coarse_vectors(g.rows, sub, sma::aggregate_points(g.rows, g.interp, sub, 8), 3), apply);
  std::vector<Eigen::Index> fewer;
  for (int p = 0; p < n; ++p)
    if (p % 7 != 3) fewer.push_back(p);
  const sma::DeflationPreconditioner pre = sma::coarse_on(space, fewer, g.weight);
  const Eigen::Index k = (Eigen::Index)fewer.size();
  Eigen::MatrixXd P(k, k);
  for (Eigen::Index j = 0; j < k; ++j) P.col(j) = pre.apply(Eigen::VectorXd::Unit(k, j));
  const Eigen::MatrixXd DP = pre.weight.asDiagonal() * P;
  EXPECT_LE((DP - DP.transpose()).norm(), 1e-10 * DP.norm());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (DP + DP.transpose()));
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
}

}  // namespace
