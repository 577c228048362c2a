// The fraction model's step record after the step solver (edp/solvers/dct.idp, newton path): what
// the script computed in six statements and four function calls after each step, each costing
// FreeFEM's interpreter thousands of instructions, every step:
//   b     = |chi|                                  (the latent fraction of each point)
//   load  = Q ((b - bStart) rho L / dt)            (the step's latent heat as nodal loads)
//   s     = alpha(Interp T) chi                    (the phase stress at the step's end)
//   bStart = b                                     (the next step's load starts from it)
// The two sparse products are the caller's (the glue passes FreeFEM's own matrix-vector product,
// so that the sums run in FreeFEM's order and the numbers are those of the script, bit for bit);
// the rest is element by element, in the script's arithmetic.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "material.hpp"
#include "span.hpp"

namespace sma {

// Whether the law's alpha is finite and >= 0 (not -0) at any interpolation (weights at most 1 in
// size, as a P1 -> P0 one's) of these nodal temperatures: rho a > 0 and every |T|, |Tc| and rho a
// at most 1e100, so that rho a (Tc - T) cannot overflow (a NaN temperature: no).
inline bool alpha_finite_at(const ThermalLaw& law, span<const double> temperature) {
  const double bound = 1e100, rho_a = law.rho * law.a;
  if (!(rho_a > 0 && rho_a <= bound && std::abs(law.Tc) <= bound)) return false;
  return std::all_of(temperature.begin(), temperature.end(), [bound](double t) { return std::abs(t) <= bound; });
}

// apply_latent(x, y): y = Q x (nodes from points); apply_interp(x, y): y = Interp x (points from
// nodes). latent_rate = rho L / dt. chi, b_start, stress: one value per point; temperature, load:
// one per heat node.
template <class ApplyLatent, class ApplyInterp>
void fraction_step_record(const ThermalLaw& law, double latent_rate, span<const double> chi,
                          span<double> b_start, span<const double> temperature, ApplyLatent apply_latent,
                          ApplyInterp apply_interp, span<double> load, span<double> stress) {
  law.validate();
  const std::size_t n = chi.size();
  if (b_start.size() != n || stress.size() != n)
    throw std::invalid_argument("fraction_step_record: chi, b_start and stress need one value per point");
  if (load.size() != temperature.size())
    throw std::invalid_argument("fraction_step_record: load and temperature need one value per heat node");
  std::vector<double> change(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double b = std::abs(chi[i]);
    change[i] = (b - b_start[i]) * latent_rate;  // dchi = b - bStart; dchi *= rho L / dt
    b_start[i] = b;
  }
  // (no change, the whole tail of a run: Q 0 is +0 everywhere, the product's every sum of exact
  // zeros started at +0)
  if (std::any_of(change.begin(), change.end(), [](double c) { return c != 0.0; }))
    apply_latent(change.data(), load.begin());
  else
    std::fill(load.begin(), load.end(), 0.0);
  // (every chi zero, the whole tail of a run again: s = alpha chi is chi itself, a zero of chi's
  // sign, wherever alpha is finite and not negative. The law's alpha, rho a (Tc - T) below Tc and
  // +0 above, is so at every point when rho a > 0 and the nodes' temperatures are finite and
  // bounded, an interpolation's weights being at most 1 in size: then no interpolation.)
  if (std::all_of(chi.begin(), chi.end(), [](double x) { return x == 0.0; }) &&
      alpha_finite_at(law, temperature)) {
    std::copy(chi.begin(), chi.end(), stress.begin());
    return;
  }
  std::vector<double> at_points(n);
  apply_interp(temperature.begin(), at_points.data());
  for (std::size_t i = 0; i < n; ++i) stress[i] = law.alpha(at_points[i]) * chi[i];
}

// The area fractions [austenite, martensite 1, martensite 2] of signed martensite fractions chi
// over points of the given areas (edp/solvers/dct.idp FractionsOfChi), in the script's arithmetic:
// |chi|, chi + |chi| (2 chi where chi > 0) and |chi| - chi (-2 chi where chi < 0) each dotted with
// the areas, summed in the points' order, over the areas' sum.
inline void area_fractions(span<const double> chi, span<const double> area, double fractions[3]) {
  if (area.size() != chi.size()) throw std::invalid_argument("area_fractions: one area per point");
  double total = 0, latent = 0, m1 = 0, m2 = 0;
  for (std::size_t i = 0; i < area.size(); ++i) total += area[i];
  for (std::size_t i = 0; i < chi.size(); ++i) {
    const double b = std::abs(chi[i]);
    m1 += area[i] * (chi[i] + b);
    m2 += area[i] * (b - chi[i]);
    latent += area[i] * b;
  }
  fractions[1] = 0.5 * m1 / total;
  fractions[2] = 0.5 * m2 / total;
  fractions[0] = 1. - latent / total;
}

// The phase labels of signed martensite fractions chi for the output fields (edp/solvers/dct.idp
// PhaseLabelsOfChi): 1 martensite 1 (chi > 0), 2 martensite 2 (chi < 0), 0 austenite (chi = 0, and
// a NaN, as the script's chi > 0 ? 1 : (chi < 0 ? 2 : 0) gave), one per point.
inline void phase_labels(span<const double> chi, span<double> labels) {
  if (labels.size() != chi.size()) throw std::invalid_argument("phase_labels: one label per point");
  for (std::size_t i = 0; i < chi.size(); ++i) labels[i] = chi[i] > 0 ? 1. : (chi[i] < 0 ? 2. : 0.);
}

// The step solver's data array (plugin/glue/step.cpp StepSolveFraction, n points, `nodes` heat nodes,
// `dofs` displacement dofs): [area | kappa | threshold offset | chi at the step's start | b at the
// step's start | heat right side | heat free mask | force | free dofs], segments of n, n, n, n, n,
// nodes, nodes, dofs, dofs values. Writes the five a step changes (chi, b, the heat right side, its
// mask, the force: copies, bit for bit); the others stay as the run's first step set them.
inline void set_step_data(span<double> data, span<const double> chi, span<const double> b,
                          span<const double> heat_rhs, span<const double> heat_mask, span<const double> force) {
  const std::size_t n = chi.size(), nodes = heat_rhs.size(), dofs = force.size();
  if (b.size() != n || heat_mask.size() != nodes || data.size() != 5 * n + 2 * nodes + 2 * dofs)
    throw std::invalid_argument("set_step_data: the data array holds " + std::to_string(data.size()) +
                                " values, not 5 x " + std::to_string(n) + " points + 2 x " +
                                std::to_string(nodes) + " heat nodes + 2 x " + std::to_string(dofs) +
                                " dofs, or b and the heat mask are not of the points' and nodes' sizes");
  double* out = data.begin();
  auto put = [&out](span<const double> segment, std::size_t at) {
    std::copy(segment.begin(), segment.end(), out + at);
  };
  put(chi, 3 * n);
  put(b, 4 * n);
  put(heat_rhs, 5 * n);
  put(heat_mask, 5 * n + nodes);
  put(force, 5 * n + 2 * nodes);
}

}  // namespace sma
