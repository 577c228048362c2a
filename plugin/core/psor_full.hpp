// Projected SOR on the full stiffness system (the paper's own method, [58]-[60],
// docs/model.md#projected-sor):
// Gauss-Seidel with over-relaxation over every degree of freedom of K u = b, where the two dofs of
// each contact node are swept together in the node's (n, t) frame and projected:
//   normal:      u_n <- max(-gap, u_n - omega res_n / K_nn)             (Signorini: n.u + gap >= 0)
//   tangential:  u_t <- p + shrink(z - p, omega g / K_tt),  z = u_t - omega res_t / K_tt
// where res = K u - b, p = t.u at the previous load step (the slip is t.(u - u_previous): eq. [57]
// times dt), g the Tresca slip threshold (force), shrink(x, h) = sign(x) max(|x| - h, 0). With
// omega = 1 the tangential update is the exact minimiser of the node's energy plus g |slip|.
// The contact reactions are r = H (K u - b): r_n >= 0 pushes the ring off the pipe.
//
// Dirichlet rows are those FreeFEM marks by a huge diagonal (tgv, 1e30 by default): their dof is
// set to b_i / K_ii once and never swept, as plugin/seq/IncompleteCholesky.cpp in FreeFEM treats
// them. A contact node may have one blocked dof (a node on a symmetry cut): its normal must then be
// orthogonal to the blocked direction (the normal update moves along the free dof only) and its
// tangential motion is the support's business (r_t = 0 reported).
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "psor.hpp"
#include "span.hpp"

namespace sma {

// Compressed sparse rows, as FreeFEM's MatriceMorse stores them (row pointers of length n + 1).
struct CsrView {
  int n = 0;
  const int* row = nullptr;
  const int* col = nullptr;
  const double* val = nullptr;
  double at(int i, int j) const {
    for (int k = row[i]; k < row[i + 1]; ++k)
      if (col[k] == j) return val[k];
    return 0.0;
  }
  template <class T>
  double row_dot(int i, span<T> x) const {
    double s = 0.0;
    for (int k = row[i]; k < row[i + 1]; ++k) s += val[k] * x[col[k]];
    return s;
  }
};

// Contact nodes of a P1 x P1 displacement (dofs 2v, 2v+1 of vertex v), outward pipe normal n,
// tangent t = (-ny, nx), reference gap, slip threshold g >= 0 and t.u of the previous step.
struct ContactNodesView {
  span<const int> vertex;
  span<const double> nx, ny, gap, threshold, slip_reference;
};

struct FullPsorSettings {
  double omega = 1.88;
  double tol = 1e-10;             // on max |du| / max |u| over a sweep
  int maxit = 10000;
  double dirichlet_diagonal = 1e25;  // rows with K_ii >= this are Dirichlet (FreeFEM tgv = 1e30)
};

inline PsorResult psor_full(const CsrView& K, span<const double> b, const ContactNodesView& c,
                            const FullPsorSettings& set, span<double> u, span<double> rn,
                            span<double> rt) {
  const int n = K.n;
  const std::size_t m = c.vertex.size();
  if (b.size() != (std::size_t)n || u.size() != (std::size_t)n)
    throw std::invalid_argument("psor_full: b and u must have the matrix size " + std::to_string(n));
  if (c.nx.size() != m || c.ny.size() != m || c.gap.size() != m || c.threshold.size() != m ||
      c.slip_reference.size() != m || rn.size() != m || rt.size() != m)
    throw std::invalid_argument("psor_full: the contact arrays must all have " + std::to_string(m) +
                                " entries (one per contact node)");
  if (!(set.omega > 0.0 && set.omega < 2.0))
    throw std::invalid_argument("psor_full: relaxation omega = " + std::to_string(set.omega) +
                                " must be in (0, 2)");
  if (!(set.tol >= 0.0)) throw std::invalid_argument("psor_full: tolerance must be >= 0");

  std::vector<double> diag(n);
  std::vector<char> dirichlet(n);
  for (int i = 0; i < n; ++i) {
    diag[i] = K.at(i, i);
    if (!(diag[i] > 0.0))
      throw std::invalid_argument("psor_full: diagonal entry " + std::to_string(i) +
                                  " not positive: the matrix is not a stiffness matrix");
    dirichlet[i] = diag[i] >= set.dirichlet_diagonal;
    if (dirichlet[i]) u[i] = b[i] / diag[i];
  }
  // Per contact node: frame with blocked components removed, and the sweep order marker.
  std::vector<int> node_of_dof(n, -1);
  std::vector<double> nx(m), ny(m);
  std::vector<char> tangent_free(m);
  for (std::size_t i = 0; i < m; ++i) {
    const int v = c.vertex[i];
    if (v < 0 || 2 * v + 1 >= n)
      throw std::invalid_argument("psor_full: contact vertex " + std::to_string(v) + " out of range");
    if (!(c.threshold[i] >= 0.0))
      throw std::invalid_argument("psor_full: slip threshold < 0 at contact node " + std::to_string(i));
    node_of_dof[2 * v] = node_of_dof[2 * v + 1] = (int)i;
    nx[i] = c.nx[i];
    ny[i] = c.ny[i];
    const bool bx = dirichlet[2 * v], by = dirichlet[2 * v + 1];
    if (bx && by)
      throw std::invalid_argument("psor_full: contact node " + std::to_string(i) +
                                  " has both dofs blocked");
    if ((bx && std::fabs(nx[i]) > 1e-6) || (by && std::fabs(ny[i]) > 1e-6))
      throw std::invalid_argument("psor_full: contact node " + std::to_string(i) +
                                  " has a blocked dof along its normal (the support and the pipe"
                                  " push the same way)");
    if (bx) nx[i] = 0.0, ny[i] = ny[i] >= 0 ? 1.0 : -1.0;
    if (by) ny[i] = 0.0, nx[i] = nx[i] >= 0 ? 1.0 : -1.0;
    tangent_free[i] = !(bx || by);
  }

  PsorResult result;
  const double w = set.omega;
  while (result.iterations < set.maxit) {
    ++result.iterations;
    double change = 0.0, size = 0.0;
    for (int d = 0; d < n; ++d) {
      if (dirichlet[d]) continue;
      const int node = node_of_dof[d];
      if (node < 0) {
        const double delta = -w * (K.row_dot(d, u) - b[d]) / diag[d];
        u[d] += delta;
        change = std::max(change, std::fabs(delta));
        size = std::max(size, std::fabs(u[d]));
        continue;
      }
      const int v = c.vertex[node];
      if (d != 2 * v && !(d == 2 * v + 1 && dirichlet[2 * v])) continue;  // once per node
      const double kxx = diag[2 * v], kyy = diag[2 * v + 1], kxy = K.at(2 * v, 2 * v + 1);
      const double ax = nx[node], ay = ny[node], tx = -ay, ty = ax;
      double resx = K.row_dot(2 * v, u) - b[2 * v], resy = K.row_dot(2 * v + 1, u) - b[2 * v + 1];
      // Normal: along n (which has no component on a blocked dof).
      const double knn = ax * (kxx * ax + kxy * ay) + ay * (kxy * ax + kyy * ay);
      const double un = ax * u[2 * v] + ay * u[2 * v + 1];
      const double un_new = std::max(-c.gap[node], un - w * (ax * resx + ay * resy) / knn);
      const double dn = un_new - un;
      u[2 * v] += dn * ax;
      u[2 * v + 1] += dn * ay;
      resx += (kxx * ax + kxy * ay) * dn;
      resy += (kxy * ax + kyy * ay) * dn;
      double dt = 0.0;
      if (tangent_free[node]) {
        const double ktt = tx * (kxx * tx + kxy * ty) + ty * (kxy * tx + kyy * ty);
        const double ut = tx * u[2 * v] + ty * u[2 * v + 1];
        const double z = ut - w * (tx * resx + ty * resy) / ktt;
        const double p = c.slip_reference[node], h = w * c.threshold[node] / ktt;
        const double slip = z - p;
        const double ut_new = p + (slip > 0 ? 1.0 : -1.0) * std::max(std::fabs(slip) - h, 0.0);
        dt = ut_new - ut;
        u[2 * v] += dt * tx;
        u[2 * v + 1] += dt * ty;
      }
      change = std::max({change, std::fabs(dn), std::fabs(dt)});
      size = std::max({size, std::fabs(u[2 * v]), std::fabs(u[2 * v + 1])});
    }
    // Per unit relaxation below omega = 1 (psor.hpp says why).
    result.residual = (size > 0 ? change / size : change) / std::min(w, 1.0);
    if (result.residual <= set.tol) {
      result.converged = true;
      break;
    }
  }
  for (std::size_t i = 0; i < m; ++i) {
    const int v = c.vertex[i];
    const double resx = K.row_dot(2 * v, u) - b[2 * v], resy = K.row_dot(2 * v + 1, u) - b[2 * v + 1];
    rn[i] = nx[i] * resx + ny[i] * resy;
    rt[i] = tangent_free[i] ? -ny[i] * resx + nx[i] * resy : 0.0;
  }
  return result;
}

}  // namespace sma
