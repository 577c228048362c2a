// A deflation space recycled across the linearised solves of one time step (step_newton.hpp's
// newton_direction), and the deflation preconditioner it gives on a subset of the points.
//
// Why: on a fine mesh the linearised step of a wide transformation front has a few tens of
// eigenvalues 1e-5 to 1e-3 of its largest (the front's smooth modes, where the eigenstress'
// elastic response nearly cancels the laminate term), and GMRES spends 200-290 products a solve
// on them; the step's active-set rounds and Newton iterations solve that operator again and
// again on nearly the same free points. The eigenvectors of the small eigenvalues found by one
// solve (harmonic Ritz vectors, with their images A v, which GMRES's Arnoldi relation gives
// without a product) are kept and reused as a preconditioner for the next solves:
//   P = I + Q (target M^-1 - I) Q' D,   M = Q' D A Q (symmetric part),
// Q a D-orthonormal basis of the kept vectors restricted to the solve's points, D = diag(q area)
// (the operator A = -df/dbeta / q is self-adjoint in that inner product: the step's Hessian
// over q area, to the 0.1 % of its asymmetry). If Q spans an invariant subspace exactly, A P
// has its eigenvalues moved to `target` and the others unchanged; an approximate Q (the images
// are those of the operator when the vectors were found: the next rounds restrict it to other
// points, the next iterations linearise at another state) only makes the preconditioner less
// good, never the answer different (GMRES is right-preconditioned: its residual is the true one).
// P is self-adjoint and positive in D (|M|'s eigenvalues are used), so A P has the inertia of A:
// an unstable block still shows a negative Ritz value, and P y of its Ritz vector y still has
// negative curvature (y' P' D A P y = theta y' D P y).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace sma {

// Kept vectors (columns, one entry per point, zero where their solve did not act) and their
// images under the operator they were found with.
struct RecycledSpace {
  Eigen::MatrixXd vectors, images;
  // Where the deflated eigenvalues are moved: 1, the scale of newton_direction's operator
  // -df/dbeta / q (its laminate term alone is the identity).
  double target = 1.0;
  int capacity = 0;     // columns kept (0: no recycling)
  bool stale = false;   // the images are of another operator (an earlier linearisation): refresh()
  bool empty() const { return vectors.cols() == 0; }
};

// P = I + Q G Q' D on one subset of the points (empty Q: P = I).
struct DeflationPreconditioner {
  Eigen::MatrixXd q, g;  // subset x modes, modes x modes
  Eigen::VectorXd weight;  // D on the subset
  bool empty() const { return q.cols() == 0; }
  Eigen::VectorXd apply(const Eigen::VectorXd& y) const {
    if (empty()) return y;
    Eigen::VectorXd out = y;
    out.noalias() += q * (g * (q.transpose() * weight.cwiseProduct(y)));
    return out;
  }
};

namespace deflation_detail {

// A D-orthonormal basis of the columns of z (directions of relative Gram eigenvalue below 1e-10
// dropped) and the images az carried along: returns the basis, az becomes its images.
inline Eigen::MatrixXd orthonormal(const Eigen::MatrixXd& z, const Eigen::VectorXd& weight, Eigen::MatrixXd& az) {
  if (z.cols() == 0) return z;
  const Eigen::MatrixXd gram = z.transpose() * weight.asDiagonal() * z;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (gram + gram.transpose()));
  const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < eig.eigenvalues().size(); ++i)
    if (eig.eigenvalues()[i] > 1e-10 * largest) keep.push_back(i);
  Eigen::MatrixXd map(z.cols(), (Eigen::Index)keep.size());
  for (Eigen::Index j = 0; j < (Eigen::Index)keep.size(); ++j)
    map.col(j) = eig.eigenvectors().col(keep[(std::size_t)j]) / std::sqrt(eig.eigenvalues()[keep[(std::size_t)j]]);
  az = az * map;
  return z * map;
}

}  // namespace deflation_detail

// The preconditioner on the points `sub` (weight: D on every point): the kept vectors restricted
// to sub, the modes of |Rayleigh quotient| below cutoff x target deflated to target.
inline DeflationPreconditioner deflation_on(const RecycledSpace& space, const std::vector<Eigen::Index>& sub,
                                            const Eigen::VectorXd& weight, double cutoff = 0.1,
                                            double accuracy = 1.0) {
  DeflationPreconditioner p;
  if (space.empty() || sub.empty()) return p;
  const Eigen::Index k = (Eigen::Index)sub.size(), m = space.vectors.cols();
  Eigen::MatrixXd z(k, m), az(k, m);
  p.weight.resize(k);
  for (Eigen::Index a = 0; a < k; ++a) {
    z.row(a) = space.vectors.row(sub[(std::size_t)a]);
    az.row(a) = space.images.row(sub[(std::size_t)a]);
    p.weight[a] = weight[sub[(std::size_t)a]];
  }
  const Eigen::MatrixXd q = deflation_detail::orthonormal(z, p.weight, az);
  if (q.cols() == 0) return p;
  const Eigen::MatrixXd t = q.transpose() * p.weight.asDiagonal() * az;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (t + t.transpose()));
  // Only modes that are eigenvectors to within their own eigenvalue (|A v - mu v|_D <= accuracy |mu|)
  // are deflated: P multiplies v by target / mu, and with it v's error, which A P then carries
  // outside the deflated space at target x (error / mu): a mixture of modes (a harmonic Ritz vector
  // of a GMRES run that stopped early) would spread the spectrum instead of shrinking it.
  std::vector<Eigen::Index> small;
  for (Eigen::Index i = 0; i < eig.eigenvalues().size(); ++i) {
    const double mu = eig.eigenvalues()[i];
    if (!(std::fabs(mu) < cutoff * space.target)) continue;
    const Eigen::VectorXd error = az * eig.eigenvectors().col(i) - mu * (q * eig.eigenvectors().col(i));
    if (std::sqrt(error.dot(p.weight.cwiseProduct(error))) <= accuracy * std::fabs(mu)) small.push_back(i);
  }
  if (small.empty()) return p;
  const Eigen::Index r = (Eigen::Index)small.size();
  p.q.resize(k, r);
  p.g = Eigen::MatrixXd::Zero(r, r);
  for (Eigen::Index j = 0; j < r; ++j) {
    const Eigen::Index i = small[(std::size_t)j];
    p.q.col(j) = q * eig.eigenvectors().col(i);
    const double mu = std::max(std::fabs(eig.eigenvalues()[i]), 1e-8 * space.target);
    p.g(j, j) = space.target / mu - 1.0;
  }
  return p;
}

// The images of the kept vectors recomputed under the operator `apply` on the points `sub` (a new
// linearisation: stale images misplace the deflated eigenvalues, a mode found at 1e-3 and now at
// 1e-2 would be moved to 10 x target, spreading the spectrum GMRES has to cover). Only the modes
// the stale images put below cutoff x target are refreshed (one product each) and kept, restricted
// to sub. Returns the products spent.
template <class Apply>
int refresh(RecycledSpace& space, const std::vector<Eigen::Index>& sub, const Eigen::VectorXd& weight,
            const Apply& apply, double cutoff = 0.1) {
  space.stale = false;
  const DeflationPreconditioner stale =
      deflation_on(space, sub, weight, cutoff, std::numeric_limits<double>::infinity());
  const Eigen::Index r = stale.q.cols(), n = space.vectors.rows();
  space.vectors = Eigen::MatrixXd::Zero(n, r);
  space.images = Eigen::MatrixXd::Zero(n, r);
  for (Eigen::Index j = 0; j < r; ++j) {
    const Eigen::VectorXd image = apply(Eigen::VectorXd(stale.q.col(j)));
    for (Eigen::Index a = 0; a < (Eigen::Index)sub.size(); ++a) {
      space.vectors(sub[(std::size_t)a], j) = stale.q(a, j);
      space.images(sub[(std::size_t)a], j) = image[a];
    }
  }
  return (int)r;
}

// Adds vectors (columns, one entry per point) and their images to the space and keeps the
// `capacity` directions of smallest |Rayleigh quotient| of their span.
inline void recycle(RecycledSpace& space, const Eigen::MatrixXd& vectors, const Eigen::MatrixXd& images,
                    const Eigen::VectorXd& weight) {
  if (space.capacity <= 0 || vectors.cols() == 0) return;
  Eigen::MatrixXd z = vectors, az = images;
  if (!space.empty()) {
    z.resize(vectors.rows(), space.vectors.cols() + vectors.cols());
    az.resize(z.rows(), z.cols());
    z << space.vectors, vectors;
    az << space.images, images;
  }
  const Eigen::MatrixXd q = deflation_detail::orthonormal(z, weight, az);
  const Eigen::MatrixXd t = q.transpose() * weight.asDiagonal() * az;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (t + t.transpose()));
  std::vector<Eigen::Index> order((std::size_t)eig.eigenvalues().size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = (Eigen::Index)i;
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return std::fabs(eig.eigenvalues()[a]) < std::fabs(eig.eigenvalues()[b]);
  });
  const Eigen::Index keep = std::min<Eigen::Index>(space.capacity, (Eigen::Index)order.size());
  Eigen::MatrixXd select(q.cols(), keep);
  for (Eigen::Index j = 0; j < keep; ++j) select.col(j) = eig.eigenvectors().col(order[(std::size_t)j]);
  space.vectors = q * select;
  space.images = az * select;
}

}  // namespace sma
