// FreeFEM's dense matrices (real[int,int]) to and from Eigen's, entry by entry: the glue's
// conversions of W, a compliance and the like (solvers.cpp, law.cpp).
#ifndef SMA_GLUE_DENSE_HPP
#define SMA_GLUE_DENSE_HPP

#include <Eigen/Dense>

#include "glue/glue.hpp"

namespace sma_glue {

inline Eigen::MatrixXd DenseOf(KNM<double>* a) {
  Eigen::MatrixXd m(a->N(), a->M());
  for (long i = 0; i < a->N(); ++i)
    for (long j = 0; j < a->M(); ++j) m(i, j) = (*a)(i, j);
  return m;
}

// a = m, a resized to m's size.
inline void SetDense(KNM<double>* a, const Eigen::MatrixXd& m) {
  a->resize(m.rows(), m.cols());
  for (long i = 0; i < m.rows(); ++i)
    for (long j = 0; j < m.cols(); ++j) (*a)(i, j) = m(i, j);
}

}  // namespace sma_glue

#endif
