// Pointwise phase projection of Frémond's shape-memory-alloy law (paper cases i-v,
// docs/model.md#thresholds).
//
// At a quadrature point with in-plane strain trace t, the local step of the DC algorithm picks
// sigma2 = s I in the subdifferential of phi2(e) = max(alpha |tr e| - c, 0)  [9].
// Equivalently it picks the phase of least free energy among
//     austenite: -c,   martensite 1: -alpha t,   martensite 2: +alpha t
// (the terms common to W0, W1, W2 cancel), and s = 0, +alpha, -alpha accordingly.
// Ties (t exactly on a threshold) admit any s between the two values; the rule kept here is:
// stay in the previous phase if it is one of the minimisers, otherwise take the first minimiser
// in the order austenite, martensite 1, martensite 2. This selection is a valid subgradient,
// is deterministic, and never flips a point that sits exactly on its threshold, which is what
// lets the DC loop stop on "no phase changed".
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "span.hpp"

namespace sma {

enum class Phase : int { Austenite = 0, Martensite1 = 1, Martensite2 = 2 };

inline double spherical_stress(Phase p, double alpha) {
  switch (p) {
    case Phase::Martensite1: return alpha;
    case Phase::Martensite2: return -alpha;
    default: return 0.0;
  }
}

// The phase of least energy at one point; `previous` breaks exact ties.
inline Phase project_phase(double trace, double alpha, double c, Phase previous) {
  if (!std::isfinite(trace) || !std::isfinite(alpha) || !std::isfinite(c))
    throw std::domain_error("project_phase: non-finite strain trace, alpha or c");
  const double energy[3] = {-c, -alpha * trace, alpha * trace};
  const double least = std::fmin(energy[0], std::fmin(energy[1], energy[2]));
  const int prev = static_cast<int>(previous);
  if (prev >= 0 && prev < 3 && energy[prev] == least) return previous;
  for (int p = 0; p < 3; ++p)
    if (energy[p] == least) return static_cast<Phase>(p);
  return Phase::Austenite;  // unreachable: one energy equals the least
}

// Projects every point. `phase` holds the previous phases on entry (as doubles 0, 1, 2, so
// that FreeFEM P0 arrays can carry them) and the new ones on exit; `s` receives sigma2 = s I.
// Returns how many points changed phase.
inline std::size_t project_phases(span<const double> trace, span<const double> alpha,
                                  span<const double> c, span<double> s, span<double> phase) {
  const std::size_t n = trace.size();
  if (alpha.size() != n || c.size() != n || s.size() != n || phase.size() != n)
    throw std::invalid_argument("project_phases: arrays of different lengths (trace " +
                                std::to_string(n) + ", alpha " + std::to_string(alpha.size()) +
                                ", c " + std::to_string(c.size()) + ", s " +
                                std::to_string(s.size()) + ", phase " +
                                std::to_string(phase.size()) + ")");
  std::size_t changed = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(alpha[i] >= 0.0))
      throw std::domain_error("project_phases: alpha < 0 at point " + std::to_string(i) +
                              " (alpha must be a(Tc - T) >= 0)");
    const Phase before = static_cast<Phase>(static_cast<int>(phase[i]));
    const Phase after = project_phase(trace[i], alpha[i], c[i], before);
    changed += (after != before);
    phase[i] = static_cast<double>(static_cast<int>(after));
    s[i] = spherical_stress(after, alpha[i]);
  }
  return changed;
}

// Fenchel conjugate of phi2 at sigma2 = s I (paper [49], completed for c < 0 where phi2 is
// alpha|t| - c everywhere and its conjugate is the constant c on [-alpha, alpha]).
// Returns +infinity outside the domain |s| <= alpha.
inline double phi2_conjugate(double s, double alpha, double c) {
  if (std::fabs(s) > alpha) return INFINITY;
  if (c < 0.0) return c;
  if (alpha == 0.0) return 0.0;  // domain is {0}
  return c / alpha * std::fabs(s);
}

// Sum over points of w_i (phi2*(s_i) - t_i s_i): the sigma2-dependent part of Auchmuty's
// Lagrangian L_II [45], [52].
inline double auchmuty_local_part(span<const double> trace, span<const double> alpha,
                                  span<const double> c, span<const double> s,
                                  span<const double> weight) {
  double sum = 0.0;
  for (std::size_t i = 0; i < trace.size(); ++i)
    sum += weight[i] * (phi2_conjugate(s[i], alpha[i], c[i]) - trace[i] * s[i]);
  return sum;
}

// Quadrature layout of the local step: one point per P1 triangle (weight = area),
// three mid-edge points per P2 triangle (weight = area / 3), in element-major order.
inline void quadrature_weights(span<const double> element_area, int points_per_element,
                               span<double> weight) {
  if (points_per_element != 1 && points_per_element != 3)
    throw std::invalid_argument("quadrature_weights: points_per_element must be 1 (P1) or 3 (P2), got " +
                                std::to_string(points_per_element));
  if (weight.size() != element_area.size() * static_cast<std::size_t>(points_per_element))
    throw std::invalid_argument("quadrature_weights: weight array has the wrong length");
  for (std::size_t k = 0; k < element_area.size(); ++k)
    for (int q = 0; q < points_per_element; ++q)
      weight[k * points_per_element + q] = element_area[k] / points_per_element;
}

}  // namespace sma
