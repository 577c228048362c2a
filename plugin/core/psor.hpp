// Projected SOR (projected Gauss-Seidel with over-relaxation) on a condensed contact problem:
// the paper's Signorini + Tresca sweeps ([58]-[60], docs/model.md#projected-sor), in the Delassus
// form of LMGC90's nonsmooth Gauss-Seidel.
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
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace sma {

namespace psor_detail {
// A number for a message, with its significant digits (std::to_string prints 1e-9 as 0.000000).
inline std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}
}  // namespace psor_detail

struct PsorResult {
  int iterations = 0;
  double residual = 0.0;  // max |r_new - r_old| / max(|r|, tiny), over the last sweep
  bool converged = false;
  int polishes = 0;       // polish attempts (psor_cone's)
};

// Natural-map residual of the contact laws: 0 exactly at a solution, scale-free.
inline double contact_law_residual(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                                   const Eigen::VectorXd& g, const Eigen::VectorXd& r) {
  const Eigen::VectorXd w = W * r - q;
  double worst = 0.0, scale = 0.0;
  for (Eigen::Index i = 0; i < g.size(); ++i) {
    const double rhoN = 1.0 / W(2 * i, 2 * i), wtt = W(2 * i + 1, 2 * i + 1);
    const double rn = std::max(0.0, r[2 * i] - rhoN * w[2 * i]);
    // W_tt = 0: a blocked tangential motion (g = 0, checked by psor_condensed), r_t must be 0.
    const double rt = wtt == 0.0 ? 0.0 : std::clamp(r[2 * i + 1] - (1.0 / wtt) * w[2 * i + 1], -g[i], g[i]);
    worst = std::max({worst, std::fabs(rn - r[2 * i]), std::fabs(rt - r[2 * i + 1])});
    scale = std::max({scale, std::fabs(r[2 * i]), std::fabs(r[2 * i + 1])});
  }
  return scale > 0 ? worst / scale : worst;
}

// Active-set polish (a primal-dual active-set, i.e. semismooth Newton, iteration started from the
// statuses of the PSOR iterate): per component, normal active if r_n - w_n / W_nn > 0 else
// separated (r_n = 0); tangential stuck if |r_t - w_t / W_tt| < g else sliding at +-g. The active
// components' equations w_k = 0 are solved exactly (dense LDLT, m is small), the statuses
// recomputed from the new iterate, until they repeat. Projected SOR finds the statuses roughly in
// a few sweeps but then converges linearly at a rate set by the conditioning of W (10^4 - 10^5
// sweeps for a ring's all-active Delassus operator); this finishes exactly. Accepted when the
// statuses are a fixed point and the contact laws hold (natural-map residual <= accept).
inline bool polish_active_set(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                              const Eigen::VectorXd& g, double accept, Eigen::VectorXd& r,
                              int max_rounds = 30) {
  const Eigen::Index n = r.size();
  Eigen::VectorXd candidate = r;
  std::vector<int> status(n, -2), previous;  // 0 fixed at 0, +-1 fixed at +-g, 2 active
  for (int round = 0; round < max_rounds; ++round) {
    const Eigen::VectorXd w = W * candidate - q;
    previous = status;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (W(k, k) == 0.0) { status[k] = 0; continue; }
      const double z = candidate[k] - w[k] / W(k, k);
      if (k % 2 == 0) status[k] = z > 0.0 ? 2 : 0;
      else {
        const double bound = g[k / 2];
        status[k] = std::fabs(z) < bound ? 2 : (bound == 0.0 ? 0 : (z > 0 ? 1 : -1));
      }
    }
    if (status == previous) break;
    std::vector<Eigen::Index> active;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (status[k] == 2) active.push_back(k);
      else candidate[k] = status[k] == 0 ? 0.0 : status[k] * g[k / 2];
    }
    const Eigen::Index a = (Eigen::Index)active.size();
    if (a == 0) continue;
    Eigen::VectorXd fixed = candidate;
    for (Eigen::Index i = 0; i < a; ++i) fixed[active[i]] = 0.0;
    const Eigen::VectorXd wfixed = W * fixed;
    Eigen::MatrixXd Waa(a, a);
    Eigen::VectorXd rhs(a);
    for (Eigen::Index i = 0; i < a; ++i) {
      rhs[i] = q[active[i]] - wfixed[active[i]];
      for (Eigen::Index j = 0; j < a; ++j) Waa(i, j) = W(active[i], active[j]);
    }
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(Waa);
    if (ldlt.info() != Eigen::Success) return false;
    const Eigen::VectorXd x = ldlt.solve(rhs);
    for (Eigen::Index i = 0; i < a; ++i) candidate[active[i]] = x[i];
  }
  if (status != previous || contact_law_residual(W, q, g, candidate) > accept) return false;
  r = candidate;
  return true;
}

// Runs PSOR sweeps from the given r (warm start) until the relative change of r over a sweep is
// <= tol or maxit sweeps; with polish_every > 0, an active-set polish is tried every that many
// sweeps and ends the sweeps when it solves the problem (converged, residual = its law residual).
// Throws on inconsistent input; never returns a silent non-answer: the caller reads `converged`,
// `iterations` and `residual`.
inline PsorResult psor_condensed(const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& g, double omega, double tol, int maxit,
                                 Eigen::VectorXd& r, int polish_every = 0) {
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
      throw std::invalid_argument("psor: Delassus tangential diagonal " + psor_detail::number(W(2 * i + 1, 2 * i + 1)) +
                                  " not positive at contact node " + std::to_string(i) + " with slip threshold " +
                                  psor_detail::number(g[i]) + " (a blocked tangential motion, W_tt = 0, needs threshold 0)");
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
    // Under-relaxed (omega < 1), a sweep moves r by omega times the Gauss-Seidel step: the change
    // is measured per unit relaxation, else a small omega stops at once on a change that only
    // looks small (-omega 1e-300: "converged" on the warm start). omega >= 1: the change itself.
    result.residual = (size > 0 ? change / size : change) / std::min(omega, 1.0);
    if (result.residual <= tol) {
      result.converged = true;
      break;
    }
    if (polish_every > 0 && result.iterations % polish_every == 0 &&
        polish_active_set(W, q, g, std::max(tol, 1e-8), r)) {
      result.residual = contact_law_residual(W, q, g, r);
      result.converged = true;
      break;
    }
  }
  return result;
}

}  // namespace sma
