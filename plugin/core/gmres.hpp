// GMRES from x = 0, without restart, on a linear operator given as a function (the step solver's
// products, step_newton.hpp; the cone polish's Newton steps on a reused factor, psor_cone.hpp), with
// the Ritz values of its Hessenberg matrix and, asked for, harmonic Ritz vectors.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

namespace sma {
namespace step_detail {

// GMRES from x = 0 (no restart) on a linear operator; the Ritz values of its Hessenberg matrix
// tell whether the operator has an eigenvalue of non-positive real part in the Krylov space.
struct GmresResult {
  Eigen::VectorXd x;
  int iterations = 0;
  double smallest_ritz_real = 1.0;
  Eigen::VectorXd smallest_ritz_vector;  // its Ritz vector (real part, unit length)
  bool finite = true;
  bool converged = false;  // the residual fell to rtol
  // Asked for (harvest > 0): the harmonic Ritz vectors of the smallest |harmonic Ritz values|
  // (real parts, columns) and their images under the operator (from the Arnoldi relation, no
  // product): the deflation space's candidates (deflation.hpp).
  Eigen::MatrixXd harvest_vectors, harvest_images;
};
template <class Op>
GmresResult gmres(const Op& apply, const Eigen::VectorXd& b, double rtol, int maxit, bool stop_if_unstable = false,
                  double atol = 0.0, int stable_cap = std::numeric_limits<int>::max(), int harvest = 0) {
  GmresResult out;
  const Eigen::Index n = b.size();
  out.x = Eigen::VectorXd::Zero(n);
  const double beta = b.norm();
  if (n == 0 || beta == 0.0) return out;
  const int m = (int)std::min<Eigen::Index>(maxit, n);
  // H: the Arnoldi Hessenberg matrix (for the Ritz values); R: H rotated to upper triangular by
  // the Givens rotations (cs, sn), g the rotated right side. Held for `cap` iterations and grown
  // (doubled, the new entries zero) when the iterations reach it: most solves take a few tens of
  // the m allowed, and zeroing two (m + 1) x m matrices per solve cost more than its products.
  int cap = std::min(m, 16);
  Eigen::MatrixXd V(n, cap + 1), H = Eigen::MatrixXd::Zero(cap + 1, cap), R = Eigen::MatrixXd::Zero(cap + 1, cap);
  Eigen::VectorXd cs = Eigen::VectorXd::Zero(cap), sn = Eigen::VectorXd::Zero(cap), g = Eigen::VectorXd::Zero(cap + 1);
  V.col(0) = b / beta;
  g[0] = beta;
  int k = 0;
  for (; k < m; ++k) {
    if (k == cap) {
      cap = std::min(m, 2 * cap);
      V.conservativeResize(Eigen::NoChange, cap + 1);
      H.conservativeResizeLike(Eigen::MatrixXd::Zero(cap + 1, cap));
      R.conservativeResizeLike(Eigen::MatrixXd::Zero(cap + 1, cap));
      cs.conservativeResizeLike(Eigen::VectorXd::Zero(cap));
      sn.conservativeResizeLike(Eigen::VectorXd::Zero(cap));
      g.conservativeResizeLike(Eigen::VectorXd::Zero(cap + 1));
    }
    Eigen::VectorXd w = apply(V.col(k));
    for (int j = 0; j <= k; ++j) {  // modified Gram-Schmidt
      H(j, k) = w.dot(V.col(j));
      w -= H(j, k) * V.col(j);
    }
    H(k + 1, k) = w.norm();
    const bool breakdown = !(H(k + 1, k) > 1e-14 * beta);
    if (!breakdown) V.col(k + 1) = w / H(k + 1, k);
    R.col(k).head(k + 2) = H.col(k).head(k + 2);
    for (int j = 0; j < k; ++j) {
      const double t = cs[j] * R(j, k) + sn[j] * R(j + 1, k);
      R(j + 1, k) = -sn[j] * R(j, k) + cs[j] * R(j + 1, k);
      R(j, k) = t;
    }
    const double rr = std::hypot(R(k, k), R(k + 1, k));
    cs[k] = rr > 0 ? R(k, k) / rr : 1.0;
    sn[k] = rr > 0 ? R(k + 1, k) / rr : 0.0;
    R(k, k) = rr;
    R(k + 1, k) = 0.0;
    g[k + 1] = -sn[k] * g[k];
    g[k] = cs[k] * g[k];
    const double enough = std::max(rtol * beta, atol);
    if (breakdown || std::fabs(g[k + 1]) <= enough) {
      out.converged = std::fabs(g[k + 1]) <= enough;
      ++k;
      break;
    }
    // A clearly unstable operator (a Ritz value below -1e-3 of the largest) is reported without
    // solving on: its Ritz values are checked at 8, 16, 32, ... iterations. (A nearly singular
    // stable one, whose smallest Ritz values wander around zero until they settle, is solved.)
    // stable_cap: at that many iterations an operator that does not look clearly unstable is
    // left unsolved (its partial solution is still a descent move); a clearly unstable one is
    // solved on to maxit, since a saddle's Newton move needs the solution itself.
    const bool at_check = stop_if_unstable && k + 1 >= 8 && ((k + 1) & k) == 0;
    if (at_check || k + 1 == stable_cap) {
      const Eigen::EigenSolver<Eigen::MatrixXd> early(H.topLeftCorner(k + 1, k + 1), false);
      const Eigen::VectorXd re = early.eigenvalues().real();
      const bool unstable = re.minCoeff() < -1e-3 * early.eigenvalues().cwiseAbs().maxCoeff();
      if ((at_check && unstable) || (k + 1 == stable_cap && !unstable)) {
        ++k;
        break;
      }
    }
  }
  out.iterations = k;
  const bool broke_down = k > 0 && !(H(k, k - 1) > 1e-14 * beta);
  // y = R^-1 g by back-substitution (a zero pivot: the operator is singular on the Krylov space).
  Eigen::VectorXd y = Eigen::VectorXd::Zero(k);
  for (int i = k - 1; i >= 0; --i) {
    double t = g[i];
    for (int j = i + 1; j < k; ++j) t -= R(i, j) * y[j];
    y[i] = R(i, i) != 0.0 ? t / R(i, i) : std::numeric_limits<double>::quiet_NaN();
  }
  out.x = V.leftCols(k) * y;
  out.finite = out.x.allFinite();
  if (k > 0) {
    const Eigen::EigenSolver<Eigen::MatrixXd> eig(H.topLeftCorner(k, k), true);
    Eigen::Index which = 0;
    for (Eigen::Index i = 1; i < eig.eigenvalues().size(); ++i)
      if (eig.eigenvalues()[i].real() < eig.eigenvalues()[which].real()) which = i;
    out.smallest_ritz_real = eig.eigenvalues()[which].real();
    out.smallest_ritz_vector = V.leftCols(k) * eig.eigenvectors().col(which).real();
    const double norm = out.smallest_ritz_vector.norm();
    if (norm > 0) out.smallest_ritz_vector /= norm;
  }
  if (harvest > 0 && k > 0) {
    // Harmonic Ritz values: the eigenvalues of H_k + h^2 H_k^-T e_k e_k' (h = H(k, k-1)), the
    // better approximations of the eigenvalues nearest zero (plain Ritz values where H_k is singular).
    const Eigen::Index rows = broke_down ? k : k + 1;
    Eigen::MatrixXd F = H.topLeftCorner(k, k);
    if (!broke_down) {
      const Eigen::FullPivLU<Eigen::MatrixXd> lu(F.transpose());
      if (lu.isInvertible()) {
        const Eigen::VectorXd f = lu.solve(Eigen::VectorXd::Unit(k, k - 1));
        if (f.allFinite()) F.col(k - 1) += H(k, k - 1) * H(k, k - 1) * f;
      }
    }
    const Eigen::EigenSolver<Eigen::MatrixXd> eig(F, true);
    std::vector<Eigen::Index> order((std::size_t)k);
    for (Eigen::Index i = 0; i < k; ++i) order[(std::size_t)i] = i;
    std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
      return std::abs(eig.eigenvalues()[a]) < std::abs(eig.eigenvalues()[b]);
    });
    const Eigen::Index take = std::min<Eigen::Index>(harvest, k);
    Eigen::MatrixXd s(k, take);
    for (Eigen::Index j = 0; j < take; ++j) s.col(j) = eig.eigenvectors().col(order[(std::size_t)j]).real();
    if (s.allFinite()) {
      out.harvest_vectors = V.leftCols(k) * s;
      out.harvest_images = V.leftCols(rows) * (H.topLeftCorner(rows, k) * s);
    }
  }
  return out;
}

}  // namespace step_detail
}  // namespace sma
