// Projected SOR on a condensed 3D contact problem: Signorini and a Tresca disk, the two tangential
// components of a 3D contact together (issue 49; psor.hpp is the 2D problem: one tangential
// component, a Tresca interval). With the slip-threshold fixed point g = mu r_n around it
// (coulomb_cone_fixed_point) it solves the Coulomb cone, as the scenes' loops do in 2D.
//
// Unknowns: per contact node i, r = (r_n, r_t1, r_t2), stored interleaved (3 per node; t1, t2 any
// orthonormal pair of the tangent plane). With the Delassus operator W = H K^-1 H' (3m x 3m,
// symmetric positive definite, or with the rows and columns of blocked tangential motions zero)
// and q the free motion, the local motions are w = W r - q and the laws are
//   Signorini:    r_n >= 0, w_n >= 0, r_n w_n = 0
//   Tresca disk:  |r_t| <= g_i;  |r_t| < g_i => w_t = 0 (stick);  |r_t| = g_i => w_t = -k r_t,
//                 k >= 0 (the slip opposes the reaction); i.e. r_t = proj_disk(g)(r_t - rho w_t)
//                 for any rho > 0.
// A sweep takes each node in turn (block Gauss-Seidel, as LMGC90's and Siconos' nonsmooth
// Gauss-Seidel): the normal component as psor.hpp's, r_n <- max(0, r_n - omega w_n / W_nn); then
// the tangential pair by the exact solution of its local problem (the 2 x 2 block A of W, the
// others fixed: min 1/2 x'A x - b'x over the disk |x| <= g, tresca_disk_local), relaxed by omega
// and projected back on the disk. The disk couples the two components: two scalar clamps in turn
// (psor.hpp's update per component) would bound each, not |r_t|.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "gmres.hpp"
#include "psor.hpp"

namespace sma {

// The point of the disk |x| <= radius nearest to x.
inline Eigen::Vector2d project_disk(const Eigen::Vector2d& x, double radius) {
  const double norm = x.norm();
  return norm <= radius ? x : Eigen::Vector2d(x * (radius / norm));
}

// min 1/2 x'A x - b'x over |x| <= g, A symmetric positive definite (2 x 2), g >= 0. Inside: A x = b.
// On the circle (the unconstrained minimum outside it): x = (A + lambda I)^-1 b with the lambda > 0
// that puts it on the circle, the root of phi(lambda) = 1 / |x(lambda)| - 1 / g (the trust-region
// subproblem's secular equation, which Newton's method solves monotonically from the left: phi is
// concave and increasing; More and Sorensen), in A's eigenbasis, kept in the bracket
// [0, |b| / g] where phi changes sign.
// A blocked component (its diagonal 0, its row and column 0) stays 0, the other on [-g, g].
inline Eigen::Vector2d tresca_disk_local(const Eigen::Matrix2d& A, const Eigen::Vector2d& b, double g) {
  if (!(g > 0.0)) return Eigen::Vector2d::Zero();
  if (A(0, 0) == 0.0 || A(1, 1) == 0.0) {
    Eigen::Vector2d x = Eigen::Vector2d::Zero();
    for (int k = 0; k < 2; ++k)
      if (A(k, k) != 0.0) x[k] = std::clamp(b[k] / A(k, k), -g, g);
    return x;
  }
  const Eigen::Vector2d inside = A.ldlt().solve(b);
  if (inside.norm() <= g) return inside;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(A);
  const Eigen::Vector2d d = eigen.eigenvalues(), c = eigen.eigenvectors().transpose() * b;
  double low = 0.0, high = b.norm() / g, lambda = 0.0;
  for (int it = 0; it < 100; ++it) {
    const double s0 = c[0] / (d[0] + lambda), s1 = c[1] / (d[1] + lambda);
    const double norm = std::hypot(s0, s1);
    const double phi = 1.0 / norm - 1.0 / g;
    if (phi < 0) low = lambda; else high = lambda;
    // d|x|/dlambda = -(s0^2 / (d0 + lambda) + s1^2 / (d1 + lambda)) / |x|; phi' = -|x|' / |x|^2
    const double slope = (s0 * s0 / (d[0] + lambda) + s1 * s1 / (d[1] + lambda)) / (norm * norm * norm);
    double next = lambda - phi / slope;
    if (!(next > low && next < high)) next = 0.5 * (low + high);  // a Newton step out of the bracket: bisect
    if (std::fabs(next - lambda) <= 1e-15 * std::max(next, 1e-300) || high - low <= 1e-15 * high) {
      lambda = next;
      break;
    }
    lambda = next;
  }
  const Eigen::Vector2d x = eigen.eigenvectors() *
                            Eigen::Vector2d(c[0] / (d[0] + lambda), c[1] / (d[1] + lambda));
  return project_disk(x, g);  // on the circle to round-off; never outside it
}

// The natural-map residual of the 3D laws: 0 exactly at a solution, scale-free (max over the
// components of |F(r) - r| over max |r|, F the laws' projections with rho = 1 / W_nn for the normal
// and 1 / max(W_t1t1, W_t2t2) for the tangential pair).
inline double cone_law_residual(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, const Eigen::VectorXd& g,
                                const Eigen::VectorXd& r) {
  const Eigen::VectorXd w = W * r - q;
  double worst = 0.0, scale = 0.0;
  for (Eigen::Index i = 0; i < g.size(); ++i) {
    const Eigen::Index n = 3 * i;
    const double rn = std::max(0.0, r[n] - w[n] / W(n, n));
    const double wtt = std::max(W(n + 1, n + 1), W(n + 2, n + 2));
    const Eigen::Vector2d rt(r[n + 1], r[n + 2]);
    const Eigen::Vector2d mapped =
        wtt == 0.0 ? Eigen::Vector2d::Zero() : project_disk(rt - Eigen::Vector2d(w[n + 1], w[n + 2]) / wtt, g[i]);
    worst = std::max({worst, std::fabs(rn - r[n]), (mapped - rt).lpNorm<Eigen::Infinity>()});
    scale = std::max({scale, std::fabs(r[n]), rt.lpNorm<Eigen::Infinity>()});
  }
  return scale > 0 ? worst / scale : worst;
}

// The polish of the 3D problem: a semismooth Newton method on its natural map (Alart and Curnier's
// approach, with the exact generalized Jacobian), started from the sweeps' iterate. With
// z = r - rho (W r - q) (rho = 1 / W_nn for the normal, 1 / max(W_t1t1, W_t2t2) for the pair),
// F(r) = r - P(z), P the projections: max(0, z_n), and the disk |z_t| <= g (the segment where one
// tangential motion is blocked, 0 where both are or g = 0). Newton's step solves
// (I - D (I - rho W)) dr = -F (dense LU: the matrix is not symmetric), D = dP/dz per node: 1 or 0
// for the normal; I inside the disk, (g / |z_t|) (I - d d') on its circle (d = z_t / |z_t|: the
// sliding direction turns with the slip, which a fixed-direction active set misses); then
// backtracking on |F|. Accepted when the natural-map residual is <= accept; otherwise the sweeps go
// on (psor.hpp's polish plays the same role in 2D, where the interval makes the set's faces flat).
namespace cone_detail {
// P(z) and its derivative D for node i's rows k = 3i .. 3i + 2 (z, P, D: the whole vectors and matrix).
// (D: the node's 3 x 3 block, its rows and columns k .. k + 2 addressed as 0 .. 2 through `base` = k)
inline void project_node(const Eigen::MatrixXd& W, const Eigen::VectorXd& g, Eigen::Index i, const Eigen::VectorXd& z,
                         Eigen::VectorXd& p, Eigen::MatrixXd* D, Eigen::Index base) {
  const Eigen::Index k = 3 * i;
  p[k] = std::max(0.0, z[k]);
  if (D) (*D)(k - base, k - base) = z[k] > 0.0 ? 1.0 : 0.0;
  const bool free1 = W(k + 1, k + 1) != 0.0, free2 = W(k + 2, k + 2) != 0.0;
  p[k + 1] = p[k + 2] = 0.0;
  if (!(g[i] > 0.0) || (!free1 && !free2)) return;
  if (free1 != free2) {  // the segment of the free component
    const Eigen::Index c = free1 ? k + 1 : k + 2;
    p[c] = std::clamp(z[c], -g[i], g[i]);
    if (D) (*D)(c - base, c - base) = std::fabs(z[c]) < g[i] ? 1.0 : 0.0;
    return;
  }
  const Eigen::Vector2d zt(z[k + 1], z[k + 2]);
  const double norm = zt.norm();
  if (norm <= g[i]) {
    p[k + 1] = zt[0], p[k + 2] = zt[1];
    if (D) (*D)(k + 1 - base, k + 1 - base) = (*D)(k + 2 - base, k + 2 - base) = 1.0;
    return;
  }
  const Eigen::Vector2d d = zt / norm;
  p[k + 1] = g[i] * d[0], p[k + 2] = g[i] * d[1];
  if (D) (*D).block<2, 2>(k + 1 - base, k + 1 - base) = (g[i] / norm) * (Eigen::Matrix2d::Identity() - d * d.transpose());
}
}  // namespace cone_detail

// What the polish keeps from one Newton step to the next, across calls on the same W (the
// caller's: the step solver keeps one over a time step): the last LU factor
// of the Newton matrix's kept rows, and which rows. A step whose kept rows are the same is solved
// by GMRES on its own matrix, preconditioned by that factor (the matrices differ only where a
// node's status or sliding direction moved, W being the same), to 1e-12 of its right side in at
// most 30 products; else (other rows, or GMRES short of it) the matrix is factorised again and
// kept. Each round of each polish factorised its matrix before: on Coulomb's cone at -nt 16 -nz 20
// (1071 rows) that was most of the run (docs/measurements.md#m-cone-polish).
struct ConePolishMemory {
  std::vector<Eigen::Index> kept;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  bool held = false;
  long factorisations = 0, reuses = 0;  // (counts over the memory's life)
};

// Newton's step J step = -F of polish_cone, where J = I - D + D diag(rho) W (+ Coulomb's slope
// column). A row whose D row is 0 and whose slope is 0 (an open node's three rows; a tangential
// motion blocked, or without a threshold) is the identity's: its step is -F there, known, and only
// the other rows and columns are solved for, with the known steps moved to the right side. The same
// solution as the whole LU's (to round-off); its cost is the pressing nodes' cube, not the bore's,
// or with a memory a few products when the factor of an earlier step serves.
namespace cone_detail {
inline Eigen::VectorXd reduced_newton_step(const Eigen::MatrixXd& J, const Eigen::MatrixXd& D, const Eigen::VectorXd& F,
                                           const Eigen::VectorXd* slope, ConePolishMemory* memory = nullptr) {
  const Eigen::Index n = F.size();
  std::vector<Eigen::Index> kept, known;
  kept.reserve((std::size_t)n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const bool identity = D.row(k).isZero(0.0) && (!slope || (*slope)[k] == 0.0);
    (identity ? known : kept).push_back(k);
  }
  Eigen::VectorXd step(n);
  for (Eigen::Index k : known) step[k] = -F[k];
  if (kept.empty()) return step;
  const Eigen::Index a = (Eigen::Index)kept.size();
  Eigen::MatrixXd Jkk(a, a);
  Eigen::VectorXd rhs(a);
  for (Eigen::Index i = 0; i < a; ++i) {
    const Eigen::Index row = kept[(std::size_t)i];
    double right = -F[row];
    for (Eigen::Index k : known) right -= J(row, k) * step[k];
    rhs[i] = right;
  }
  for (Eigen::Index j = 0; j < a; ++j)
    for (Eigen::Index i = 0; i < a; ++i) Jkk(i, j) = J(kept[(std::size_t)i], kept[(std::size_t)j]);
  Eigen::VectorXd solved;
  bool done = false;
  if (memory && memory->held && memory->kept == kept) {
    const Eigen::PartialPivLU<Eigen::MatrixXd>& lu = memory->lu;
    const auto preconditioned = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return Jkk * lu.solve(v); };
    const step_detail::GmresResult g = step_detail::gmres(preconditioned, rhs, 1e-12, 30);
    if (g.converged && g.finite) {
      solved = lu.solve(g.x);
      done = solved.allFinite() && (Jkk * solved - rhs).norm() <= 1e-10 * rhs.norm();
    }
    if (done) ++memory->reuses;
  }
  if (!done) {
    if (memory) {
      memory->lu.compute(Jkk);
      memory->kept = kept;
      memory->held = true;
      ++memory->factorisations;
      solved = memory->lu.solve(rhs);
    } else {
      solved = Jkk.partialPivLu().solve(rhs);
    }
  }
  for (Eigen::Index i = 0; i < a; ++i) step[kept[(std::size_t)i]] = solved[i];
  return step;
}
}  // namespace cone_detail

inline bool polish_cone(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, const Eigen::VectorXd& g, double accept,
                        Eigen::VectorXd& r, int max_rounds = 15, const Eigen::VectorXd* coulomb_mu = nullptr,
                        ConePolishMemory* memory = nullptr) {
  const Eigen::Index m = g.size(), n = 3 * m;
  Eigen::VectorXd rho(n);
  for (Eigen::Index i = 0; i < m; ++i) {
    const Eigen::Index k = 3 * i;
    rho[k] = 1.0 / W(k, k);
    const double wtt = std::max(W(k + 1, k + 1), W(k + 2, k + 2));
    rho[k + 1] = rho[k + 2] = wtt > 0.0 ? 1.0 / wtt : 0.0;
  }
  // D is block diagonal (3 x 3 per node): held as an n x 3 matrix of the blocks, so that
  // J = I - D + D diag(rho) W costs 9 n^2 rather than a dense product's n^3.
  Eigen::MatrixXd block(3, 3);
  // Coulomb's radius g = mu max(0, x_n) of the iterate itself (coulomb_mu; Alart and Curnier's),
  // else the given thresholds; `slope` (Coulomb) the tangential rows' derivative along their
  // node's x_n, mu d on the circle (d the sliding direction), 0 inside.
  Eigen::VectorXd radius = g, slope;
  const auto natural = [&](const Eigen::VectorXd& x, Eigen::VectorXd& F, Eigen::MatrixXd* D) {
    const Eigen::VectorXd z = x - rho.cwiseProduct(W * x - q);
    Eigen::VectorXd p(n);
    if (D) D->setZero(n, 3);
    if (coulomb_mu) {
      for (Eigen::Index i = 0; i < m; ++i) radius[i] = (*coulomb_mu)[i] * std::max(0.0, x[3 * i]);
      if (D) slope.setZero(n);
    }
    for (Eigen::Index i = 0; i < m; ++i) {
      block.setZero();
      cone_detail::project_node(W, radius, i, z, p, D ? &block : nullptr, 3 * i);
      if (D) D->middleRows(3 * i, 3) = block;
      if (D && coulomb_mu && x[3 * i] > 0.0 && radius[i] > 0.0)
        for (int c = 1; c <= 2; ++c)  // on the circle (or the segment's end): |p_t| = radius
          if (block(c, c) != 1.0 && (p[3 * i + 1] != 0.0 || p[3 * i + 2] != 0.0))
            slope[3 * i + c] = (*coulomb_mu)[i] * p[3 * i + c] / radius[i];
    }
    F = x - p;
  };
  // An iterate is accepted projected on the sets (r_n >= 0, the disk; Newton's iterates may be
  // outside them by round-off) when the laws hold to accept there.
  const auto accepted = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd y = x;
    Eigen::VectorXd gy = g;
    // On Coulomb's cone a node the natural map leaves open (z_n <= 0) is open exactly: Newton's
    // iterate may hold round-off there (1e-27), which would read as pressing, with a disk of its
    // own (its radius mu r_n).
    Eigen::VectorXd wy;
    if (coulomb_mu) wy = W * y - q;
    for (Eigen::Index i = 0; i < m; ++i) {
      y[3 * i] = std::max(0.0, y[3 * i]);
      if (coulomb_mu && !(y[3 * i] - rho[3 * i] * wy[3 * i] > 0.0)) y[3 * i] = 0.0;
      if (coulomb_mu) gy[i] = (*coulomb_mu)[i] * y[3 * i];
      const Eigen::Vector2d t = project_disk(Eigen::Vector2d(y[3 * i + 1], y[3 * i + 2]), gy[i]);
      y[3 * i + 1] = t[0], y[3 * i + 2] = t[1];
    }
    if (!(cone_law_residual(W, q, gy, y) <= accept)) return false;
    r = y;
    return true;
  };
  Eigen::VectorXd x = r, F(n), Ftrial(n), xtrial(n);
  Eigen::MatrixXd D(n, 3), J(n, n);
  for (int round = 0; round < max_rounds; ++round) {
    if (accepted(x)) return true;
    natural(x, F, &D);
    // J = I - D (I - rho W) = I - D + D diag(rho) W, column by column: J's column j is the block
    // diagonal D diag(rho) times W's column j, both read and written in storage order (a product
    // of each node's 3 rows of W, strided, was 8 % of the 3D cone's run).
    for (Eigen::Index j = 0; j < n; ++j) {
      const double* w = W.col(j).data();
      double* out = J.col(j).data();
      for (Eigen::Index i = 0; i < m; ++i) {
        const Eigen::Index k = 3 * i;
        const double a0 = rho[k] * w[k], a1 = rho[k + 1] * w[k + 1], a2 = rho[k + 2] * w[k + 2];
        for (int c = 0; c < 3; ++c) out[k + c] = D(k + c, 0) * a0 + D(k + c, 1) * a1 + D(k + c, 2) * a2;
      }
    }
    for (Eigen::Index i = 0; i < m; ++i) {
      J.block(3 * i, 3 * i, 3, 3) += Eigen::Matrix3d::Identity() - D.middleRows(3 * i, 3);
      if (coulomb_mu) J.block(3 * i + 1, 3 * i, 2, 1) -= slope.segment(3 * i + 1, 2);
    }
    const Eigen::VectorXd step = cone_detail::reduced_newton_step(J, D, F, coulomb_mu ? &slope : nullptr, memory);
    if (!step.allFinite()) return false;
    const double merit = F.squaredNorm();
    double t = 1.0;
    for (; t > 1e-8; t *= 0.5) {
      xtrial = x + t * step;
      natural(xtrial, Ftrial, nullptr);
      if (Ftrial.squaredNorm() <= (1 - 1e-4 * t) * merit) break;
    }
    if (!(t > 1e-8)) return false;
    x = xtrial;
  }
  return accepted(x);
}

// Sweeps from the given r (a warm start) until the relative change of r over a sweep is <= tol
// (measured per unit relaxation, as psor_condensed's) or maxit sweeps; with polish_every > 0 the
// polish (polish_cone) is tried after polish_every sweeps and ends them when it solves the
// problem (converged, residual = its law residual): the ring's all-active Delassus operator makes
// the sweeps alone converge linearly at a rate set by its conditioning (200000 sweeps left a change
// of 3e-7 on sleeve-3d's bending, measured). After each polish that fails the wait before the next
// doubles (10, 20, 40 ... sweeps): a polish costs a dense LU per round, O(n^3) against a sweep's
// O(n^2), and while part of the bore sticks it may fail for thousands of sweeps (sleeve-3d's
// pull-out at L = 10 cm: 10644 sweeps, a failed polish every 10 was most of the time); doubling
// keeps the polishes to log2 of the sweeps and adds at most as many sweeps as were already done.
// The polishes' factor is kept over the call (ConePolishMemory), or over the caller's calls when
// it gives its memory (the step solver: over a time step).
// Throws on inconsistent input; the caller reads `converged`, `iterations`, `residual`, `polishes`.
inline PsorResult psor_cone(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, const Eigen::VectorXd& g,
                            double omega, double tol, int maxit, Eigen::VectorXd& r, int polish_every = 0,
                            const Eigen::VectorXd* coulomb_mu = nullptr, ConePolishMemory* memory = nullptr) {
  const Eigen::Index m = g.size();
  if (W.rows() != 3 * m || W.cols() != 3 * m || q.size() != 3 * m || r.size() != 3 * m)
    throw std::invalid_argument("psor_cone: W must be 3m x 3m and q, r of length 3m for m = " + std::to_string(m) +
                                " contact nodes");
  if (!(omega > 0.0 && omega < 2.0))
    throw std::invalid_argument("psor_cone: relaxation omega = " + psor_detail::number(omega) + " must be in (0, 2)");
  if (!(tol >= 0.0)) throw std::invalid_argument("psor_cone: tolerance must be >= 0");
  for (Eigen::Index i = 0; i < m; ++i) {
    const Eigen::Index n = 3 * i;
    if (!(g[i] >= 0.0))
      throw std::invalid_argument("psor_cone: slip threshold g = " + psor_detail::number(g[i]) + " < 0 at contact node " +
                                  std::to_string(i));
    if (!(W(n, n) > 0.0))
      throw std::invalid_argument("psor_cone: Delassus normal diagonal not positive at contact node " + std::to_string(i) +
                                  " (is its normal motion blocked by a support?)");
    // A support may block a tangential motion (a node on a symmetry plane: its row and column of
    // W are 0): its component stays 0, and the disk of the other is the segment [-g, g] (one
    // blocked) or nothing (both blocked: the threshold must then be 0, as psor_condensed's).
    const bool blocked1 = W(n + 1, n + 1) == 0.0, blocked2 = W(n + 2, n + 2) == 0.0;
    if (blocked1 && blocked2 && g[i] != 0.0)
      throw std::invalid_argument("psor_cone: both tangential motions blocked (Delassus tangential diagonals 0) at "
                                  "contact node " + std::to_string(i) + " with slip threshold " + psor_detail::number(g[i]) +
                                  " (needs threshold 0)");
    // A tangential compliance not 0 but round-off beside the normal's is a motion a support holds,
    // rounded away from exact (a node 6e-17 off its symmetry plane gave 4e-33 of it: sleeve-3d's
    // pull-out, docs/measurements.md#m-sleeve-3d-pullout); its reaction would be anything in the
    // disk. Refused, naming the node: such a motion must be held exactly (its row of W 0).
    for (Eigen::Index c = 1; c <= 2; ++c)
      if (W(n + c, n + c) > 0.0 && W(n + c, n + c) <= 1e-12 * W(n, n))
        throw std::invalid_argument("psor_cone: tangential compliance " + psor_detail::number(W(n + c, n + c) / W(n, n)) +
                                    " of the normal's at contact node " + std::to_string(i) + " (tangent " +
                                    std::to_string(c) + "): a motion a support holds but for round-off (a node off "
                                    "its symmetry plane?); hold it exactly (its row of W 0)");
    if (!(W(n + 1, n + 1) >= 0.0 && W(n + 2, n + 2) >= 0.0) ||
        (!blocked1 && !blocked2 && !(W.block<2, 2>(n + 1, n + 1).determinant() > 0.0)))
      throw std::invalid_argument("psor_cone: the tangential 2 x 2 block of the Delassus operator is not positive "
                                  "definite at contact node " + std::to_string(i));
  }
  if (coulomb_mu && (coulomb_mu->size() != m || !(coulomb_mu->minCoeff() >= 0.0)))
    throw std::invalid_argument("psor_cone: Coulomb's coefficients must be m values >= 0");
  PsorResult result;
  Eigen::VectorXd w = W * r - q;  // kept up to date column by column
  // The disk's radius per node: g, or on Coulomb's cone (coulomb_mu) mu r_n of the sweep's own
  // normal reaction, taken as soon as the node's normal component is updated.
  Eigen::VectorXd radius = g;
  long long polish_wait = polish_every, next_polish = polish_every;  // (long: doubled past maxit)
  // the polishes' factor: the caller's (kept over its calls), else this call's own
  ConePolishMemory own_memory;
  ConePolishMemory* const polish_memory = memory ? memory : &own_memory;
  while (result.iterations < maxit) {
    ++result.iterations;
    double change = 0.0, size = 0.0;
    for (Eigen::Index i = 0; i < m; ++i) {
      const Eigen::Index n = 3 * i;
      const double oldN = r[n];
      const double newN = std::max(0.0, oldN - omega * w[n] / W(n, n));
      if (newN != oldN) {
        r[n] = newN;
        w += W.col(n) * (newN - oldN);
      }
      change = std::max(change, std::fabs(newN - oldN));
      size = std::max(size, newN);
      if (coulomb_mu) radius[i] = (*coulomb_mu)[i] * newN;
      if (radius[i] == 0.0 && r[n + 1] == 0.0 && r[n + 2] == 0.0) continue;  // frictionless or blocked: r_t stays 0
      const Eigen::Vector2d oldT(r[n + 1], r[n + 2]);
      const Eigen::Matrix2d A = W.block<2, 2>(n + 1, n + 1);
      // the pair's local problem with the others fixed: w_t(x) = A (x - oldT) + w_t
      const Eigen::Vector2d b = A * oldT - Eigen::Vector2d(w[n + 1], w[n + 2]);
      const Eigen::Vector2d exact = tresca_disk_local(A, b, radius[i]);
      const Eigen::Vector2d newT = project_disk(oldT + omega * (exact - oldT), radius[i]);
      const Eigen::Vector2d delta = newT - oldT;
      if (delta[0] != 0.0 || delta[1] != 0.0) {
        r[n + 1] = newT[0];
        r[n + 2] = newT[1];
        w += W.col(n + 1) * delta[0] + W.col(n + 2) * delta[1];
      }
      change = std::max(change, delta.lpNorm<Eigen::Infinity>());
      size = std::max(size, newT.lpNorm<Eigen::Infinity>());
    }
    result.residual = (size > 0 ? change / size : change) / std::min(omega, 1.0);
    if (result.residual <= tol) {
      result.converged = true;
      break;
    }
    // (accepted at the sweeps' own tolerance: Newton's last steps are cheap, and the slip-threshold
    // fixed point around this needs its answers to better than its own tolerance)
    if (polish_every > 0 && result.iterations == next_polish) {
      ++result.polishes;
      if (polish_cone(W, q, g, tol, r, 15, coulomb_mu, polish_memory)) {
        if (coulomb_mu)
          for (Eigen::Index i = 0; i < m; ++i) radius[i] = (*coulomb_mu)[i] * r[3 * i];
        result.residual = cone_law_residual(W, q, radius, r);
        result.converged = true;
        break;
      }
      if (polish_wait < maxit) polish_wait *= 2;
      next_polish = result.iterations + polish_wait;
    }
  }
  return result;
}

struct ConeFixedPointResult {
  int iterations = 0, sweeps = 0;  // fixed-point iterations; PSOR sweeps in all
  double change = 0.0;             // the last relative change of the thresholds
  bool converged = false;
};

// Coulomb's cone |r_t| <= mu_i r_n by the scenes' slip-threshold fixed point (contact.idp
// ElasticContactSolve, in 3D): g = mu max(0, r_n) of the previous iterate, a warm-started Tresca
// solve (psor_cone), until max |g_new - g| <= slip_tol max |g_new|. Nodes with blocked tangential
// motion take mu = 0 (the caller passes 0 there).
inline ConeFixedPointResult coulomb_cone_fixed_point(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                                                     const Eigen::VectorXd& mu, double omega, double tol, int maxit,
                                                     double slip_tol, int slip_maxit, Eigen::VectorXd& r) {
  const Eigen::Index m = mu.size();
  if (r.size() != 3 * m) throw std::invalid_argument("coulomb_cone_fixed_point: r must have 3 entries per node");
  Eigen::VectorXd g(m), g_new(m);
  for (Eigen::Index i = 0; i < m; ++i) g[i] = mu[i] * std::max(0.0, r[3 * i]);
  ConeFixedPointResult result;
  while (result.iterations < slip_maxit) {
    ++result.iterations;
    const PsorResult sweeps = psor_cone(W, q, g, omega, tol, maxit, r);
    result.sweeps += sweeps.iterations;
    if (!sweeps.converged) return result;
    for (Eigen::Index i = 0; i < m; ++i) g_new[i] = mu[i] * std::max(0.0, r[3 * i]);
    const double size = std::max(0.0, g_new.maxCoeff());
    result.change = (g_new - g).lpNorm<Eigen::Infinity>() / (size > 0 ? size : 1.0);
    g = g_new;
    if (result.change <= slip_tol) {
      result.converged = true;
      break;
    }
  }
  return result;
}

}  // namespace sma
