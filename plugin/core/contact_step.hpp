// One global step of the DC loop with the condensed contact problem (edp/solvers/contact.idp,
// mode "condensed"), in one call: the script's version spent more time in its per-node loops than
// in the back-solves it wrapped (docs/benchmarks.md).
//
//   z = L^-1 P rhs                                    (forward half of u_free = K^-1 rhs)
//   H S u_free = (D^-1 Y)' z                          (Y = L^-1 P S H': delassus_factor, which
//                                                      holds all the step needs of H and S)
//   q_n = -(n.u_free + gap),  q_t = -(t.u_free - t.u_previous) where the node may slide, else 0
//   r = PSOR on the Delassus problem w = W r - q (psor.hpp; r is the warm start, in/out)
//   u = P' L^-T D^-1 (z + Y r) = K^-1 (rhs + S H' r)  (backward half; S = diag(free))
// One forward and one backward solve per step, whatever r: the cost of one back-solve. (Before,
// u_free = K^-1 rhs and u = K^-1 (rhs + S H' r): two back-solves whenever some r != 0.)
#pragma once

#include <Eigen/Dense>
#include <stdexcept>
#include <string>

#include "psor.hpp"
#include "psor_cone.hpp"
#include "sparse_spd.hpp"
#include "span.hpp"

namespace sma {

// H S K^-1 b on every contact row, from z = L^-1 P b (SpdFactor::forward): the rows Y stands
// for; the others (tangential rows of a frictionless problem, whose W rows are 0 and r_t stays 0)
// are 0. Columns the caller keeps (DelassusFactor::caller_columns): its product, C' z.
inline Eigen::VectorXd contact_motion(const DelassusFactor& d, const Eigen::VectorXd& z) {
  Eigen::VectorXd motion;
  if (d.caller_columns) {
    if (!d.motion) throw std::logic_error("a contact problem whose columns the caller keeps, used with no product bound to it");
    motion.resize((Eigen::Index)d.rows.size());
    d.motion(z, span<double>(motion.data(), (std::size_t)motion.size()));
  } else {
    motion = d.y_scaled.transpose() * z;
  }
  Eigen::VectorXd hu = Eigen::VectorXd::Zero(d.w.rows());
  for (std::size_t j = 0; j < d.rows.size(); ++j) hu[d.rows[j]] = motion[(Eigen::Index)j];
  return hu;
}

// The Delassus problem's free motion from H S u_free: q_n = -(n.u_free + gap),
// q_t = -(t.u_free - t.u_previous) where the node may slide, else 0.
inline Eigen::VectorXd contact_free_motion(const DelassusFactor& d, const Eigen::VectorXd& hu, span<const double> gap,
                                           span<const double> slip_reference, span<const double> tangent_free) {
  const Eigen::Index m = (Eigen::Index)gap.size();
  Eigen::VectorXd q(2 * m);
  for (Eigen::Index i = 0; i < m; ++i) {
    q[2 * i] = -(hu[2 * i] + gap[i]);
    q[2 * i + 1] = tangent_free[i] != 0 && d.w(2 * i + 1, 2 * i + 1) != 0.0 ? -(hu[2 * i + 1] - slip_reference[i]) : 0.0;
  }
  return q;
}

// z += Y r (the rows Y stands for), so that SpdFactor::backward(z) is K^-1 (b + S H' r); nothing
// when r = 0.
inline void add_contact_load(const DelassusFactor& d, const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  if (!(r.lpNorm<Eigen::Infinity>() > 0)) return;
  Eigen::VectorXd reactions((Eigen::Index)d.rows.size());
  for (std::size_t j = 0; j < d.rows.size(); ++j) reactions[(Eigen::Index)j] = r[d.rows[j]];
  z += d.y * reactions;
}

// add_contact_load for a caller that adds many loads (the step solver's products): the columns
// of Y whose reaction is nonzero only, summed in the caller's work vector (n) and added to z, as
// Eigen evaluates z += Y r (a zeroed temporary, then added): the same bits, no allocation.
inline void add_contact_load_sparse(const DelassusFactor& d, const Eigen::VectorXd& r, Eigen::VectorXd& z,
                                    Eigen::VectorXd& work) {
  if (!(r.lpNorm<Eigen::Infinity>() > 0)) return;
  work.setZero(z.size());
  // Through raw pointers: a store through work[] could alias the vectors' own members, which the
  // loop would otherwise reload at every term.
  double* const sum = work.data();
  const double* const reaction = r.data();
  const int* const outer = d.y.outerIndexPtr();
  const int* const inner = d.y.innerIndexPtr();
  const double* const value = d.y.valuePtr();
  const std::size_t columns = d.rows.size();
  for (std::size_t j = 0; j < columns; ++j) {
    const double rj = reaction[d.rows[j]];
    if (rj == 0.0) continue;  // its terms are exact zeros, which leave the (+0 started) sums as they are
    #pragma GCC unroll 8
    for (int e = outer[j], end = outer[j + 1]; e < end; ++e) sum[inner[e]] += value[e] * rj;
  }
  z += work;
}

// The entry of contact_motion(d, z) at contact row `row` (column j of Y standing for it, -1 for
// none: 0), as Eigen's product forms it (a sum from 0, added to 0).
inline double contact_motion_at(const DelassusFactor& d, int column, const Eigen::VectorXd& z) {
  if (column < 0) return 0.0;
  const int* const inner = d.y_scaled.innerIndexPtr();
  const double* const value = d.y_scaled.valuePtr();
  const double* const zz = z.data();
  double t = 0.0;
  #pragma GCC unroll 8
  for (int e = d.y_scaled.outerIndexPtr()[column], end = d.y_scaled.outerIndexPtr()[column + 1]; e < end; ++e)
    t += value[e] * zz[inner[e]];
  return 0.0 + 1.0 * t;
}

struct ContactStepSettings {
  double omega = 1.88, tol = 1e-10;
  int maxit = 100000, polish = 10;
};

// Per node i: gap[i], threshold[i] (Tresca g), slip_reference[i] (t.u at the step's start),
// tangent_free[i] (0 where a support blocks the tangential motion). d: the contact problem's
// Delassus operator and factor (delassus_factor, on k). u receives the solution.
inline PsorResult condensed_global_step(const SpdFactor& k, const DelassusFactor& d, span<const double> rhs,
                                        span<const double> gap, span<const double> threshold,
                                        span<const double> slip_reference, span<const double> tangent_free,
                                        const ContactStepSettings& settings, Eigen::VectorXd& r, span<double> u) {
  const Eigen::Index m = (Eigen::Index)gap.size(), n = k.size();
  if (d.w.rows() != 2 * m || d.y.rows() != n)
    throw std::invalid_argument("the contact problem has " + std::to_string(d.w.rows() / 2) + " nodes and " +
                                std::to_string(d.y.rows()) + " dofs, the step " + std::to_string(m) + " and " +
                                std::to_string(n));
  if ((Eigen::Index)threshold.size() != m || (Eigen::Index)slip_reference.size() != m ||
      (Eigen::Index)tangent_free.size() != m || r.size() != 2 * m)
    throw std::invalid_argument("per-node data of unequal lengths");
  Eigen::VectorXd z = k.forward(rhs);
  const Eigen::VectorXd q = contact_free_motion(d, contact_motion(d, z), gap, slip_reference, tangent_free);
  const Eigen::VectorXd g = Eigen::Map<const Eigen::VectorXd>(threshold.begin(), m);
  const PsorResult res = psor_condensed(d.w, q, g, settings.omega, settings.tol, settings.maxit, r, settings.polish);
  add_contact_load(d, r, z);
  k.backward(z, u);
  return res;
}

// The cone's free motion from H S u_free (three rows per node): q_n = -(n.u_free + gap),
// q_tc = -(tc.u_free - slip_reference[2i + c - 1]) for c = 1, 2, 0 where a support blocks the
// component (its Delassus diagonal 0).
inline Eigen::VectorXd cone_free_motion(const DelassusFactor& d, const Eigen::VectorXd& hu, span<const double> gap,
                                        span<const double> slip_reference) {
  const Eigen::Index m = (Eigen::Index)gap.size();
  Eigen::VectorXd q(3 * m);
  for (Eigen::Index i = 0; i < m; ++i) {
    q[3 * i] = -(hu[3 * i] + gap[i]);
    for (int c = 1; c <= 2; ++c)
      q[3 * i + c] = d.w(3 * i + c, 3 * i + c) != 0.0 ? -(hu[3 * i + c] - slip_reference[2 * i + c - 1]) : 0.0;
  }
  return q;
}

// The 3D contact step (psor_cone.hpp): three rows per node (n, t1, t2) in d, its Delassus operator
// formed on all of them; per node i: gap[i], threshold[i] (the Tresca disk's radius),
// slip_reference[2i], [2i + 1] (t1.u and t2.u at the stage's start). The free motion
// q = (-(n.u_free + gap), -(t1.u_free - ref1), -(t2.u_free - ref2)), a tangential row whose motion
// a support blocks (its Delassus diagonal 0) taking q = 0; then the sweeps, and u as
// condensed_global_step's: one forward and one backward solve.
// coulomb_mu (m values): Coulomb's cone at once (psor_cone's), threshold the radius to start from.
inline PsorResult condensed_cone_step(const SpdFactor& k, const DelassusFactor& d, span<const double> rhs,
                                      span<const double> gap, span<const double> threshold,
                                      span<const double> slip_reference, const ContactStepSettings& settings,
                                      Eigen::VectorXd& r, span<double> u, const Eigen::VectorXd* coulomb_mu = nullptr) {
  const Eigen::Index m = (Eigen::Index)gap.size(), n = k.size();
  if (d.w.rows() != 3 * m || d.y.rows() != n || (Eigen::Index)d.rows.size() != 3 * m)
    throw std::invalid_argument("the cone's contact problem has " + std::to_string(d.w.rows()) + " rows (all formed: " +
                                std::to_string(d.rows.size()) + ") and " + std::to_string(d.y.rows()) + " dofs, the step " +
                                std::to_string(m) + " nodes (3 rows each) and " + std::to_string(n) + " dofs");
  if ((Eigen::Index)threshold.size() != m || (Eigen::Index)slip_reference.size() != 2 * m || r.size() != 3 * m)
    throw std::invalid_argument("per-node data of unequal lengths (threshold m, slip reference 2m, r 3m)");
  Eigen::VectorXd z = k.forward(rhs);
  const Eigen::VectorXd q = cone_free_motion(d, contact_motion(d, z), gap, slip_reference);
  const Eigen::VectorXd g = Eigen::Map<const Eigen::VectorXd>(threshold.begin(), m);
  const PsorResult res = psor_cone(d.w, q, g, settings.omega, settings.tol, settings.maxit, r, settings.polish, coulomb_mu);
  add_contact_load(d, r, z);
  k.backward(z, u);
  return res;
}

}  // namespace sma
