// The deflation space of plugin/core/deflation.hpp and the harmonic Ritz pairs gmres() harvests
// for it (plugin/core/step_newton.hpp), on operators whose spectrum is known: A = D^-1 S, S
// symmetric, self-adjoint in the inner product D (as the step's linearisation is).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "core/deflation.hpp"
#include "core/step_newton.hpp"

namespace {

// n x n, D-self-adjoint, `small` eigenvalues 1e-4 (1 + i), the rest in [0.2, 1]; `shift` moves
// the smallest one to -shift (an unstable mode).
struct KnownOperator {
  Eigen::MatrixXd a, vectors;
  Eigen::VectorXd weight, values;
  KnownOperator(int n, int small, double shift = 0.0) {
    weight.resize(n);
    for (int i = 0; i < n; ++i) weight[i] = 1.0 + 0.5 * std::sin(i);
    std::srand(7);
    const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(n, n)).householderQ();
    values.resize(n);
    for (int i = 0; i < n; ++i) values[i] = i < small ? 1e-4 * (1 + i) : 0.2 + 0.8 * i / n;
    if (shift > 0) values[0] = -shift;
    const Eigen::VectorXd root = weight.cwiseSqrt();
    // A = D^-1/2 Q L Q' D^1/2: D A = D^1/2 Q L Q' D^1/2 is symmetric.
    a = root.cwiseInverse().asDiagonal() * q * values.asDiagonal() * q.transpose() * root.asDiagonal();
    vectors = root.cwiseInverse().asDiagonal() * q;
  }
};

// The harvested images are A times the harvested vectors (from the Arnoldi relation, no product).
TEST(Deflation, HarvestedImagesAreTheOperatorsProducts) {
  const KnownOperator op(200, 10);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(200);
  int products = 0;
  auto apply = [&](const Eigen::VectorXd& x) { ++products; return Eigen::VectorXd(op.a * x); };
  const sma::step_detail::GmresResult g = sma::step_detail::gmres(apply, b, 1e-10, 300, false, 0.0, 1 << 30, 6);
  ASSERT_EQ(g.harvest_vectors.cols(), 6);
  EXPECT_EQ(products, g.iterations);  // the harvest costs no product
  const Eigen::MatrixXd error = op.a * g.harvest_vectors - g.harvest_images;
  EXPECT_LE(error.norm(), 1e-10 * g.harvest_images.norm());
}

// Recycled over repeated solves with the same operator, the space deflates its small eigenvalues:
// fewer products per solve (refresh included), the same solution to the solve's tolerance.
TEST(Deflation, RecycledSpaceCutsTheProductsOfRepeatedSolves) {
  const int n = 400;
  const KnownOperator op(n, 20);
  const std::vector<Eigen::Index> sub = sma::step_detail::all_points(n);
  sma::RecycledSpace space;
  space.capacity = 40;
  std::srand(11);
  int first = 0, last = 0;
  for (int solve = 0; solve < 6; ++solve) {
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    int products = 0;
    auto apply = [&](const Eigen::VectorXd& x) { ++products; return Eigen::VectorXd(op.a * x); };
    if (!space.empty()) sma::refresh(space, sub, op.weight, apply);
    const sma::DeflationPreconditioner pre = sma::deflation_on(space, sub, op.weight);
    auto preconditioned = [&](const Eigen::VectorXd& y) { return apply(pre.apply(y)); };
    const sma::step_detail::GmresResult g =
        sma::step_detail::gmres(preconditioned, b, 1e-8, 400, false, 0.0, 1 << 30, 8);
    ASSERT_TRUE(g.converged);
    const Eigen::VectorXd x = pre.apply(g.x);
    Eigen::VectorXd residual = op.a * x;
    residual -= b;
    EXPECT_LE(residual.norm(), 1.01e-8 * b.norm()) << "solve " << solve;  // the true residual
    Eigen::MatrixXd vectors(n, g.harvest_vectors.cols());
    for (Eigen::Index j = 0; j < vectors.cols(); ++j) vectors.col(j) = pre.apply(g.harvest_vectors.col(j));
    sma::recycle(space, vectors, g.harvest_images, op.weight);
    (solve == 0 ? first : last) = products;
  }
  EXPECT_LT(2 * last, first) << "first solve " << first << " products, last " << last;
}

// P is positive in D: an unstable operator stays unstable (a negative Ritz value of A P), and the
// Ritz vector mapped back by P has negative curvature v' D A v < 0, also when the unstable mode
// itself is in the deflation space.
TEST(Deflation, PreconditionedOperatorKeepsTheInstability) {
  const int n = 120;
  const KnownOperator op(n, 6, 0.05);
  const std::vector<Eigen::Index> sub = sma::step_detail::all_points(n);
  sma::RecycledSpace space;
  space.capacity = 10;
  // The space: the exact eigenvectors of the 6 smallest |eigenvalues| (the unstable one included).
  sma::recycle(space, op.vectors.leftCols(6), op.a * op.vectors.leftCols(6), op.weight);
  const sma::DeflationPreconditioner pre = sma::deflation_on(space, sub, op.weight);
  EXPECT_EQ(pre.q.cols(), 6);
  auto preconditioned = [&](const Eigen::VectorXd& y) { return Eigen::VectorXd(op.a * pre.apply(y)); };
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  const sma::step_detail::GmresResult g = sma::step_detail::gmres(preconditioned, b, 1e-12, n);
  ASSERT_TRUE(g.converged);
  EXPECT_LT(g.smallest_ritz_real, 0.0);
  const Eigen::VectorXd v = pre.apply(g.smallest_ritz_vector);
  EXPECT_LT(v.dot(op.weight.cwiseProduct(op.a * v)), 0.0);
  // The deflated modes moved to target (1): no Ritz value left below the stable ones but the
  // unstable one, now at -target.
  EXPECT_NEAR(g.smallest_ritz_real, -1.0, 1e-6);
}

// Inaccurate vectors (a mixture of a small and a large mode) are not deflated: P would carry
// their error outside the space at target x error / mu.
TEST(Deflation, InaccurateVectorsAreNotDeflated) {
  const int n = 100;
  const KnownOperator op(n, 4);
  sma::RecycledSpace space;
  space.capacity = 4;
  const Eigen::VectorXd mixed = op.vectors.col(0) + 0.1 * op.vectors.col(50);
  sma::recycle(space, mixed, op.a * mixed, op.weight);
  EXPECT_EQ(sma::deflation_on(space, sma::step_detail::all_points(n), op.weight).q.cols(), 0);
  sma::RecycledSpace exact;
  exact.capacity = 4;
  sma::recycle(exact, op.vectors.col(0), op.a * op.vectors.col(0), op.weight);
  EXPECT_EQ(sma::deflation_on(exact, sma::step_detail::all_points(n), op.weight).q.cols(), 1);
}

}  // namespace
