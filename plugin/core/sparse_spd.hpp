// A sparse symmetric positive definite matrix factorised once and solved many times, and the
// Delassus operator of a contact problem built from that factorisation.
//
// Why in the plugin: FreeFEM's K^-1 (UMFPACK, a general LU with iterative refinement) is about
// four times slower per back-solve than a sparse LDL' with a fill-reducing ordering (Eigen's
// SimplicialLDLT, AMD) on the stiffness and heat matrices, which are symmetric positive definite
// (docs/parameters.md, "back-solves"; docs/benchmarks.md, "One DC iteration against one
// back-solve"). The Delassus operator W = H K^-1 H' is formed from sparse
// forward solves (delassus_factor()), so that no dense n x m matrix K^-1 H' is ever held.
//
// Dirichlet rows marked by a huge diagonal (FreeFEM's tgv) stay in the matrix: an LDL' pivot of
// 1e30 makes their unknowns b_i / 1e30, as FreeFEM's own solvers do.
//
// The fill-reducing ordering: AMD below SpdFactor::kNestedDissectionFrom unknowns, from there the
// nested dissection of CHOLMOD (NESDIS: METIS's graph partitioner, constrained minimum degree on
// the leaves), which on the sleeve's meshes from 59k unknowns leaves 12-14 % fewer nonzeros in L,
// the work of each solve (docs/parameters.md, "back-solve ordering": the scene's stiffness and
// heat matrices, tools/bench/backsolve.cpp). The factorisation and the solves are Eigen's in both
// cases (the same LDL', the same halves for the contact step); only the permutation differs.
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/Sparse>
#include <Eigen/Dense>
#include <cholmod.h>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "span.hpp"

namespace sma {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// z = L^-1 z for the unit lower triangular L stored strictly below its diagonal (column-major),
// as Eigen's sparse triangular solve forms it (SparseCore/TriangularSolver.h, column-major
// lower: column by column from the first, a zero entry's column skipped, each entry below the
// diagonal z_r -= z_i l_ri in the column's order), through raw pointers (Eigen's loop reads the
// vector through coeffRef(row, col) and its iterator's bounds at every entry): the same
// operations in the same order, the same bits.
inline void unit_lower_solve_in_place(const SparseMatrix& l, double* z) {
  const int n = (int)l.cols();
  const int* const outer = l.outerIndexPtr();
  const int* const counts = l.innerNonZeroPtr();  // null when compressed
  const int* const inner = l.innerIndexPtr();
  const double* const value = l.valuePtr();
  for (int i = 0; i < n; ++i) {
    const double t = z[i];
    if (t == 0.0) continue;
    int e = outer[i];
    const int end = counts ? e + counts[i] : outer[i + 1];
    while (e < end && inner[e] < i) ++e;
    if (e < end && inner[e] == i) ++e;
    #pragma GCC unroll 8
    for (; e < end; ++e) z[inner[e]] -= t * value[e];
  }
}
// z = L'^-1 z (the unit upper triangular L', row i of which is column i of L), as Eigen's
// row-major upper solve forms it: rows from the last, t = z_i - sum l_ri z_r in the column's
// order, then z_i = t.
inline void unit_upper_solve_in_place(const SparseMatrix& l, double* z) {
  const int n = (int)l.cols();
  const int* const outer = l.outerIndexPtr();
  const int* const counts = l.innerNonZeroPtr();
  const int* const inner = l.innerIndexPtr();
  const double* const value = l.valuePtr();
  for (int i = n - 1; i >= 0; --i) {
    double t = z[i];
    int e = outer[i];
    const int end = counts ? e + counts[i] : outer[i + 1];
    while (e < end && inner[e] < i) ++e;
    if (e < end && inner[e] == i) ++e;
    #pragma GCC unroll 8
    for (; e < end; ++e) t -= value[e] * z[inner[e]];
    z[i] = t;
  }
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

// The nested-dissection permutation of a's pattern (a symmetric, both triangles stored) by CHOLMOD:
// perm[k] is the row of a that becomes row k (CHOLMOD's Perm, Eigen's P^-1 indices). Throws,
// naming CHOLMOD's status, when the ordering fails (out of memory).
inline Eigen::VectorXi nested_dissection_order(const SparseMatrix& a) {
  const int n = (int)a.rows();
  // The lower triangle's pattern, as CHOLMOD's symmetric (stype -1) input.
  std::vector<int> colp((std::size_t)n + 1, 0), rows;
  rows.reserve((std::size_t)a.nonZeros() / 2 + (std::size_t)n);
  for (int j = 0; j < n; ++j) {
    for (SparseMatrix::InnerIterator it(a, j); it; ++it)
      if (it.row() >= j) rows.push_back((int)it.row());
    colp[(std::size_t)j + 1] = (int)rows.size();
  }
  cholmod_common c;
  cholmod_start(&c);
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_NESDIS;
  c.supernodal = CHOLMOD_SIMPLICIAL;
  c.print = 0;
  cholmod_sparse pattern{};
  pattern.nrow = pattern.ncol = (std::size_t)n;
  pattern.nzmax = rows.size();
  pattern.p = colp.data();
  pattern.i = rows.data();
  pattern.stype = -1;
  pattern.itype = CHOLMOD_INT;
  pattern.xtype = CHOLMOD_PATTERN;
  pattern.dtype = CHOLMOD_DOUBLE;
  pattern.sorted = 1;
  pattern.packed = 1;
  cholmod_factor* l = cholmod_analyze(&pattern, &c);
  const int status = c.status;
  Eigen::VectorXi perm;
  if (l && status == CHOLMOD_OK) perm = Eigen::Map<const Eigen::VectorXi>((const int*)l->Perm, n);
  cholmod_free_factor(&l, &c);
  cholmod_finish(&c);
  if (perm.size() != n)
    throw std::runtime_error("the nested-dissection ordering (CHOLMOD) failed: status " + std::to_string(status));
  return perm;
}

// What the step solver asks of a solver of A x = b (plugin/core/step_newton.hpp): the solve in two
// halves, x = backward(forward(b)), between which the condensed contact reads the contact rows'
// motion and adds the reactions' load (contact_step.hpp). SpdFactor's halves are those of its LDL';
// ExternalSolver's are a copy and a solve the caller provides (a distributed solve on MPI ranks).
class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual int size() const = 0;
  // z = the forward half of b (z resized; no allocation once it has the size)
  virtual void forward_into(span<const double> b, Eigen::VectorXd& z) const = 0;
  // x = the backward half of z (z may be overwritten)
  virtual void backward_in_place(Eigen::VectorXd& z, span<double> x) const = 0;
  // x = A^-1 b, the two halves in turn
  void solve(span<const double> b, span<double> x) const {
    Eigen::VectorXd z;
    forward_into(b, z);
    backward_in_place(z, x);
  }
};

class SpdFactor : public LinearSolver {
 public:
  // Unknowns from which the nested-dissection ordering replaces AMD (docs/parameters.md,
  // "back-solve ordering"): on the scene's matrices the two fill L alike at 26k-53k unknowns, the
  // nested dissection 12-14 % less from 59k and 15 % more at 3.5k; the default meshes (at most
  // 11k unknowns) keep AMD, their outputs bit for bit.
  static constexpr int kNestedDissectionFrom = 50000;
  // The threshold for this factor (a test sets 0 to exercise the nested dissection on a small matrix).
  void set_nested_dissection_from(int n) { nested_from_ = n; }
  bool nested_dissection() const { return nested_; }
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
      n_ = 0;
      analysed_ = false;
      nested_ = a.rows() >= nested_from_;
      if (nested_) {
        // P A P' with CHOLMOD's nested-dissection P, factorised in Eigen's natural order.
        const Eigen::VectorXi order = nested_dissection_order(a);
        nd_p_.resize((int)a.rows());
        nd_pinv_.resize((int)a.rows());
        for (int k = 0; k < (int)a.rows(); ++k) {
          nd_pinv_.indices()[k] = order[k];
          nd_p_.indices()[order[k]] = k;
        }
        nd_.analyzePattern(permuted(a));
      } else {
        ldlt_.analyzePattern(a);
      }
      pattern_ = a;
      analysed_ = true;
    }
    if (nested_) nd_.factorize(permuted(a));
    else ldlt_.factorize(a);
    if ((nested_ ? nd_.info() : ldlt_.info()) != Eigen::Success)
      throw std::invalid_argument("the LDL' factorisation failed (a zero pivot: singular matrix)");
    const Eigen::VectorXd d = nested_ ? nd_.vectorD() : ldlt_.vectorD();
    const double dmin = d.minCoeff();
    if (!(dmin > 0))
      throw std::invalid_argument("the matrix is not positive definite (a pivot of " + std::to_string(dmin) +
                                  "): a support missing, or a negative coefficient");
    n_ = (int)a.rows();
    inverse_diagonal_ = d.cwiseInverse();  // 1 / d_i, the values D^-1 z multiplies by
  }
  int size() const override { return n_; }
  // x = A^-1 b (x and b may not alias).
  void solve(span<const double> b, span<double> x) const {
    check_size(b.size(), "right-hand side");
    check_size(x.size(), "solution");
    Eigen::Map<const Eigen::VectorXd> bb(b.begin(), n_);
    Eigen::Map<Eigen::VectorXd> xx(x.begin(), n_);
    if (nested_) xx = nd_pinv_ * nd_.solve(nd_p_ * bb);
    else xx = ldlt_.solve(bb);
  }
  // The two halves of solve(), for a caller that works between them (the condensed contact step
  // reads the contact rows' motion off z and adds the reactions' load to it): z = L^-1 P b, then
  // x = P' L^-T D^-1 z. backward(forward(b)) is solve(b), operation for operation.
  Eigen::VectorXd forward(span<const double> b) const {
    Eigen::VectorXd z;
    forward_into(b, z);
    return z;
  }
  void backward(const Eigen::VectorXd& z, span<double> x) const {
    Eigen::VectorXd t = z;
    backward_in_place(t, x);
  }
  // The same on the caller's work vector z, for a caller that solves many times (the step
  // solver): no allocation once z has the size, the permutations by index (Eigen's permutation
  // products' values); z is overwritten by backward_in_place.
  void forward_into(span<const double> b, Eigen::VectorXd& z) const override {
    check_size(b.size(), "right-hand side");
    z.resize(n_);
    const auto& perm = permutation_p();
    double* const zz = z.data();
    const double* const bb = b.begin();
    if (perm.size()) {
      const int* const p = perm.data();
      for (int i = 0; i < n_; ++i) zz[p[i]] = bb[i];  // z = P b
    } else {
      for (int i = 0; i < n_; ++i) zz[i] = bb[i];
    }
    unit_lower_solve_in_place(factor_l(), zz);
  }
  void backward_in_place(Eigen::VectorXd& z, span<double> x) const override {
    check_size((std::size_t)z.size(), "forward-solved vector");
    check_size(x.size(), "solution");
    // D^-1 z as Eigen's inverse diagonal product forms it, (1 / d_i) z_i (vectorD() is a copy).
    double* const zz = z.data();
    const double* const inverse = inverse_diagonal_.data();
    for (int i = 0; i < n_; ++i) zz[i] = inverse[i] * zz[i];
    unit_upper_solve_in_place(factor_l(), zz);
    const auto& perm = nested_ ? nd_pinv_.indices() : ldlt_.permutationPinv().indices();
    double* const xx = x.begin();
    if (perm.size()) {
      const int* const p = perm.data();
      for (int i = 0; i < n_; ++i) xx[p[i]] = zz[i];  // x = P' z
    } else {
      for (int i = 0; i < n_; ++i) xx[i] = zz[i];
    }
  }
  // X = A^-1 B for a block of right-hand sides.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const {
    check_size((std::size_t)b.rows(), "right-hand side block");
    if (nested_) return nd_pinv_ * nd_.solve(nd_p_ * b);
    return ldlt_.solve(b);
  }
  // Y = L^-1 P B for a sparse B (n x c), P A P' = L D L': each column by a sparse forward solve
  // that visits only the columns of L reachable from the column's nonzeros (their paths up the
  // elimination tree; L stores each column's rows in increasing order, its first one the parent).
  // For right-hand sides with a few nonzeros (contact rows) this is far less than a full solve.
  SparseMatrix forward_solve_sparse(const SparseMatrix& b) const {
    check_size((std::size_t)b.rows(), "right-hand side block");
    const SparseMatrix& l = factor_l();
    const auto& perm = permutation_p();
    const int n = n_;
    std::vector<int> parent(n, -1);
    for (int j = 0; j < n; ++j)
      if (l.outerIndexPtr()[j + 1] > l.outerIndexPtr()[j]) parent[j] = l.innerIndexPtr()[l.outerIndexPtr()[j]];
    std::vector<double> x(n, 0.0);
    std::vector<char> marked(n, 0);
    std::vector<int> reach;
    std::vector<Eigen::Triplet<double, int>> y;
    for (int c = 0; c < b.cols(); ++c) {
      reach.clear();
      for (SparseMatrix::InnerIterator it(b, c); it; ++it) {
        const int row = perm.size() ? perm[it.row()] : (int)it.row();
        x[row] += it.value();
        for (int j = row; j >= 0 && !marked[j]; j = parent[j]) {
          marked[j] = 1;
          reach.push_back(j);
        }
      }
      std::sort(reach.begin(), reach.end());  // parent[j] > j: increasing order is topological
      for (int j : reach) {
        const double xj = x[j];
        if (xj == 0.0) continue;
        for (SparseMatrix::InnerIterator it(l, j); it; ++it) x[it.row()] -= it.value() * xj;
      }
      for (int j : reach) {
        if (x[j] != 0.0) y.emplace_back(j, c, x[j]);
        x[j] = 0.0;
        marked[j] = 0;
      }
    }
    SparseMatrix result(n, b.cols());
    result.setFromTriplets(y.begin(), y.end());
    return result;
  }
  // D of P A P' = L D L'.
  Eigen::VectorXd diagonal() const { return nested_ ? nd_.vectorD() : ldlt_.vectorD(); }
  // Nonzeros of the factor L (memory: about 12 bytes each).
  long factor_nonzeros() const { return n_ ? (long)factor_l().nonZeros() : 0; }

 private:
  void check_size(std::size_t got, const char* what) const {
    if (n_ == 0) throw std::invalid_argument("no matrix factorised");
    if ((long)got != n_)
      throw std::invalid_argument(std::string(what) + " of " + std::to_string(got) + " values for a " +
                                  std::to_string(n_) + " x " + std::to_string(n_) + " matrix");
  }
  // L (strictly lower) and P's indices of the factorisation in use.
  const SparseMatrix& factor_l() const {
    return nested_ ? nd_.matrixL().nestedExpression() : ldlt_.matrixL().nestedExpression();
  }
  const Eigen::VectorXi& permutation_p() const { return nested_ ? nd_p_.indices() : ldlt_.permutationP().indices(); }
  // P A P' (both triangles) for the nested-dissection factor.
  SparseMatrix permuted(const SparseMatrix& a) const {
    SparseMatrix pap(a.rows(), a.cols());
    pap.selfadjointView<Eigen::Lower>() = a.selfadjointView<Eigen::Lower>().twistedBy(nd_p_);
    return pap;
  }
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>> nd_;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> nd_p_, nd_pinv_;
  int nested_from_ = kNestedDissectionFrom;
  bool nested_ = false;
  SparseMatrix pattern_;
  Eigen::VectorXd inverse_diagonal_;
  bool analysed_ = false;
  int n_ = 0;
};

// The Delassus operator W = H S A^-1 S H' (k x k) of the contact rows H (k x n), S = diag(free)
// zeroing the supported (Dirichlet) dofs, with its factor: with P A P' = L D L' and
// Y = L^-1 P S H_rows' (sparse forward solves: SpdFactor::forward_solve_sparse), W = Y' D^-1 Y: no
// backward solve, no dense n x k matrix; memory is that of the sparse Y. normal_only: only the even
// rows of H (the normal components of interleaved (n, t) pairs) are formed; the odd rows and
// columns of W are 0. Y and D^-1 Y are kept for the contact step (contact_step.hpp), which gets
// H S A^-1 b = (D^-1 Y)' L^-1 P b and A^-1 (b + S H' r) from one forward and one backward solve.
struct DelassusFactor {
  Eigen::MatrixXd w;       // k x k
  SparseMatrix y;          // n x rows.size(): L^-1 P S H_rows'
  SparseMatrix y_scaled;   // D^-1 Y
  std::vector<int> rows;   // the rows of H that the columns of Y stand for
  // Where the caller keeps the columns C of an ExternalSolver's problem
  // (delassus_from_caller_columns: the distributed run's, each rank a slice of their rows),
  // y_scaled is empty and motion(z, out) gives out = C' z (rows.size() values), bound by the caller
  // for the duration of a call (plugin/glue/step.cpp StepSolveFractionBy) and empty otherwise.
  using Motion = std::function<void(const Eigen::VectorXd& z, span<double> motion)>;
  bool caller_columns = false;
  Motion motion;
};

inline DelassusFactor delassus_factor(const SpdFactor& a, const SparseMatrix& h, span<const double> free,
                                      bool normal_only) {
  const int n = a.size(), k = (int)h.rows();
  if (h.cols() != n)
    throw std::invalid_argument("H has " + std::to_string(h.cols()) + " columns for a " + std::to_string(n) +
                                " x " + std::to_string(n) + " matrix");
  if ((long)free.size() != n)
    throw std::invalid_argument("free has " + std::to_string(free.size()) + " values for " + std::to_string(n) +
                                " dofs");
  if (normal_only && k % 2 != 0) throw std::invalid_argument("normal_only needs (n, t) pairs of rows");
  Eigen::Map<const Eigen::VectorXd> mask(free.begin(), n);
  DelassusFactor result;
  std::vector<int>& wanted = result.rows;
  for (int r = 0; r < k; r += normal_only ? 2 : 1) wanted.push_back(r);
  // The wanted rows of H, masked, as the columns of B = S H_wanted'.
  const SparseMatrix ht = h.transpose();
  std::vector<Eigen::Triplet<double, int>> t;
  for (std::size_t c = 0; c < wanted.size(); ++c)
    for (SparseMatrix::InnerIterator it(ht, wanted[c]); it; ++it)
      if (mask[it.row()] != 0.0) t.emplace_back((int)it.row(), (int)c, it.value() * mask[it.row()]);
  SparseMatrix b(n, (int)wanted.size());
  b.setFromTriplets(t.begin(), t.end());
  result.y = a.forward_solve_sparse(b);
  const Eigen::VectorXd dinv = a.diagonal().cwiseInverse();
  result.y_scaled = dinv.asDiagonal() * result.y;
  const Eigen::MatrixXd compact = Eigen::MatrixXd(SparseMatrix(result.y.transpose() * result.y_scaled));
  result.w = Eigen::MatrixXd::Zero(k, k);
  for (std::size_t i = 0; i < wanted.size(); ++i)
    for (std::size_t j = 0; j < wanted.size(); ++j) result.w(wanted[i], wanted[j]) = compact(i, j);
  return result;
}

// A solver of A x = b that the caller provides (the distributed solves of FreeFEM's ffddm on MPI
// ranks, edp/solvers/distributed.idp): its forward half is the identity (z = b), its backward half
// the caller's solve x = A^-1 z. Its contact problem is delassus_from_caller_columns's. The solve is bound
// for the duration of a call (plugin/glue/step.cpp StepSolveFractionBy) and is empty otherwise.
class ExternalSolver : public LinearSolver {
 public:
  using Solve = std::function<void(const Eigen::VectorXd& b, span<double> x)>;
  explicit ExternalSolver(int n, Solve solve = nullptr) : n_(n), solve_(std::move(solve)) {
    if (n < 0) throw std::invalid_argument("an external solver of " + std::to_string(n) + " unknowns");
  }
  void bind(Solve solve) { solve_ = std::move(solve); }
  int size() const override { return n_; }
  void forward_into(span<const double> b, Eigen::VectorXd& z) const override {
    check_size(b.size(), "right-hand side");
    z = Eigen::Map<const Eigen::VectorXd>(b.begin(), n_);
  }
  void backward_in_place(Eigen::VectorXd& z, span<double> x) const override {
    check_size((std::size_t)z.size(), "forward-solved vector");
    check_size(x.size(), "solution");
    if (!solve_) throw std::logic_error("an external solver called with no solve bound to it");
    solve_(z, x);
  }

 private:
  void check_size(std::size_t got, const char* what) const {
    if (got != (std::size_t)n_)
      throw std::invalid_argument(std::string("external solver: ") + what + " has " + std::to_string(got) +
                                  " values for " + std::to_string(n_) + " unknowns");
  }
  int n_;
  Solve solve_;
};

// The contact problem of an ExternalSolver (whose forward half is the identity): Y = S H_rows'
// (so that z + Y r = b + S H' r before the backward solve) and W = H S A^-1 S H' given (k x k, the
// caller's), the columns C = S A^-1 S H_rows' (n x rows: C' b = H S A^-1 b for every b with S b =
// b, the step solver's right sides) kept by the caller, which binds their product C' z to
// DelassusFactor::motion for each call: the distributed run, where each rank holds the rows of C of
// a slice of the dofs and the product is the ranks' sum (the columns are dofs x bore rows, the
// run's largest array: divided by the ranks instead of held whole by every rank). normal_only: the
// even rows of H only (frictionless (n, t) pairs), as delassus_factor's. The same DelassusFactor
// every contact routine reads.
inline DelassusFactor delassus_from_caller_columns(const SparseMatrix& h, span<const double> free, const Eigen::MatrixXd& w,
                                                   bool normal_only) {
  const Eigen::Index n = h.cols(), k = h.rows();
  if ((Eigen::Index)free.size() != n)
    throw std::invalid_argument("free has " + std::to_string(free.size()) + " values for " + std::to_string(n) + " dofs");
  if (normal_only && k % 2 != 0) throw std::invalid_argument("normal_only needs (n, t) pairs of rows");
  DelassusFactor result;
  for (int r = 0; r < (int)k; r += normal_only ? 2 : 1) result.rows.push_back(r);
  const Eigen::Index c = (Eigen::Index)result.rows.size();
  if (w.rows() != k || w.cols() != k)
    throw std::invalid_argument("W is " + std::to_string(w.rows()) + " x " + std::to_string(w.cols()) + " for " +
                                std::to_string(k) + " contact rows");
  if (!w.allFinite()) throw std::invalid_argument("W holds a value that is not finite");
  Eigen::Map<const Eigen::VectorXd> mask(free.begin(), n);
  const SparseMatrix ht = h.transpose();
  std::vector<Eigen::Triplet<double, int>> t;
  for (Eigen::Index j = 0; j < c; ++j)
    for (SparseMatrix::InnerIterator it(ht, result.rows[(std::size_t)j]); it; ++it)
      if (mask[it.row()] != 0.0) t.emplace_back((int)it.row(), (int)j, it.value() * mask[it.row()]);
  result.y.resize((int)n, (int)c);
  result.y.setFromTriplets(t.begin(), t.end());
  result.y_scaled.resize((int)n, (int)c);
  result.caller_columns = true;
  result.w = w;
  return result;
}

// A second deformable body at the contact (an elastic pipe), loaded only by the contact reactions:
// it receives -H_2' r and moves at the contact rows by -C r, C = H_2 K_2^-1 H_2' its compliance
// there (symmetric positive semi-definite). The relative motion the Signorini-Coulomb laws see is
// then H u - (-C r) + gap = H u_free + (W + C) r + gap: the two bodies' compliances add, and every
// solver of the condensed problem (psor.hpp, contact_step.hpp, step_newton.hpp) runs unchanged on
// W + C. The first body's u = K^-1 (rhs + S H' r) keeps Y, so only W changes; the second body's
// displacement is recovered from r by its own solve. C is k x k in W's layout; it must be 0 on the
// rows W does not stand for (the tangential rows of a frictionless problem), finite and symmetric
// with a non-negative diagonal.
inline void add_obstacle_compliance(DelassusFactor& d, const Eigen::MatrixXd& c) {
  const Eigen::Index k = d.w.rows();
  if (c.rows() != k || c.cols() != k)
    throw std::invalid_argument("the compliance is " + std::to_string(c.rows()) + " x " + std::to_string(c.cols()) +
                                " for a Delassus operator of " + std::to_string(k) + " x " + std::to_string(k));
  if (!c.allFinite()) throw std::invalid_argument("the compliance has a value that is not finite");
  const double size = c.cwiseAbs().maxCoeff();
  std::vector<char> used((std::size_t)k, 0);
  for (int r : d.rows) used[(std::size_t)r] = 1;
  for (Eigen::Index i = 0; i < k; ++i) {
    if (c(i, i) < 0)
      throw std::invalid_argument("the compliance has a negative diagonal entry " + std::to_string(c(i, i)) +
                                  " at row " + std::to_string(i));
    for (Eigen::Index j = 0; j < k; ++j) {
      if (std::fabs(c(i, j) - c(j, i)) > 1e-12 * size)
        throw std::invalid_argument("the compliance is not symmetric at (" + std::to_string(i) + ", " +
                                    std::to_string(j) + ")");
      if ((!used[(std::size_t)i] || !used[(std::size_t)j]) && c(i, j) != 0.0)
        throw std::invalid_argument("the compliance couples row " + std::to_string(i) + " or " + std::to_string(j) +
                                    ", which the frictionless Delassus operator leaves out (tangential rows)");
    }
  }
  d.w += c;
}

}  // namespace sma
