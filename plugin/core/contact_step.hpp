// One global step of the DC loop with the condensed contact problem (edp/solvers/contact.idp,
// mode "condensed"), in one call: the script's version spent more time in its per-node loops than
// in the back-solves it wrapped (docs/benchmarks.md).
//
//   u = K^-1 (rhs + S H' r0), r0 the warm start (S = diag(free))
//   H u_free = H u - W r0
//   q_n = -(n.u_free + gap),  q_t = -(t.u_free - t.u_previous) where the node may slide, else 0
//   r = PSOR on the Delassus problem w = W r - q (psor.hpp; from r0, in/out)
//   u += K^-1 S H' (r - r0) when r != r0
// One back-solve when the reactions do not change beyond the sweeps' tolerance (the warm start was
// the answer: an all-austenite step), two otherwise, as u_free then u would take.
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
  Eigen::Map<Eigen::VectorXd> uu(u.begin(), n);
  Eigen::Map<const Eigen::VectorXd> b(rhs.begin(), n);
  const Eigen::VectorXd r0 = r;
  const bool warm = r0.lpNorm<Eigen::Infinity>() > 0;
  if (warm)
    uu = k.solve(Eigen::MatrixXd(b + c.free.cwiseProduct(c.h.transpose() * r0)));
  else
    k.solve(rhs, u);
  Eigen::VectorXd hu = c.h * uu;
  if (warm) hu -= c.w * r0;  // H u_free
  Eigen::VectorXd q(2 * m), g(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    q[2 * i] = -(hu[2 * i] + gap[i]);
    q[2 * i + 1] = tangent_free[i] != 0 ? -(hu[2 * i + 1] - slip_reference[i]) : 0.0;
    g[i] = threshold[i];
  }
  const PsorResult res = psor_condensed(c.w, q, g, settings.omega, settings.tol, settings.maxit, r, settings.polish);
  // A change of the reactions within the sweeps' own tolerance is round-off of the warm start (an
  // all-austenite step recomputes the same reactions): r is kept at r0, which the sweeps could not
  // tell from their answer, and u needs no second back-solve.
  const Eigen::VectorXd dr = r - r0;
  const double change = dr.lpNorm<Eigen::Infinity>();
  if (warm && change <= settings.tol * r.lpNorm<Eigen::Infinity>())
    r = r0;
  else if (change > 0)
    uu += k.solve(Eigen::MatrixXd(c.free.cwiseProduct(c.h.transpose() * dr)));
  return res;
}

}  // namespace sma
