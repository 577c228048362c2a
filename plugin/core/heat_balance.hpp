// The discrete heat balance of a time step (edp/problems/sleeve/time-loop.idp): the heat stored,
// capacity' (T1 - T0), against what entered through the boundary, what the source released and
// what the fractions' dissipation added; the scheme makes them equal to round-off.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace sma::heat_balance {

// capacity' (T1 - T0), summed from 0 in node order, each difference formed first: the script's
// `dT = T1 - T0; capacity' * dT` (FreeFEM's dot product) bit for bit.
inline double stored(const double* capacity, const double* T1, const double* T0, std::size_t n) {
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) sum += capacity[i] * (T1[i] - T0[i]);
  return sum;
}

// |stored - budget| / scale with budget = entered + released + dissipated and scale =
// max(|stored|, |entered| + |released| + dissipated) (dissipated >= 0, 0 without dissipation: the
// same bits as leaving it out); 0 when the scale is 0 (no heat moved, nothing to compare).
inline double relative_residual(double stored, double entered, double released, double dissipated) {
  const double budget = entered + released + dissipated;
  const double scale = std::max(std::fabs(stored), std::fabs(entered) + std::fabs(released) + dissipated);
  return scale > 0 ? std::fabs(stored - budget) / scale : 0.0;
}

}  // namespace sma::heat_balance
