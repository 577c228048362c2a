// Random contact problems shared by the PSOR unit tests and the Siconos oracle, and random
// symmetric matrices of given eigenvalues (the cone's polish, the step solver's linearised law).
#pragma once

#include <Eigen/Dense>
#include <random>

namespace sma_test {

// A A' + n I with A of standard normal entries: symmetric positive definite, condition O(1).
inline Eigen::MatrixXd random_spd(int n, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j) = normal(rng);
  return A * A.transpose() + n * Eigen::MatrixXd::Identity(n, n);
}

// Q diag(eigenvalues) Q', Q the orthogonal factor of a matrix whose entries are drawn by
// entry(rng), row by row.
template <class Distribution>
inline Eigen::MatrixXd random_symmetric(const Eigen::VectorXd& eigenvalues, std::mt19937& rng, Distribution& entry) {
  const Eigen::Index n = eigenvalues.size();
  Eigen::MatrixXd A(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) A(i, j) = entry(rng);
  const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(A).householderQ();
  return Q * eigenvalues.asDiagonal() * Q.transpose();
}

// A Tresca problem on m contact nodes: Delassus operator W (random_spd, divided by 2m when
// `unit_scale`, so that its diagonal is about 2), free motion q ~ N(0, 1) per component,
// thresholds g ~ U(0, g_max) per node; drawn in that order.
struct TrescaProblem {
  Eigen::MatrixXd W;
  Eigen::VectorXd q, g;
};

inline TrescaProblem random_tresca(int m, double g_max, bool unit_scale, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, g_max);
  TrescaProblem p;
  p.W = random_spd(2 * m, rng);
  if (unit_scale) p.W /= 2 * m;
  p.q.resize(2 * m);
  p.g.resize(m);
  for (int k = 0; k < 2 * m; ++k) p.q[k] = normal(rng);
  for (int i = 0; i < m; ++i) p.g[i] = uniform(rng);
  return p;
}

}  // namespace sma_test
