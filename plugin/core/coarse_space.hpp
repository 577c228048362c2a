// A coarse space of smooth vectors over a large free block, the second level of a two-level right
// preconditioner for step_newton.hpp's GMRES (newton_direction). Off (StepSettings::coarse).
//
// Why it was built: on a fine mesh the linearised step of a wide, partly transformed front has a
// continuum of small eigenvalues (down to 3e-5 of the largest at 140 layers), which Ritz vectors of
// one solve do not span for the next (deflation.hpp); smooth vectors built from the mesh would, if
// those modes were smooth: (smoothed) piecewise-constant vectors on aggregates of neighbouring free
// points (points sharing a heat node through the interpolation's rows).
// Why it is off: they are not. On the scaling transient the slowest Ritz vectors have under 1 % of
// their D-norm in the coarse span (eigenstrains oscillating at the element scale, which P1
// displacements relax as well as smooth ones), and the coarse products made the solves dearer
// (docs/measurements.md#m-coarse-space). It does what it should where the slow modes are smooth
// (tests/unit/test_coarse_space.cpp: a grid Laplacian's GMRES products halved).
//
// The preconditioner: Q a D-orthonormal basis of the aggregates' vectors on the solve's points,
// E = Q' D A Q (symmetric part, eigenvalues mu, eigenvectors V), D = diag(q area) as in deflation.hpp,
//   P = I + Q G Q' D,   G = V (|mu|^-1 - 1) V'   (the coarse correction moving the coarse span's
// Rayleigh quotients to 1, the scale of A's laminate identity, and leaving the D-orthogonal
// complement as it is: P = (I - Q Q' D) + Q |E|^-1 Q' D, the additive two-level method whose fine
// level is the identity), or G = V |mu|^-1 V' (additive, P = I + Q |E|^-1 Q' D).
// Applying P costs no product: E needs A Q, computed once per linearisation (one product an
// aggregate, counted with the solver's products) and reused, restricted, by the later active-set
// rounds (their points are a subset: an approximate E only makes P less good, never the answer
// different, GMRES being right-preconditioned). P is self-adjoint and positive in D (|mu|), so A P
// has A's inertia: an unstable block still shows a negative Ritz value, P y of its Ritz vector y
// still a direction of negative curvature.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <vector>

#include "deflation.hpp"

namespace sma {

// Aggregates of the points `sub` (increasing): of[a] is the aggregate of sub[a], 0 .. count - 1.
struct Aggregates {
  std::vector<int> of;
  int count = 0;
};

// Greedy aggregation by breadth-first growth over the points' adjacency (two points are neighbours
// when they share a node: point_nodes is points x nodes by rows, node_points the same matrix by
// columns), each aggregate grown to `size` points from the first point not yet taken (in sub's
// order); an aggregate left below size / 2 (hemmed in by others) joins a neighbouring one.
template <class RowMajor, class ColMajor>
inline Aggregates aggregate_points(const RowMajor& point_nodes, const ColMajor& node_points,
                                   const std::vector<Eigen::Index>& sub, int size) {
  Aggregates out;
  const Eigen::Index k = (Eigen::Index)sub.size();
  out.of.assign((std::size_t)k, -1);
  if (k == 0 || size < 1) return out;
  std::vector<Eigen::Index> local((std::size_t)point_nodes.rows(), -1);
  for (Eigen::Index a = 0; a < k; ++a) local[(std::size_t)sub[(std::size_t)a]] = a;
  auto neighbours = [&](Eigen::Index a, auto visit) {
    for (typename RowMajor::InnerIterator node(point_nodes, sub[(std::size_t)a]); node; ++node)
      for (typename ColMajor::InnerIterator p(node_points, node.col()); p; ++p) {
        const Eigen::Index b = local[(std::size_t)p.row()];
        if (b >= 0 && b != a) visit(b);
      }
  };
  std::vector<int> members;
  std::vector<Eigen::Index> queue;
  for (Eigen::Index start = 0; start < k; ++start) {
    if (out.of[(std::size_t)start] >= 0) continue;
    const int id = out.count++;
    int taken = 1;
    out.of[(std::size_t)start] = id;
    queue.assign(1, start);
    for (std::size_t head = 0; head < queue.size() && taken < size; ++head)
      neighbours(queue[head], [&](Eigen::Index b) {
        if (taken < size && out.of[(std::size_t)b] < 0) out.of[(std::size_t)b] = id, ++taken, queue.push_back(b);
      });
    members.push_back(taken);
  }
  // Small aggregates join a neighbour (the first one found), then the ids are made consecutive.
  std::vector<int> joins((std::size_t)out.count);
  for (int c = 0; c < out.count; ++c) joins[(std::size_t)c] = c;
  for (Eigen::Index a = 0; a < k; ++a) {
    const int c = out.of[(std::size_t)a];
    if (2 * members[(std::size_t)c] >= size || joins[(std::size_t)c] != c) continue;
    neighbours(a, [&](Eigen::Index b) {
      const int d = joins[(std::size_t)out.of[(std::size_t)b]];
      if (joins[(std::size_t)c] == c && d != c) joins[(std::size_t)c] = d;
    });
  }
  std::vector<int> id((std::size_t)out.count, -1);
  int count = 0;
  for (int c = 0; c < out.count; ++c) {
    int r = c;
    for (int hops = 0; joins[(std::size_t)r] != r && hops < out.count; ++hops) r = joins[(std::size_t)r];
    if (id[(std::size_t)r] < 0) id[(std::size_t)r] = count++;
    id[(std::size_t)c] = id[(std::size_t)r];
  }
  for (auto& c : out.of) c = id[(std::size_t)c];
  out.count = count;
  return out;
}

// The coarse vectors on the points they were built on, and their images under the operator.
struct CoarseSpace {
  std::vector<Eigen::Index> points;  // increasing
  Eigen::MatrixXd vectors, images;   // points x vectors: z_j, A z_j
  int count = 0;
  bool empty() const { return count == 0; }
};

// The aggregates' indicator vectors on `sub`, smoothed `smooth` times by the averaging through
// the nodes, z <- (R R' z) ./ (R R' 1), R = point_nodes' rows at sub (a smoothed aggregation:
// each pass widens a vector by one ring of points and rounds its edges; the indicators' jumps
// between aggregates are eigenstrains no displacement relaxes, which left the plain indicators'
// Rayleigh quotients far above the front's small eigenvalues).
template <class RowMajor>
inline Eigen::MatrixXd coarse_vectors(const RowMajor& point_nodes, const std::vector<Eigen::Index>& sub,
                                      const Aggregates& agg, int smooth) {
  const Eigen::Index k = (Eigen::Index)sub.size();
  Eigen::MatrixXd z = Eigen::MatrixXd::Zero(k, agg.count);
  for (Eigen::Index a = 0; a < k; ++a) z(a, agg.of[(std::size_t)a]) = 1.0;
  if (smooth <= 0) return z;
  // The nodes of sub's points, numbered locally.
  std::vector<Eigen::Index> node_of((std::size_t)point_nodes.cols(), -1);
  Eigen::Index nodes = 0;
  for (Eigen::Index a = 0; a < k; ++a)
    for (typename RowMajor::InnerIterator e(point_nodes, sub[(std::size_t)a]); e; ++e)
      if (node_of[(std::size_t)e.col()] < 0) node_of[(std::size_t)e.col()] = nodes++;
  auto average = [&](const Eigen::MatrixXd& x) {
    Eigen::MatrixXd w = Eigen::MatrixXd::Zero(nodes, x.cols()), y = Eigen::MatrixXd::Zero(k, x.cols());
    for (Eigen::Index a = 0; a < k; ++a)
      for (typename RowMajor::InnerIterator e(point_nodes, sub[(std::size_t)a]); e; ++e)
        w.row(node_of[(std::size_t)e.col()]) += e.value() * x.row(a);
    for (Eigen::Index a = 0; a < k; ++a)
      for (typename RowMajor::InnerIterator e(point_nodes, sub[(std::size_t)a]); e; ++e)
        y.row(a) += e.value() * w.row(node_of[(std::size_t)e.col()]);
    return y;
  };
  const Eigen::VectorXd norm = average(Eigen::MatrixXd::Ones(k, 1)).col(0);
  for (int pass = 0; pass < smooth; ++pass) z = norm.cwiseInverse().asDiagonal() * average(z);
  return z;
}

// The coarse space of the vectors z (columns) on `sub`: one product (apply, on sub) per vector.
template <class Apply>
inline CoarseSpace build_coarse(const std::vector<Eigen::Index>& sub, const Eigen::MatrixXd& z, const Apply& apply) {
  CoarseSpace space;
  space.points = sub;
  space.vectors = z;
  space.count = (int)z.cols();
  space.images.resize(z.rows(), z.cols());
  for (Eigen::Index j = 0; j < z.cols(); ++j) space.images.col(j) = apply(Eigen::VectorXd(z.col(j)));
  return space;
}

// The two-level preconditioner on the points `sub` (increasing; weight: D on every point). Points of
// sub outside the space's get no coarse component; the images are the space's own, restricted.
inline DeflationPreconditioner coarse_on(const CoarseSpace& space, const std::vector<Eigen::Index>& sub,
                                         const Eigen::VectorXd& weight, bool additive = false) {
  DeflationPreconditioner p;
  if (space.empty() || sub.empty()) return p;
  const Eigen::Index k = (Eigen::Index)sub.size(), m = space.count;
  Eigen::MatrixXd z = Eigen::MatrixXd::Zero(k, m), az = Eigen::MatrixXd::Zero(k, m);
  p.weight.resize(k);
  std::size_t b = 0;
  for (Eigen::Index a = 0; a < k; ++a) {
    const Eigen::Index i = sub[(std::size_t)a];
    p.weight[a] = weight[i];
    while (b < space.points.size() && space.points[b] < i) ++b;
    if (b < space.points.size() && space.points[b] == i) {
      z.row(a) = space.vectors.row((Eigen::Index)b);
      az.row(a) = space.images.row((Eigen::Index)b);
    }
  }
  const Eigen::MatrixXd q = deflation_detail::orthonormal(z, p.weight, az);
  if (q.cols() == 0) return p;
  const Eigen::MatrixXd t = q.transpose() * p.weight.asDiagonal() * az;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (t + t.transpose()));
  const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
  Eigen::VectorXd shift(eig.eigenvalues().size());
  for (Eigen::Index i = 0; i < shift.size(); ++i)
    shift[i] = 1.0 / std::max(std::fabs(eig.eigenvalues()[i]), 1e-8 * std::max(largest, 1.0)) - (additive ? 0.0 : 1.0);
  p.q = q;
  p.g = eig.eigenvectors() * shift.asDiagonal() * eig.eigenvectors().transpose();
  return p;
}

}  // namespace sma
