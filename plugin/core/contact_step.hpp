// One global step of the DC loop with the condensed contact problem (edp/solvers/contact.idp,
// mode "condensed"), in one call: the script's version spent more time in its per-node loops than
// in the back-solves it wrapped (docs/benchmarks.md).
//
//   u_free = K^-1 rhs
//   q_n = -(n.u_free + gap),  q_t = -(t.u_free - t.u_previous) where the node may slide, else 0
//   r = PSOR on the Delassus problem w = W r - q (psor.hpp; r is the warm start, in/out)
//   u = K^-1 (rhs + S H' r) when some r != 0, else u_free   (S = diag(free))
#pragma once

#include <Eigen/Dense>
#include <stdexcept>
#include <string>

#include "psor.hpp"
#include "sparse_spd.hpp"
#include "span.hpp"

namespace sma {

// The contact rows H (2m x n: (n.u, t.u) per node), the free-dof mask and the Delassus operator
// W = H S K^-1 S H' (delassus()) of one contact problem.
struct CondensedContact {
  SparseMatrix h;
  Eigen::VectorXd free;
  Eigen::MatrixXd w;
};

struct ContactStepSettings {
  double omega = 1.88, tol = 1e-10;
  int maxit = 100000, polish = 10;
};

// Per node i: gap[i], threshold[i] (Tresca g), slip_reference[i] (t.u at the step's start),
// tangent_free[i] (0 where a support blocks the tangential motion). u receives the solution.
inline PsorResult condensed_global_step(const SpdFactor& k, const CondensedContact& c, span<const double> rhs,
                                        span<const double> gap, span<const double> threshold,
                                        span<const double> slip_reference, span<const double> tangent_free,
                                        const ContactStepSettings& settings, Eigen::VectorXd& r, span<double> u) {
  const Eigen::Index m = (Eigen::Index)gap.size(), n = k.size();
  if (c.h.rows() != 2 * m || c.h.cols() != n || c.w.rows() != 2 * m || c.free.size() != n)
    throw std::invalid_argument("the contact problem has " + std::to_string(c.h.rows() / 2) + " nodes and " +
                                std::to_string(c.h.cols()) + " dofs, the step " + std::to_string(m) + " and " +
                                std::to_string(n));
  if ((Eigen::Index)threshold.size() != m || (Eigen::Index)slip_reference.size() != m ||
      (Eigen::Index)tangent_free.size() != m || r.size() != 2 * m)
    throw std::invalid_argument("per-node data of unequal lengths");
  k.solve(rhs, u);
  Eigen::Map<Eigen::VectorXd> uu(u.begin(), n);
  const Eigen::VectorXd hu = c.h * uu;
  Eigen::VectorXd q(2 * m), g(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    q[2 * i] = -(hu[2 * i] + gap[i]);
    q[2 * i + 1] = tangent_free[i] != 0 ? -(hu[2 * i + 1] - slip_reference[i]) : 0.0;
    g[i] = threshold[i];
  }
  const PsorResult res = psor_condensed(c.w, q, g, settings.omega, settings.tol, settings.maxit, r, settings.polish);
  if (r.lpNorm<Eigen::Infinity>() > 0) {
    Eigen::Map<const Eigen::VectorXd> b(rhs.begin(), n);
    const Eigen::VectorXd loaded = b + c.free.cwiseProduct(c.h.transpose() * r);
    k.solve(span<const double>(loaded.data(), (std::size_t)n), u);
  }
  return res;
}

}  // namespace sma
