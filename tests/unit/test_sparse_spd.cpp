// Unit tests of the plugin's sparse SPD factorisation and Delassus operator
// (plugin/core/sparse_spd.hpp), against dense Eigen computations of the same quantities.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/contact_step.hpp"
#include "core/sparse_spd.hpp"

namespace {

using sma::SparseMatrix;

// The 5-point Laplacian of an nx x ny grid plus shift I: sparse, symmetric positive definite, the
// pattern of a P1 stiffness on a structured mesh.
SparseMatrix grid_laplacian(int nx, int ny, double shift) {
  std::vector<Eigen::Triplet<double, int>> t;
  auto id = [&](int i, int j) { return i * ny + j; };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      t.emplace_back(id(i, j), id(i, j), 4.0 + shift);
      if (i > 0) t.emplace_back(id(i, j), id(i - 1, j), -1.0);
      if (i + 1 < nx) t.emplace_back(id(i, j), id(i + 1, j), -1.0);
      if (j > 0) t.emplace_back(id(i, j), id(i, j - 1), -1.0);
      if (j + 1 < ny) t.emplace_back(id(i, j), id(i, j + 1), -1.0);
    }
  SparseMatrix a(nx * ny, nx * ny);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

Eigen::VectorXd random_vector(int n, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = normal(rng);
  return v;
}

double relative(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }

// The contact rows of m nodes (normal n = (0.8, 0.6), tangent (-0.6, 0.8) on each node's two
// unknowns nodes[i], nodes[i] + 1): H, 2m x n, as the contact tests use it.
SparseMatrix contact_rows(int n, const int* nodes, int m) {
  std::vector<Eigen::Triplet<double, int>> t;
  for (int i = 0; i < m; ++i) {
    t.emplace_back(2 * i, nodes[i], 0.8);
    t.emplace_back(2 * i, nodes[i] + 1, 0.6);
    t.emplace_back(2 * i + 1, nodes[i], -0.6);
    t.emplace_back(2 * i + 1, nodes[i] + 1, 0.8);
  }
  SparseMatrix h(2 * m, n);
  h.setFromTriplets(t.begin(), t.end());
  return h;
}

// Contact rows that are unit vectors on dofs: per node i, one row per entry of `offsets`, on the dof
// nodes[i] + offset (the normal first, then the tangents).
SparseMatrix unit_rows(int n, const int* nodes, int m, const std::vector<int>& offsets) {
  const int k = (int)offsets.size();
  std::vector<Eigen::Triplet<double, int>> t;
  for (int i = 0; i < m; ++i)
    for (int c = 0; c < k; ++c) t.emplace_back(k * i + c, nodes[i] + offsets[c], 1.0);
  SparseMatrix h(k * m, n);
  h.setFromTriplets(t.begin(), t.end());
  return h;
}

std::vector<double> to_std(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

TEST(SparseSpd, SolveEqualsDenseSolve) {
  std::mt19937 rng(1);
  const SparseMatrix a = grid_laplacian(12, 9, 0.01);
  sma::SpdFactor f;
  f.factorize(a);
  const Eigen::VectorXd b = random_vector(a.rows(), rng);
  std::vector<double> bs = to_std(b), x(a.rows());
  f.solve(bs, x);
  const Eigen::VectorXd exact = Eigen::MatrixXd(a).llt().solve(b);
  EXPECT_LT(relative(Eigen::Map<Eigen::VectorXd>(x.data(), x.size()), exact), 1e-12);
  // A block of right-hand sides gives the same columns.
  Eigen::MatrixXd block(a.rows(), 3);
  for (int c = 0; c < 3; ++c) block.col(c) = random_vector(a.rows(), rng);
  const Eigen::MatrixXd xb = f.solve(block), xe = Eigen::MatrixXd(a).llt().solve(block);
  EXPECT_LT((xb - xe).norm() / xe.norm(), 1e-12);
  EXPECT_GT(f.factor_nonzeros(), 0);
}

// The two halves of a solve (the contact step works between them) give solve() bit for bit.
TEST(SparseSpd, ForwardThenBackwardIsTheSolve) {
  std::mt19937 rng(2);
  const SparseMatrix a = grid_laplacian(11, 7, 0.02);
  sma::SpdFactor f;
  f.factorize(a);
  const std::vector<double> b = to_std(random_vector(a.rows(), rng));
  std::vector<double> x(a.rows()), halves(a.rows());
  f.solve(b, x);
  f.backward(f.forward(b), halves);
  for (int i = 0; i < a.rows(); ++i) ASSERT_EQ(halves[i], x[i]) << "dof " << i;
  EXPECT_THROW(f.backward(Eigen::VectorXd::Zero(a.rows() + 1), halves), std::invalid_argument);
}

// The halves on a caller's work vector (the step solver's) give solve() bit for bit, also
// with signed zeros in the right side (Dirichlet rows of a masked load).
TEST(SparseSpd, WorkVectorHalvesAreTheSolve) {
  std::mt19937 rng(3);
  const SparseMatrix a = grid_laplacian(9, 8, 0.05);
  sma::SpdFactor f;
  f.factorize(a);
  Eigen::VectorXd rhs = random_vector(a.rows(), rng);
  rhs[0] = -0.0, rhs[5] = 0.0, rhs[a.rows() - 1] = -0.0;
  const std::vector<double> b = to_std(rhs);
  std::vector<double> x(a.rows()), halves(a.rows());
  f.solve(b, x);
  Eigen::VectorXd z(3);  // resized by forward_into
  f.forward_into(b, z);
  const Eigen::VectorXd reference = f.forward(b);
  for (int i = 0; i < a.rows(); ++i) ASSERT_EQ(std::signbit(z[i]), std::signbit(reference[i])) << "dof " << i;
  ASSERT_EQ(z, reference);
  f.backward_in_place(z, halves);
  for (int i = 0; i < a.rows(); ++i) {
    ASSERT_EQ(halves[i], x[i]) << "dof " << i;
    ASSERT_EQ(std::signbit(halves[i]), std::signbit(x[i])) << "dof " << i;
  }
  Eigen::VectorXd wrong = Eigen::VectorXd::Zero(a.rows() + 1);
  EXPECT_THROW(f.backward_in_place(wrong, halves), std::invalid_argument);
}

// The raw-pointer triangular solves of the halves give Eigen's sparse triangular solves
// (SimplicialLDLT's matrixL() and matrixU() views) bit for bit, signed zeros included, on a
// factor's L and on a strictly lower L stored uncompressed with its diagonal entries present
// (which both skip); and they solve L x = b, L' x = b to round-off (an independent dense solve).
TEST(SparseSpd, TriangularSolvesAreEigens) {
  std::mt19937 rng(4);
  Eigen::SimplicialLDLT<SparseMatrix> reference(grid_laplacian(10, 9, 0.03));
  const SparseMatrix& l = reference.matrixL().nestedExpression();
  // An uncompressed L with explicit (ignored) unit diagonal entries, as the skip rules allow.
  const int n = 40;
  SparseMatrix other(n, n);
  other.reserve(Eigen::VectorXi::Constant(n, 6));
  std::uniform_real_distribution<double> uniform(-0.5, 0.5);
  for (int j = 0; j < n; ++j) {
    other.insert(j, j) = 7.0;  // not read: the views are unit-diagonal
    for (int i = j + 1; i < n; i += 1 + (i * 7 + j) % 5) other.insert(i, j) = uniform(rng);
  }
  ASSERT_FALSE(other.isCompressed());
  const SparseMatrix* const matrices[] = {&l, &other};
  for (const SparseMatrix* m : matrices) {
    const int size = (int)m->rows();
    Eigen::VectorXd b = random_vector(size, rng);
    b[0] = -0.0, b[3] = 0.0, b[size - 1] = -0.0, b[size / 2] = 0.0;
    Eigen::VectorXd lower = b, upper = b, lower_eigen = b, upper_eigen = b;
    sma::unit_lower_solve_in_place(*m, lower.data());
    sma::unit_upper_solve_in_place(*m, upper.data());
    Eigen::TriangularView<const SparseMatrix, Eigen::UnitLower>(*m).solveInPlace(lower_eigen);
    Eigen::TriangularView<const Eigen::Transpose<const SparseMatrix>, Eigen::UnitUpper>(m->transpose())
        .solveInPlace(upper_eigen);
    for (int i = 0; i < size; ++i) {
      ASSERT_EQ(lower[i], lower_eigen[i]) << "row " << i;
      ASSERT_EQ(std::signbit(lower[i]), std::signbit(lower_eigen[i])) << "row " << i;
      ASSERT_EQ(upper[i], upper_eigen[i]) << "row " << i;
      ASSERT_EQ(std::signbit(upper[i]), std::signbit(upper_eigen[i])) << "row " << i;
    }
    const Eigen::MatrixXd dense(*m);
    Eigen::MatrixXd unit = dense.triangularView<Eigen::StrictlyLower>();
    unit.diagonal().setOnes();
    EXPECT_LT(relative(unit * lower, b), 1e-13);
    EXPECT_LT(relative(unit.transpose() * upper, b), 1e-13);
  }
}

// A Dirichlet row marked by FreeFEM's tgv (1e30 on the diagonal, its couplings kept): its unknown
// is b_i / 1e30 and the others solve the reduced system.
TEST(SparseSpd, TgvRowsBehaveAsDirichlet) {
  std::mt19937 rng(2);
  SparseMatrix a = grid_laplacian(6, 5, 0.0);
  const int pinned = 7;
  a.coeffRef(pinned, pinned) = 1e30;
  sma::SpdFactor f;
  f.factorize(a);
  Eigen::VectorXd b = random_vector(a.rows(), rng);
  b[pinned] = 0.0;
  std::vector<double> bs = to_std(b), x(a.rows());
  f.solve(bs, x);
  EXPECT_LT(std::fabs(x[pinned]), 1e-25);
  // The reduced system: row and column `pinned` removed.
  const int n = a.rows();
  Eigen::MatrixXd dense(a), reduced(n - 1, n - 1);
  Eigen::VectorXd rb(n - 1);
  for (int i = 0, ri = 0; i < n; ++i) {
    if (i == pinned) continue;
    rb[ri] = b[i];
    for (int j = 0, rj = 0; j < n; ++j)
      if (j != pinned) reduced(ri, rj++) = dense(i, j);
    ++ri;
  }
  const Eigen::VectorXd rx = reduced.llt().solve(rb);
  for (int i = 0, ri = 0; i < n; ++i) {
    if (i != pinned) {
      EXPECT_NEAR(x[i], rx[ri], 1e-12 * rx.lpNorm<Eigen::Infinity>());
      ++ri;
    }
  }
}

TEST(SparseSpd, RefactorisationWithNewValuesAndNewPattern) {
  std::mt19937 rng(3);
  sma::SpdFactor f;
  f.factorize(grid_laplacian(8, 8, 0.5));
  const SparseMatrix b = grid_laplacian(8, 8, 2.0);  // same pattern, new values
  f.factorize(b);
  Eigen::VectorXd rhs = random_vector(64, rng);
  std::vector<double> rs = to_std(rhs), x(64);
  f.solve(rs, x);
  EXPECT_LT(relative(Eigen::Map<Eigen::VectorXd>(x.data(), 64), Eigen::MatrixXd(b).llt().solve(rhs)), 1e-12);
  const SparseMatrix c = grid_laplacian(5, 7, 1.0);  // another size and pattern
  f.factorize(c);
  EXPECT_EQ(f.size(), 35);
  Eigen::VectorXd rc = random_vector(35, rng);
  std::vector<double> rcs = to_std(rc), xc(35);
  f.solve(rcs, xc);
  EXPECT_LT(relative(Eigen::Map<Eigen::VectorXd>(xc.data(), 35), Eigen::MatrixXd(c).llt().solve(rc)), 1e-12);
}

TEST(SparseSpd, RefusesWhatItCannotSolve) {
  sma::SpdFactor f;
  std::vector<double> b(4), x(4);
  EXPECT_THROW(f.solve(b, x), std::invalid_argument);  // nothing factorised
  SparseMatrix nonsymmetric = grid_laplacian(2, 2, 0.0);
  nonsymmetric.coeffRef(0, 1) = -2.0;
  try {
    f.factorize(nonsymmetric);
    FAIL() << "a non-symmetric matrix was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not symmetric"), std::string::npos) << e.what();
  }
  SparseMatrix indefinite = grid_laplacian(2, 2, 0.0);
  indefinite.coeffRef(3, 3) = -5.0;
  try {
    f.factorize(indefinite);
    FAIL() << "an indefinite matrix was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
  }
  SparseMatrix rectangular(3, 4);
  EXPECT_THROW(f.factorize(rectangular), std::invalid_argument);
  f.factorize(grid_laplacian(2, 2, 0.0));
  std::vector<double> short_b(3);
  EXPECT_THROW(f.solve(short_b, x), std::invalid_argument);
}

// W = H S A^-1 S H' against the dense product, with supported dofs (sparse forward solves: Y' D^-1 Y);
// normal_only keeps only the even rows and columns.
TEST(SparseSpd, DelassusEqualsDenseProduct) {
  std::mt19937 rng(4);
  const SparseMatrix a = grid_laplacian(10, 10, 0.1);
  const int n = a.rows(), k = 12;
  std::uniform_int_distribution<int> dof(0, n - 1);
  std::vector<Eigen::Triplet<double, int>> t;
  for (int r = 0; r < k; ++r)
    for (int e = 0; e < 2; ++e) t.emplace_back(r, dof(rng), std::normal_distribution<double>()(rng));
  SparseMatrix h(k, n);
  h.setFromTriplets(t.begin(), t.end());
  std::vector<double> free(n, 1.0);
  for (int i = 0; i < n; i += 7) free[i] = 0.0;
  sma::SpdFactor f;
  f.factorize(a);
  const Eigen::MatrixXd w = sma::delassus_factor(f, h, free, false).w;
  const Eigen::VectorXd s = Eigen::Map<Eigen::VectorXd>(free.data(), n);
  const Eigen::MatrixXd hs = Eigen::MatrixXd(h) * s.asDiagonal();
  const Eigen::MatrixXd exact = hs * Eigen::MatrixXd(a).llt().solve(hs.transpose());
  EXPECT_LT((w - exact).norm() / exact.norm(), 1e-12);
  EXPECT_LT((w - w.transpose()).norm() / w.norm(), 1e-12);  // symmetric
  const Eigen::MatrixXd wn = sma::delassus_factor(f, h, free, true).w;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      if (i % 2 == 0 && j % 2 == 0)
        EXPECT_NEAR(wn(i, j), exact(i, j), 1e-12 * exact.norm());
      else
        EXPECT_EQ(wn(i, j), 0.0);
    }
  EXPECT_THROW(sma::delassus_factor(f, SparseMatrix(k, n + 1), free, false), std::invalid_argument);
}

// The nested-dissection ordering (large matrices: SpdFactor::kNestedDissectionFrom) forced on a
// small one gives the AMD path's solution to 1e-12, its halves give its solve bit for bit, its
// Delassus operator is AMD's; its factor is a fill-reducing one (far below the natural order's
// band, about nx ny^2 for an nx x ny grid numbered along ny: 41k against 150k here).
TEST(SparseSpd, NestedDissectionSolvesAsAmd) {
  std::mt19937 rng(5);
  SparseMatrix a = grid_laplacian(60, 50, 0.01);
  a.coeffRef(17, 17) = 1e30;  // a Dirichlet row (tgv)
  const int n = a.rows();
  sma::SpdFactor amd, nd;
  nd.set_nested_dissection_from(0);
  amd.factorize(a);
  nd.factorize(a);
  EXPECT_FALSE(amd.nested_dissection());
  EXPECT_TRUE(nd.nested_dissection());
  EXPECT_LT(nd.factor_nonzeros(), 60L * 50 * 50 / 3);
  EXPECT_LT(nd.factor_nonzeros(), 2 * amd.factor_nonzeros());
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {  // new values on the same pattern: a numeric refactorisation
      a.coeffRef(3, 3) += 2.0;
      a.coeffRef(200, 200) += 5.0;
      amd.factorize(a);
      nd.factorize(a);
      ASSERT_TRUE(nd.nested_dissection());
    }
    const std::vector<double> b = to_std(random_vector(n, rng));
    std::vector<double> xa(n), xn(n), halves(n);
    amd.solve(b, xa);
    nd.solve(b, xn);
    const Eigen::Map<Eigen::VectorXd> va(xa.data(), n), vn(xn.data(), n);
    EXPECT_LT(relative(vn, va), 1e-12) << "pass " << pass;
    Eigen::VectorXd z;
    nd.forward_into(b, z);
    nd.backward_in_place(z, halves);
    for (int i = 0; i < n; ++i) ASSERT_EQ(halves[i], xn[i]) << "dof " << i;
    Eigen::MatrixXd block(n, 2);
    block.col(0) = va;
    block.col(1) = Eigen::Map<const Eigen::VectorXd>(b.data(), n);
    const Eigen::MatrixXd ya = amd.solve(block), yn = nd.solve(block);
    EXPECT_LT((yn - ya).norm() / ya.norm(), 1e-12);
  }
  // The Delassus operator through the nested dissection's sparse forward solves.
  const int m = 6, nodes[m] = {0, 301, 602, 1203, 1804, 2998};
  const SparseMatrix h = contact_rows(n, nodes, m);
  std::vector<double> free(n, 1.0);
  free[17] = 0.0;
  const Eigen::MatrixXd wa = sma::delassus_factor(amd, h, free, false).w, wn = sma::delassus_factor(nd, h, free, false).w;
  EXPECT_LT((wn - wa).norm() / wa.norm(), 1e-12);
  // The ordering is reproducible (a run gives the same bits every time): a second factor's solve
  // equals the first's bit for bit.
  sma::SpdFactor again;
  again.set_nested_dissection_from(0);
  again.factorize(a);
  const std::vector<double> b = to_std(random_vector(n, rng));
  std::vector<double> x1(n), x2(n);
  nd.solve(b, x1);
  again.solve(b, x2);
  EXPECT_EQ(x1, x2);
}

// The threshold: from kNestedDissectionFrom unknowns on, a factor orders by nested dissection.
TEST(SparseSpd, LargeMatricesTakeTheNestedDissection) {
  const int side = 224;  // 50 176 unknowns
  ASSERT_GE(side * side, sma::SpdFactor::kNestedDissectionFrom);
  sma::SpdFactor large, small;
  large.factorize(grid_laplacian(side, side, 0.01));
  small.factorize(grid_laplacian(side, 220, 0.01));  // 49 280
  ASSERT_LT(side * 220, sma::SpdFactor::kNestedDissectionFrom);
  EXPECT_TRUE(large.nested_dissection());
  EXPECT_FALSE(small.nested_dissection());
}

}  // namespace

namespace {

// One condensed contact global step (plugin/core/contact_step.hpp) on a grid "body" pressed onto
// an obstacle at 4 nodes: u solves K u = rhs + S H' r, and Signorini holds at every node
// (r_n >= 0, n.u + gap >= 0, r_n (n.u + gap) = 0 to the PSOR tolerance); frictionless nodes carry
// no tangential reaction.
TEST(ContactStep, SolvesTheCondensedProblem) {
  const SparseMatrix a = grid_laplacian(9, 9, 0.05);
  const int n = a.rows(), m = 4;
  const int nodes[m] = {3, 22, 40, 58};
  // normal component: the dof itself; "tangential": a neighbour dof
  const SparseMatrix h = unit_rows(n, nodes, m, {0, 1});
  sma::SpdFactor k;
  k.factorize(a);
  std::vector<double> free(n, 1.0);
  const sma::DelassusFactor c = sma::delassus_factor(k, h, free, true);
  // A load pulling every dof down by 1: the free solution penetrates the obstacle (gap 0.5) at
  // some nodes and not at others (gaps up to 100).
  std::vector<double> rhs(n, -1.0), gap = {0.5, 100.0, 0.5, 2.0}, threshold(m, 0.0), reference(m, 0.0),
      tangent_free(m, 1.0), u(n);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * m);
  sma::ContactStepSettings set;
  set.tol = 1e-13;
  const sma::PsorResult res = sma::condensed_global_step(k, c, rhs, gap, threshold, reference, tangent_free, set, r, u);
  ASSERT_TRUE(res.converged);
  const Eigen::Map<Eigen::VectorXd> uu(u.data(), n);
  const Eigen::VectorXd residual = a * uu - Eigen::Map<Eigen::VectorXd>(rhs.data(), n) - h.transpose() * r;
  EXPECT_LT(residual.norm() / Eigen::Map<Eigen::VectorXd>(rhs.data(), n).norm(), 1e-12);
  int active = 0;
  for (int i = 0; i < m; ++i) {
    const double normal_gap = uu[nodes[i]] + gap[i];
    EXPECT_GE(r[2 * i], 0.0);
    EXPECT_GE(normal_gap, -1e-9);
    EXPECT_LT(std::fabs(r[2 * i] * normal_gap), 1e-9 * (1 + r.lpNorm<Eigen::Infinity>()));
    EXPECT_EQ(r[2 * i + 1], 0.0);
    active += r[2 * i] > 0;
  }
  EXPECT_GT(active, 0);  // the obstacle pushed somewhere
  EXPECT_LT(active, m);  // and not everywhere: both statuses are exercised
  // Warm starts: from the answer itself (one back-solve: r does not move) and from half of it (the
  // correction K^-1 S H' (r - r0)): the same reactions and displacement.
  for (double scale : {1.0, 0.5}) {
    Eigen::VectorXd rw = scale * r;
    std::vector<double> uw(n);
    ASSERT_TRUE(sma::condensed_global_step(k, c, rhs, gap, threshold, reference, tangent_free, set, rw, uw).converged);
    EXPECT_LT((rw - r).norm(), 1e-10 * r.norm()) << "warm start x" << scale;
    EXPECT_LT((Eigen::Map<Eigen::VectorXd>(uw.data(), n) - uu).norm(), 1e-10 * uu.norm()) << "warm start x" << scale;
  }
}


// The step's one forward and one backward solve against its definition written out with full
// solves: u_free = K^-1 rhs, q from H u_free, PSOR on W, u = K^-1 (rhs + S H' r). With friction
// (all rows of H formed, sliding and sticking nodes) and supported dofs on the contact rows.
// The step solver's contact load and motion (add_contact_load_sparse, contact_motion_at) give
// add_contact_load's and contact_motion's bits: reactions zero on some rows (their columns
// skipped), signed zeros in z (kept or not as Eigen's z += Y r keeps them).
TEST(ContactStep, SparseLoadAndMotionHaveTheWholeBits) {
  SparseMatrix a = grid_laplacian(10, 8, 0.03);
  const int n = a.rows(), m = 5;
  const int nodes[m] = {2, 17, 33, 50, 66};
  const SparseMatrix h = contact_rows(n, nodes, m);
  std::vector<double> free(n, 1.0);
  sma::SpdFactor k;
  k.factorize(a);
  std::mt19937 rng(5);
  for (const bool normal_only : {false, true}) {
    const sma::DelassusFactor c = sma::delassus_factor(k, h, free, normal_only);
    Eigen::VectorXd z = random_vector(n, rng);
    for (int i = 0; i < n; i += 7) z[i] = -0.0;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * m);
    r[0] = 1.5, r[1] = -0.25, r[4] = 2.0, r[8] = -0.0;  // rows 2, 3, 6, ... carry nothing
    Eigen::VectorXd whole = z, sparse = z, work;
    sma::add_contact_load(c, r, whole);
    sma::add_contact_load_sparse(c, r, sparse, work);
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(sparse[i], whole[i]) << "dof " << i;
      ASSERT_EQ(std::signbit(sparse[i]), std::signbit(whole[i])) << "dof " << i;
    }
    std::vector<int> column(2 * m, -1);
    for (std::size_t j = 0; j < c.rows.size(); ++j) column[(std::size_t)c.rows[j]] = (int)j;
    const Eigen::VectorXd motion = sma::contact_motion(c, z);
    for (int row = 0; row < 2 * m; ++row) {
      const double at = sma::contact_motion_at(c, column[(std::size_t)row], z);
      ASSERT_EQ(at, motion[row]) << "row " << row;
      ASSERT_EQ(std::signbit(at), std::signbit(motion[row])) << "row " << row;
    }
  }
}

TEST(ContactStep, OneBackSolveEqualsTheTwoSolveDefinition) {
  SparseMatrix a = grid_laplacian(10, 8, 0.03);
  const int n = a.rows(), m = 5;
  const int nodes[m] = {2, 17, 33, 50, 66};
  const SparseMatrix h = contact_rows(n, nodes, m);
  std::vector<double> free(n, 1.0);
  free[nodes[0] + 1] = 0.0;  // a support under a contact row: S must mask it
  free[40] = 0.0;
  for (int i = 0; i < n; ++i)
    if (free[i] == 0.0) a.coeffRef(i, i) = 1e30;  // supports marked as FreeFEM does (tgv)
  sma::SpdFactor k;
  k.factorize(a);
  const sma::DelassusFactor c = sma::delassus_factor(k, h, free, false);
  std::mt19937 rng(9);
  Eigen::VectorXd rhs = random_vector(n, rng) - 2.0 * Eigen::VectorXd::Ones(n);
  const Eigen::VectorXd s = Eigen::Map<Eigen::VectorXd>(free.data(), n);
  rhs = rhs.cwiseProduct(s);
  std::vector<double> gap = {0.1, 0.3, 0.05, 500.0, 0.2}, threshold = {0.5, 0.01, 2.0, 0.5, 0.05},
                      reference(m, 0.0), tangent_free(m, 1.0), u(n);
  sma::ContactStepSettings set;
  set.tol = 1e-14;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * m);
  ASSERT_TRUE(sma::condensed_global_step(k, c, to_std(rhs), gap, threshold, reference, tangent_free, set, r, u)
                  .converged);
  // The definition, with dense solves.
  const Eigen::LLT<Eigen::MatrixXd> dense{Eigen::MatrixXd(a)};
  const Eigen::VectorXd ufree = dense.solve(rhs), hu = h * ufree;
  Eigen::VectorXd q(2 * m), g(m);
  for (int i = 0; i < m; ++i) {
    q[2 * i] = -(hu[2 * i] + gap[i]);
    q[2 * i + 1] = -(hu[2 * i + 1] - reference[i]);
    g[i] = threshold[i];
  }
  Eigen::VectorXd rexact = Eigen::VectorXd::Zero(2 * m);
  ASSERT_TRUE(sma::psor_condensed(c.w, q, g, set.omega, set.tol, set.maxit, rexact, set.polish).converged);
  const Eigen::VectorXd uexact = dense.solve(rhs + s.cwiseProduct(h.transpose() * rexact));
  EXPECT_LT((r - rexact).norm(), 1e-11 * rexact.norm());
  EXPECT_LT(relative(Eigen::Map<Eigen::VectorXd>(u.data(), n), uexact), 1e-12);
  int pushing = 0, sliding = 0, sticking = 0;
  for (int i = 0; i < m; ++i) {
    pushing += rexact[2 * i] > 0;
    if (rexact[2 * i] > 0) (std::fabs(std::fabs(rexact[2 * i + 1]) - g[i]) < 1e-12 ? sliding : sticking)++;
  }
  EXPECT_GT(pushing, 0);
  EXPECT_LT(pushing, m);  // a node off the obstacle too
  EXPECT_GT(sliding + sticking, 0);
}

}  // namespace

// Two deformable bodies in contact (add_obstacle_compliance): the first body's condensed step on
// W + C, C = H2 K2^-1 H2' the second body's compliance, its displacement recovered as
// u2 = -K2^-1 H2' r. Checked against the two-body problem's definition: each body in equilibrium
// (K1 u1 = rhs + H1' r, K2 u2 = -H2' r: action and reaction), and Signorini on the gap measured
// from the second body's deformed surface, H1 u1 - H2 u2 + gap >= 0, with complementarity.
TEST(ContactStep, SecondDeformableBodyAddsItsCompliance) {
  const SparseMatrix a1 = grid_laplacian(9, 9, 0.05), a2 = grid_laplacian(6, 7, 0.3);
  const int n1 = a1.rows(), n2 = a2.rows(), m = 4;
  const int nodes1[m] = {3, 22, 40, 58}, nodes2[m] = {5, 12, 20, 33};
  std::vector<Eigen::Triplet<double, int>> t1, t2;
  for (int i = 0; i < m; ++i) {
    t1.emplace_back(2 * i, nodes1[i], 1.0);
    t2.emplace_back(2 * i, nodes2[i], 1.0);
  }
  SparseMatrix h1(2 * m, n1), h2(2 * m, n2);
  h1.setFromTriplets(t1.begin(), t1.end());
  h2.setFromTriplets(t2.begin(), t2.end());
  sma::SpdFactor k1, k2;
  k1.factorize(a1);
  k2.factorize(a2);
  std::vector<double> free1(n1, 1.0), free2(n2, 1.0);
  sma::DelassusFactor c = sma::delassus_factor(k1, h1, free1, true);
  const Eigen::MatrixXd w1 = c.w, compliance = sma::delassus_factor(k2, h2, free2, true).w;
  sma::add_obstacle_compliance(c, compliance);
  EXPECT_LT((c.w - w1 - compliance).norm(), 1e-14 * w1.norm());
  std::vector<double> rhs(n1, -1.0), gap = {0.5, 100.0, 0.5, 2.0}, threshold(m, 0.0), reference(m, 0.0),
      tangent_free(m, 1.0), u1(n1);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * m);
  sma::ContactStepSettings set;
  set.tol = 1e-13;
  ASSERT_TRUE(sma::condensed_global_step(k1, c, rhs, gap, threshold, reference, tangent_free, set, r, u1).converged);
  const Eigen::VectorXd load2 = -(h2.transpose() * r);
  Eigen::VectorXd u2(n2);
  k2.solve(sma::span<const double>(load2.data(), (std::size_t)n2), sma::span<double>(u2.data(), (std::size_t)n2));
  const Eigen::Map<Eigen::VectorXd> uu1(u1.data(), n1);
  const Eigen::Map<Eigen::VectorXd> rhs1(rhs.data(), n1);
  EXPECT_LT((a1 * uu1 - rhs1 - h1.transpose() * r).norm() / rhs1.norm(), 1e-12);
  EXPECT_LT((a2 * u2 + h2.transpose() * r).norm() / r.norm(), 1e-12);
  const Eigen::VectorXd motion = h1 * uu1 - h2 * u2;
  int active = 0;
  for (int i = 0; i < m; ++i) {
    const double normal_gap = motion[2 * i] + gap[i];
    EXPECT_GE(r[2 * i], 0.0);
    EXPECT_GE(normal_gap, -1e-9);
    EXPECT_LT(std::fabs(r[2 * i] * normal_gap), 1e-9 * (1 + r.lpNorm<Eigen::Infinity>()));
    active += r[2 * i] > 0;
  }
  EXPECT_GT(active, 0);
  EXPECT_LT(active, m);
  // The same step on the rigid body's W gives larger reactions: the compliant pipe yields.
  Eigen::VectorXd rigid = Eigen::VectorXd::Zero(2 * m);
  const sma::DelassusFactor c1 = sma::delassus_factor(k1, h1, free1, true);
  ASSERT_TRUE(sma::condensed_global_step(k1, c1, rhs, gap, threshold, reference, tangent_free, set, rigid, u1).converged);
  EXPECT_GT(rigid.sum(), r.sum() * (1 + 1e-6));
  // Refused: a wrong size, an asymmetric or negative compliance, one on a left-out tangential row.
  sma::DelassusFactor bad = sma::delassus_factor(k1, h1, free1, true);
  EXPECT_THROW(sma::add_obstacle_compliance(bad, Eigen::MatrixXd::Zero(2 * m + 1, 2 * m + 1)), std::invalid_argument);
  Eigen::MatrixXd asym = compliance;
  asym(0, 2) += 1.0;
  EXPECT_THROW(sma::add_obstacle_compliance(bad, asym), std::invalid_argument);
  Eigen::MatrixXd negative = -compliance;
  EXPECT_THROW(sma::add_obstacle_compliance(bad, negative), std::invalid_argument);
  Eigen::MatrixXd tangential = Eigen::MatrixXd::Zero(2 * m, 2 * m);
  tangential(1, 1) = 1.0;
  EXPECT_THROW(sma::add_obstacle_compliance(bad, tangential), std::invalid_argument);
  EXPECT_EQ((bad.w - w1).norm(), 0.0);  // a refused compliance leaves W as it was
}

// The 3D contact step (condensed_cone_step): three rows per node (the node's dof pushed by the
// obstacle, two neighbour dofs as the tangents), a load pressing every node onto the obstacle and
// dragging the tangents: equilibrium K u = rhs + H' r, and every law on the motions H u (gap,
// complementarity, the disk, stick and slip) with nodes sticking and sliding. With the second
// tangent's dof held (free = 0: its Delassus row and column 0) the step is condensed_global_step's
// on the first two rows, to round-off.
TEST(ContactStep, ConeStepSatisfiesTheLaws) {
  const SparseMatrix a = grid_laplacian(9, 9, 0.05);
  const int n = a.rows(), m = 4;
  const int nodes[m] = {12, 22, 40, 58};
  const SparseMatrix h = unit_rows(n, nodes, m, {0, 1, 9});
  sma::SpdFactor k;
  k.factorize(a);
  std::vector<double> free(n, 1.0);
  const sma::DelassusFactor c = sma::delassus_factor(k, h, free, false);
  std::vector<double> rhs(n, -1.0), gap = {0.5, 0.3, 0.5, 2.0}, threshold = {20.0, 0.4, 0.05, 10.0}, reference(2 * m, 0.0),
      u(n);
  for (int i = 0; i < m; ++i) rhs[nodes[i] + 1] += 3.0, rhs[nodes[i] + 9] -= 2.0;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(3 * m);
  sma::ContactStepSettings set;
  set.tol = 1e-14;
  set.omega = 1.2;
  const sma::PsorResult res = sma::condensed_cone_step(k, c, rhs, gap, threshold, reference, set, r, u);
  ASSERT_TRUE(res.converged);
  const Eigen::Map<Eigen::VectorXd> uu(u.data(), n);
  const Eigen::Map<Eigen::VectorXd> b(rhs.data(), n);
  EXPECT_LT((a * uu - b - h.transpose() * r).norm() / b.norm(), 1e-12);
  const Eigen::VectorXd hu = h * uu;
  int sticking = 0, sliding = 0;
  const double scale = 1 + r.lpNorm<Eigen::Infinity>();
  for (int i = 0; i < m; ++i) {
    const double normal_gap = hu[3 * i] + gap[i];
    EXPECT_GE(r[3 * i], 0.0);
    EXPECT_GE(normal_gap, -1e-9);
    EXPECT_LT(std::fabs(r[3 * i] * normal_gap), 1e-9 * scale);
    const Eigen::Vector2d rt(r[3 * i + 1], r[3 * i + 2]), slip(hu[3 * i + 1], hu[3 * i + 2]);
    EXPECT_LE(rt.norm(), threshold[i] * (1 + 1e-12));
    if (rt.norm() < threshold[i] * (1 - 1e-9)) {
      EXPECT_LT(slip.norm(), 1e-9 * scale) << "node " << i << " sticks but slips";
      ++sticking;
    } else {  // the reaction opposes the slip: slip = -k r_t, k > 0
      EXPECT_GT(slip.norm(), 1e-9);
      EXPECT_LT(std::fabs(slip[0] * rt[1] - slip[1] * rt[0]), 1e-9 * scale * slip.norm());
      EXPECT_LT(slip.dot(rt), 0.0);
      ++sliding;
    }
  }
  EXPECT_GT(sticking, 0);
  EXPECT_GT(sliding, 0);

  // the second tangent's dofs held: the 2D step on (n, t1)
  std::vector<double> held(n, 1.0);
  for (int i = 0; i < m; ++i) held[nodes[i] + 9] = 0.0;
  SparseMatrix a_held = a;
  for (int i = 0; i < m; ++i) a_held.coeffRef(nodes[i] + 9, nodes[i] + 9) = 1e30;
  sma::SpdFactor k_held;
  k_held.factorize(a_held);
  const sma::DelassusFactor c3 = sma::delassus_factor(k_held, h, held, false);
  const SparseMatrix h2 = unit_rows(n, nodes, m, {0, 1});
  const sma::DelassusFactor c2 = sma::delassus_factor(k_held, h2, held, false);
  std::vector<double> u3(n), u2(n), reference2(m, 0.0), tangent_free(m, 1.0);
  Eigen::VectorXd r3 = Eigen::VectorXd::Zero(3 * m), r2 = Eigen::VectorXd::Zero(2 * m);
  ASSERT_TRUE(sma::condensed_cone_step(k_held, c3, rhs, gap, threshold, reference, set, r3, u3).converged);
  sma::ContactStepSettings set2 = set;
  set2.polish = 0;
  ASSERT_TRUE(sma::condensed_global_step(k_held, c2, rhs, gap, threshold, reference2, tangent_free, set2, r2, u2).converged);
  for (int i = 0; i < m; ++i) {
    EXPECT_NEAR(r3[3 * i], r2[2 * i], 1e-10 * scale);
    EXPECT_NEAR(r3[3 * i + 1], r2[2 * i + 1], 1e-10 * scale);
    EXPECT_EQ(r3[3 * i + 2], 0.0);
  }
  EXPECT_LT((Eigen::Map<Eigen::VectorXd>(u3.data(), n) - Eigen::Map<Eigen::VectorXd>(u2.data(), n)).norm(),
            1e-10 * Eigen::Map<Eigen::VectorXd>(u2.data(), n).norm());
}
