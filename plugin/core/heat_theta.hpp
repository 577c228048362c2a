// The theta step's right-hand side and energy terms of the P1 heat problem (edp/solvers/heat.idp:
// HeatRhs, HeatEnergy), for the step solver's path (edp/solvers/dct.idp), where the script's
// twenty-odd array statements per step cost FreeFEM's interpreter more than the arithmetic:
//
//   rhs = [M T0 / dt - (1 - theta)(Kt T0 + G0 T0) + (1 - theta)(G0 Text0 + S0)
//          + theta (G1 Text1 + S1)] .* free + tgv TI .* imposed
//   boundary heat = dt [theta 1'G1 (Text1 - T1) + (1 - theta) 1'G0 (Text0 - T0)]
//                   (+ dt imposed' residual of the imposed nodes' own equations)
//   latent heat   = dt [theta 1'S1 + (1 - theta) 1'S0]
//
// with G = diag(g l) (nodal exchange coefficient times tributary length). Each statement of the
// script is done here in its own arithmetic and order (element by element, sums from 0 in index
// order), and the product Kt x is the caller's (the glue passes FreeFEM's own product), so the
// numbers are the script's bit for bit.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "span.hpp"

namespace sma {

// The heat problem's per-node arrays (heat.idp's heatCapacity, exchangeLength, imposedMask,
// heatFreeMask, heatTI and the step's boundary data heatG0/G1, heatText0/1).
struct HeatThetaArrays {
  span<const double> capacity, exchange_length, imposed, free_mask, imposed_temperature;
  span<const double> g0, g1, text0, text1;

  void check(std::size_t n) const {
    for (const span<const double>* a : {&capacity, &exchange_length, &imposed, &free_mask, &imposed_temperature, &g0,
                                        &g1, &text0, &text1})
      if (a->size() != n)
        throw std::invalid_argument("heat theta step: every heat array needs one value per node (" +
                                    std::to_string(n) + "), one has " + std::to_string(a->size()));
  }
};

// apply_conduction(x, y): y = Kt x. T0, S0, S1, rhs: one value per node.
template <class ApplyConduction>
void heat_theta_rhs(const HeatThetaArrays& h, double dt, double theta, double tgv, span<const double> t0,
                    span<const double> s0, span<const double> s1, ApplyConduction apply_conduction,
                    span<double> rhs) {
  const std::size_t n = t0.size();
  h.check(n);
  if (s0.size() != n || s1.size() != n || rhs.size() != n)
    throw std::invalid_argument("heat_theta_rhs: T0, S0, S1 and rhs need one value per node");
  if (n > 0 && rhs.begin() == t0.begin()) throw std::invalid_argument("heat_theta_rhs: rhs must not be T0");
  // Kt T0 into rhs, then each node's right side from it in place.
  apply_conduction(t0.begin(), rhs.begin());
  const double explicit_weight = 1 - theta;
  for (std::size_t i = 0; i < n; ++i) {
    const double g0 = h.g0[i] * h.exchange_length[i], g1 = h.g1[i] * h.exchange_length[i];
    double r = h.capacity[i] * t0[i];
    r /= dt;
    double work = rhs[i];  // (Kt T0)_i
    work += g0 * t0[i];
    r -= explicit_weight * work;
    double explicit_part = g0 * h.text0[i];
    explicit_part += s0[i];
    double implicit_part = g1 * h.text1[i];
    implicit_part += s1[i];
    r += explicit_weight * explicit_part;
    r += theta * implicit_part;
    r = r * h.free_mask[i];
    double pinned = tgv * h.imposed_temperature[i];
    pinned = pinned * h.imposed[i];
    rhs[i] = r + pinned;
  }
}

struct HeatStepEnergy {
  double boundary = 0, latent = 0;  // J per unit thickness over the step
};

// apply_conduction as above (called only when a node is imposed).
template <class ApplyConduction>
HeatStepEnergy heat_theta_energy(const HeatThetaArrays& h, double dt, double theta, span<const double> t0,
                                 span<const double> t1, span<const double> s0, span<const double> s1,
                                 ApplyConduction apply_conduction) {
  const std::size_t n = t0.size();
  h.check(n);
  if (t1.size() != n || s0.size() != n || s1.size() != n)
    throw std::invalid_argument("heat_theta_energy: T0, T1, S0 and S1 need one value per node");
  const double explicit_weight = 1 - theta;
  // The heat entering through the exchange at each end: G (Text - T), node by node.
  auto in0 = [&](std::size_t i) { return (h.g0[i] * h.exchange_length[i]) * (h.text0[i] - t0[i]); };
  auto in1 = [&](std::size_t i) { return (h.g1[i] * h.exchange_length[i]) * (h.text1[i] - t1[i]); };
  double sum0 = 0, sum1 = 0, source0 = 0, source1 = 0;
  bool any_imposed = false;
  for (std::size_t i = 0; i < n; ++i) {
    sum0 += in0(i);
    sum1 += in1(i);
    source0 += s0[i];
    source1 += s1[i];
    any_imposed = any_imposed || h.imposed[i] > 0;
  }
  HeatStepEnergy e;
  e.boundary = dt * (theta * sum1 + explicit_weight * sum0);
  e.latent = dt * (theta * source1 + explicit_weight * source0);
  if (any_imposed) {
    // The heat entering through the imposed nodes: the residual of their own (replaced) equations.
    std::vector<double> mid(n), conducted(n);
    for (std::size_t i = 0; i < n; ++i) {
      mid[i] = theta * t1[i];
      mid[i] += explicit_weight * t0[i];
    }
    apply_conduction(mid.data(), conducted.data());
    double imposed_sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double residual = h.capacity[i] * (t1[i] - t0[i]);
      residual /= dt;
      residual += conducted[i];
      double gained = theta * in1(i);
      gained += explicit_weight * in0(i);
      gained += theta * s1[i];
      gained += explicit_weight * s0[i];
      residual -= gained;
      imposed_sum += h.imposed[i] * residual;
    }
    e.boundary += dt * imposed_sum;
  }
  return e;
}

// Whether b holds a's values: the same size and every difference a_i - b_i zero (heat.idp's
// HeatPrepare: has the exchange or the imposed set changed since the last factorisation?). A NaN
// counts as a change (its difference is not zero), so the factorisation's check sees it.
inline bool same_values(span<const double> a, span<const double> b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a[i] - b[i] == 0)) return false;
  return true;
}

}  // namespace sma
