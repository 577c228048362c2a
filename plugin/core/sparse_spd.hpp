// A sparse symmetric positive definite matrix factorised once and solved many times, and the
// Delassus operator of a contact problem built from that factorisation.
//
// Why in the plugin: FreeFEM's K^-1 (UMFPACK, a general LU with iterative refinement) cost
// 126 us per back-solve of the default sleeve's 722 dofs and 518 us at 3458 dofs here; the
// stiffness and the heat matrices are symmetric positive definite, and a sparse LDL' with a
// fill-reducing ordering (Eigen's SimplicialLDLT, AMD) solves them in a fraction of that
// (docs/benchmarks.md, "Back-solves"). The Delassus operator W = H K^-1 H' is formed by blocks of
// right-hand sides, so that no dense n x m matrix K^-1 H' is ever held: memory n x block + m x m.
//
// Dirichlet rows marked by a huge diagonal (FreeFEM's tgv) stay in the matrix: an LDL' pivot of
// 1e30 makes their unknowns b_i / 1e30, as FreeFEM's own solvers do.
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/Sparse>
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "span.hpp"

namespace sma {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// The matrix of n x n given by triplets (rows[k], cols[k], values[k]); entries repeated add up.
inline SparseMatrix sparse_from_triplets(int n_rows, int n_cols, span<const int> rows,
                                         span<const int> cols, span<const double> values) {
  if (rows.size() != cols.size() || rows.size() != values.size())
    throw std::invalid_argument("triplets of unequal lengths");
  std::vector<Eigen::Triplet<double, int>> t;
  t.reserve(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows[k] < 0 || rows[k] >= n_rows || cols[k] < 0 || cols[k] >= n_cols)
      throw std::invalid_argument("entry (" + std::to_string(rows[k]) + ", " + std::to_string(cols[k]) +
                                  ") outside the " + std::to_string(n_rows) + " x " +
                                  std::to_string(n_cols) + " matrix");
    t.emplace_back(rows[k], cols[k], values[k]);
  }
  SparseMatrix a(n_rows, n_cols);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

// Largest |a_ij - a_ji| over the largest off-diagonal |a_ij| (0 for a diagonal matrix): FreeFEM
// assembles both halves of a symmetric form, equal to round-off.
inline double asymmetry(const SparseMatrix& a) {
  const SparseMatrix at = a.transpose();
  const SparseMatrix d = a - at;
  double worst = 0.0, largest = 0.0;
  for (int j = 0; j < a.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(a, j); it; ++it)
      if (it.row() != it.col()) largest = std::max(largest, std::fabs(it.value()));
  for (int j = 0; j < d.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(d, j); it; ++it) worst = std::max(worst, std::fabs(it.value()));
  return largest > 0 ? worst / largest : worst;
}

class SpdFactor {
 public:
  // Factorises a (symmetric positive definite, n x n). The symbolic analysis (ordering, pattern
  // of L) is kept while the pattern stays the same: a refactorisation with new values (the heat
  // matrix when the exchange changes) is numeric only. Throws, naming the fault, when a is not
  // square, not symmetric (relative asymmetry > 1e-12) or not positive definite.
  void factorize(const SparseMatrix& a) {
    if (a.rows() != a.cols())
      throw std::invalid_argument("the matrix is " + std::to_string(a.rows()) + " x " +
                                  std::to_string(a.cols()) + ", not square");
    const double asym = asymmetry(a);
    if (!(asym <= 1e-12))
      throw std::invalid_argument("the matrix is not symmetric (largest |a_ij - a_ji| is " +
                                  std::to_string(asym) + " of the largest off-diagonal entry)");
    const bool same_pattern = analysed_ && a.rows() == pattern_.rows() && a.nonZeros() == pattern_.nonZeros() &&
                              std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1,
                                         pattern_.outerIndexPtr()) &&
                              std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(),
                                         pattern_.innerIndexPtr());
    if (!same_pattern) {
      ldlt_.analyzePattern(a);
      pattern_ = a;
      analysed_ = true;
    }
    ldlt_.factorize(a);
    if (ldlt_.info() != Eigen::Success)
      throw std::invalid_argument("the LDL' factorisation failed (a zero pivot: singular matrix)");
    const double dmin = ldlt_.vectorD().minCoeff();
    if (!(dmin > 0))
      throw std::invalid_argument("the matrix is not positive definite (a pivot of " + std::to_string(dmin) +
                                  "): a support missing, or a negative coefficient");
    n_ = (int)a.rows();
  }
  int size() const { return n_; }
  // x = A^-1 b (x and b may not alias).
  void solve(span<const double> b, span<double> x) const {
    check_size(b.size(), "right-hand side");
    check_size(x.size(), "solution");
    Eigen::Map<const Eigen::VectorXd> bb(b.begin(), n_);
    Eigen::Map<Eigen::VectorXd> xx(x.begin(), n_);
    xx = ldlt_.solve(bb);
  }
  // X = A^-1 B for a block of right-hand sides.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const {
    check_size((std::size_t)b.rows(), "right-hand side block");
    return ldlt_.solve(b);
  }
  // Nonzeros of the factor L (memory: about 12 bytes each).
  long factor_nonzeros() const { return n_ ? (long)ldlt_.matrixL().nestedExpression().nonZeros() : 0; }

 private:
  void check_size(std::size_t got, const char* what) const {
    if (n_ == 0) throw std::invalid_argument("no matrix factorised");
    if ((long)got != n_)
      throw std::invalid_argument(std::string(what) + " of " + std::to_string(got) + " values for a " +
                                  std::to_string(n_) + " x " + std::to_string(n_) + " matrix");
  }
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
  SparseMatrix pattern_;
  bool analysed_ = false;
  int n_ = 0;
};

// The Delassus operator W = H S A^-1 S H' (k x k) of the contact rows H (k x n), S = diag(free)
// zeroing the supported (Dirichlet) dofs. normal_only: only the even rows of H (the normal
// components of interleaved (n, t) pairs) are formed; the odd rows and columns of W are 0.
// Right-hand sides go by blocks of `block` columns: memory n x block, never n x k.
inline Eigen::MatrixXd delassus(const SpdFactor& a, const SparseMatrix& h, span<const double> free,
                                bool normal_only, int block = 64) {
  const int n = a.size(), k = (int)h.rows();
  if (h.cols() != n)
    throw std::invalid_argument("H has " + std::to_string(h.cols()) + " columns for a " + std::to_string(n) +
                                " x " + std::to_string(n) + " matrix");
  if ((long)free.size() != n)
    throw std::invalid_argument("free has " + std::to_string(free.size()) + " values for " + std::to_string(n) +
                                " dofs");
  if (normal_only && k % 2 != 0) throw std::invalid_argument("normal_only needs (n, t) pairs of rows");
  Eigen::Map<const Eigen::VectorXd> mask(free.begin(), n);
  const SparseMatrix ht = h.transpose();  // column r of ht: row r of H
  std::vector<int> wanted;
  for (int r = 0; r < k; r += normal_only ? 2 : 1) wanted.push_back(r);
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(k, k);
  for (std::size_t first = 0; first < wanted.size(); first += block) {
    const int cols = (int)std::min<std::size_t>(block, wanted.size() - first);
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, cols);
    for (int c = 0; c < cols; ++c)
      for (SparseMatrix::InnerIterator it(ht, wanted[first + c]); it; ++it) rhs(it.row(), c) = it.value();
    rhs = mask.asDiagonal() * rhs;
    Eigen::MatrixXd x = a.solve(rhs);
    x = mask.asDiagonal() * x;
    const Eigen::MatrixXd hx = h * x;  // k x cols
    for (int c = 0; c < cols; ++c) w.col(wanted[first + c]) = hx.col(c);
  }
  if (normal_only)
    for (int r = 1; r < k; r += 2) w.row(r).setZero();
  return w;
}

}  // namespace sma
