// Projected SOR (projected Gauss-Seidel with over-relaxation) on a condensed contact problem:
// the paper's Signorini + Tresca sweeps (§3.3, [58]-[60]), in the Delassus form of LMGC90's
// nonsmooth Gauss-Seidel.
//
// Unknowns: per contact node i, a normal reaction r_n >= 0 (the obstacle pushes) and a tangential
// reaction r_t, stored interleaved r = (r_n0, r_t0, r_n1, r_t1, ...). With the Delassus operator
// W = H K^-1 H' (symmetric positive definite) and q the free normal/tangential motion
// (normal: penetration of the free solution minus the gap; tangential: free slip), the local
// velocities are w = W r - q and the laws are
//   Signorini:  r_n >= 0,  w_n >= 0,  r_n w_n = 0
//   Tresca:     |r_t| <= g_i;  |r_t| < g_i => w_t = 0 (stick);  r_t = g_i => w_t <= 0;
//               r_t = -g_i => w_t >= 0; i.e. r_t = proj_[-g, g](r_t - rho w_t) for any rho > 0.
// Frictionless nodes have g_i = 0. A sweep updates each component in turn:
//   r_n <- max(0, r_n - omega w_n / W_nn),   r_t <- clamp(r_t - omega w_t / W_tt, -g, g).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sma {

struct PsorResult {
  int iterations = 0;
  double residual = 0.0;  // max |r_new - r_old| / max(|r|, tiny), over the last sweep
  bool converged = false;
};

// Natural-map residual of the contact laws: 0 exactly at a solution, scale-free.
inline double contact_law_residual(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                                   const Eigen::VectorXd& g, const Eigen::VectorXd& r) {
  const Eigen::VectorXd w = W * r - q;
  double worst = 0.0, scale = 0.0;
  for (Eigen::Index i = 0; i < g.size(); ++i) {
    const double rhoN = 1.0 / W(2 * i, 2 * i), rhoT = 1.0 / W(2 * i + 1, 2 * i + 1);
    const double rn = std::max(0.0, r[2 * i] - rhoN * w[2 * i]);
    const double rt = std::clamp(r[2 * i + 1] - rhoT * w[2 * i + 1], -g[i], g[i]);
    worst = std::max({worst, std::fabs(rn - r[2 * i]), std::fabs(rt - r[2 * i + 1])});
    scale = std::max({scale, std::fabs(r[2 * i]), std::fabs(r[2 * i + 1])});
  }
  return scale > 0 ? worst / scale : worst;
}

// Runs PSOR sweeps from the given r (warm start) until the relative change of r over a sweep is
// <= tol or maxit sweeps. Throws on inconsistent input; never returns a silent non-answer: the
// caller reads `converged`, `iterations` and `residual`.
inline PsorResult psor_condensed(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& g, double omega, double tol, int maxit,
                                 Eigen::VectorXd& r) {
  const Eigen::Index m = g.size();
  if (W.rows() != 2 * m || W.cols() != 2 * m || q.size() != 2 * m || r.size() != 2 * m)
    throw std::invalid_argument("psor: W must be 2m x 2m and q, r of length 2m for m = " +
                                std::to_string(m) + " contact nodes");
  if (!(omega > 0.0 && omega < 2.0))
    throw std::invalid_argument("psor: relaxation omega = " + std::to_string(omega) +
                                " must be in (0, 2)");
  if (!(tol >= 0.0)) throw std::invalid_argument("psor: tolerance must be >= 0");
  for (Eigen::Index i = 0; i < m; ++i) {
    if (!(g[i] >= 0.0))
      throw std::invalid_argument("psor: slip threshold g = " + std::to_string(g[i]) +
                                  " < 0 at contact node " + std::to_string(i));
    if (!(W(2 * i, 2 * i) > 0.0))
      throw std::invalid_argument("psor: Delassus normal diagonal not positive at contact node " +
                                  std::to_string(i) + " (is its normal motion blocked by a support?)");
    // A support may block the tangential motion (a node on a symmetry cut): W_tt = 0 is then
    // allowed with g = 0, and r_t stays 0.
    if (!(W(2 * i + 1, 2 * i + 1) > 0.0) && !(W(2 * i + 1, 2 * i + 1) == 0.0 && g[i] == 0.0))
      throw std::invalid_argument("psor: Delassus tangential diagonal not positive at contact node " +
                                  std::to_string(i) + " with slip threshold " + std::to_string(g[i]));
  }
  PsorResult result;
  Eigen::VectorXd w = W * r - q;  // kept up to date column by column
  while (result.iterations < maxit) {
    ++result.iterations;
    double change = 0.0, size = 0.0;
    for (Eigen::Index k = 0; k < 2 * m; ++k) {
      if (W(k, k) == 0.0) continue;  // blocked tangential motion (checked above)
      const double old = r[k];
      double updated = old - omega * w[k] / W(k, k);
      updated = (k % 2 == 0) ? std::max(0.0, updated) : std::clamp(updated, -g[k / 2], g[k / 2]);
      const double delta = updated - old;
      if (delta != 0.0) {
        r[k] = updated;
        w += W.col(k) * delta;
      }
      change = std::max(change, std::fabs(delta));
      size = std::max(size, std::fabs(updated));
    }
    result.residual = size > 0 ? change / size : change;
    if (result.residual <= tol) {
      result.converged = true;
      break;
    }
  }
  return result;
}

}  // namespace sma
