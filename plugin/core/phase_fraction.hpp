// The local step with martensite fractions (-phasemodel fraction):
// Frémond's law with the phase state a signed fraction chi in [-1, 1] per quadrature point,
// chi > 0 martensite 1 of fraction chi, chi < 0 martensite 2 of fraction -chi, the rest austenite;
// sigma2 = s I with s = alpha chi.
//
// Why fractions: the on/off local step (phase_projection.hpp) cannot represent a point sitting on
// its threshold half transformed, which is where a point heated through its transformation
// temperature spends the time its latent heat takes to arrive: an on/off point flips whole,
// absorbs (or releases) all its latent heat at once, overshoots its threshold the other way and
// flips back (the chatter of docs/stability.md). The paper's own local step allows any s in
// [0, alpha] on the threshold (cases iv-v); which one is fixed by the heat balance.
//
// At one point, with strain trace t, the step solves the enthalpy-regularised local problem
//   min over chi in [-1, 1] of  -alpha t chi + c |chi| + D/2 (|chi| - b)^2
// where b is the martensite fraction the last heat solve saw (its latent heat is in T already)
// and D = -(d/dT)(alpha |t| - c) kappa = (rho a |t| [T < Tc] + rho L / T0) kappa is the local
// heat balance linearised: changing |chi| by db moves the point's temperature by kappa db
// (kappa in K per unit fraction, the local response of the heat solve to the point's latent
// heat), which moves its driving force alpha |t| - c by -D db. The minimiser is explicit:
//   |chi| = clamp(b + (alpha |t| - c) / D, 0, 1),  sign(chi) = sign(t)
// (t = 0: the previous sign, martensite 1 from austenite). It is the Frémond projection at the
// temperature the point would reach with its own latent heat: once the heat solve is redone with
// b = |chi| (the heat <-> phases fixed point, edp/solvers/dct.idp) the D term vanishes and
//   0 < |chi| < 1  =>  alpha |t| = c  (the point on its threshold, cases iv-v),
//   |chi| = 1      =>  alpha |t| >= c,    chi = 0  =>  alpha |t| <= c,
// exactly Frémond's complementarity at the converged temperature, whatever kappa > 0.
// Laminate (laminate = lambda + 2 mu > 0, what the scenes pass): without it a partial P1 point is
// mechanically unstable (its own eigenstrain change moves its uniform trace by about
// alpha / (lambda + 2 mu) per unit fraction, more than its heat balance holds once a step's heat
// spreads over several elements) and snaps whole. A partly transformed point is a laminate of
// its two phases instead, whose strain jump alpha / (lambda + 2 mu) n n relaxes
// q = alpha^2 / (lambda + 2 mu); each lamella keeps Frémond's pointwise law, so the fraction
// holds while -(1 - beta) q <= alpha |t| - c <= beta q (both lamellae admissible) and otherwise
// moves to the nearer edge of that band: |chi| = clamp(held, lower, upper) with
// lower = (D b + alpha |t| - c) / (D + q), upper = lower + q / (D + q), held the fraction at the
// step's start. A pure point still changes phase exactly at Frémond's threshold.
// kappa = 0 at a point is the on/off step there (phase_projection.hpp, same tie rule), chi in
// {-1, 0, 1}: the paper's scheme (-phasemodel onoff).
// Dissipation (the dissipative Fremond law, docs/model.md#a-dissipative-law; k = 0: the paper's
// law, the same arithmetic): a rate-independent dissipation k |chi - chi_start| per unit volume
// (k in Pa, the unit of alpha and c) added to the step's local problem. A pure point then moves
// only when its drive alpha |t| - c passes +k (towards martensite) or -k (back): the band of the
// held fraction widens by k / (D + q) on both sides. On/off (D + q = 0): the least of the
// phases' energies -c, -alpha t, +alpha t each plus k |chi - chi_start| (the same tie rule).
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "material.hpp"
#include "phase_projection.hpp"
#include "span.hpp"

namespace sma {

// The phase label of a fraction: austenite at 0, else the martensite of its sign.
inline Phase phase_of_fraction(double chi) {
  return chi > 0 ? Phase::Martensite1 : chi < 0 ? Phase::Martensite2 : Phase::Austenite;
}

// The on/off step with dissipation k (Pa): chi in {-1, 0, 1} of least
//   -c (austenite), -alpha t (martensite 1), +alpha t (martensite 2), each + k |chi - start|;
// ties: the previous phase if among the least, else the first of A, M1, M2 (project_phase's rule).
inline double project_phase_dissipative(double trace, double alpha, double c, double k,
                                        double previous, double start) {
  const double chi[3] = {0.0, 1.0, -1.0};
  const double energy[3] = {-c + k * std::fabs(start), -alpha * trace + k * std::fabs(1.0 - start),
                            alpha * trace + k * std::fabs(1.0 + start)};
  const double least = std::fmin(energy[0], std::fmin(energy[1], energy[2]));
  for (int p = 0; p < 3; ++p)
    if (chi[p] == previous && energy[p] == least) return chi[p];
  for (int p = 0; p < 3; ++p)
    if (energy[p] == least) return chi[p];
  return 0.0;  // unreachable
}

// The dissipative law's local part of Auchmuty's Lagrangian at one point: g**(chi) - s t with
// g(x) = c |x| + k |x - start| on [-1, 1] (the conjugate of phi2 at s = alpha x, k = 0: [49] and
// its completion for c < 0) and chi = s / alpha (0 where alpha = 0). g is piecewise linear with
// kinks at -1, 0, start, 1: its convex envelope is the lower hull of those points.
inline double dissipative_local_energy(double trace, double alpha, double c, double k, double s,
                                       double start) {
  const double chi = alpha > 0 ? s / alpha : 0.0;
  if (std::fabs(chi) > 1.0 + 1e-12) return INFINITY;
  const double x[4] = {-1.0, 0.0, std::fmin(1.0, std::fmax(-1.0, start)), 1.0};
  double g[4];
  for (int i = 0; i < 4; ++i) g[i] = c * std::fabs(x[i]) + k * std::fabs(x[i] - start);
  double envelope = INFINITY;
  for (int i = 0; i < 4; ++i) {
    if (x[i] == chi) envelope = std::fmin(envelope, g[i]);
    for (int j = 0; j < 4; ++j)
      if (x[i] < chi && chi < x[j])
        envelope = std::fmin(envelope, g[i] + (g[j] - g[i]) * (chi - x[i]) / (x[j] - x[i]));
  }
  return envelope - s * trace;
}

// Local heat-balance stiffness D (Pa per unit fraction) of one point.
inline double enthalpy_stiffness(const ThermalLaw& law, double trace, double alpha, double kappa) {
  const double dalpha_dT = alpha > 0 ? law.rho * law.a : 0.0;  // alpha = rho a (Tc - T) below Tc
  return (dalpha_dT * std::fabs(trace) + law.rho * law.latent / law.T0) * kappa;
}

// The new signed fraction of one point (see the header). b: the fraction |chi| the heat solve
// saw; previous: this point's chi at the last iterate (the on/off tie rule, the sign at t = 0);
// start: its chi at the start of the time step (the laminate's hysteresis is relative to it);
// laminate: lambda + 2 mu (0: no laminate, the plain enthalpy step).
inline double project_fraction(const ThermalLaw& law, double trace, double alpha, double c,
                               double kappa, double b, double previous, double start = 0.0,
                               double laminate = 0.0, double dissipation = 0.0) {
  if (!std::isfinite(trace) || !std::isfinite(alpha) || !std::isfinite(c) || !std::isfinite(kappa) ||
      !std::isfinite(b) || !std::isfinite(previous) || !std::isfinite(start) || !std::isfinite(laminate) ||
      !std::isfinite(dissipation))
    throw std::domain_error("project_fraction: non-finite input");
  if (dissipation < 0.0) throw std::domain_error("project_fraction: dissipation k < 0");
  const double D = enthalpy_stiffness(law, trace, alpha, kappa);
  const double q = laminate > 0 ? alpha * alpha / laminate : 0.0;
  if (D + q == 0.0) {
    if (dissipation > 0.0) return project_phase_dissipative(trace, alpha, c, dissipation, previous, start);
    const Phase before = phase_of_fraction(previous);
    return spherical_stress(project_phase(trace, alpha, c, before), 1.0);
  }
  if (dissipation > 0.0) {
    const double sign = trace > 0 ? 1.0 : trace < 0 ? -1.0 : (previous < 0 ? -1.0 : 1.0);
    const double held = start * sign > 0 ? std::fabs(start) : 0.0;
    const double drive = alpha * std::fabs(trace) - c;
    const double lower = (D * b + drive - dissipation) / (D + q),
                 upper = (D * b + drive + q + dissipation) / (D + q);
    const double fraction = std::fmin(1.0, std::fmax(0.0, std::fmin(upper, std::fmax(lower, held))));
    return fraction == 0.0 ? 0.0 : sign * fraction;
  }
  const double sign = trace > 0 ? 1.0 : trace < 0 ? -1.0 : (previous < 0 ? -1.0 : 1.0);
  // The fraction of this variant at the step's start (a change of variant starts from none).
  const double held = start * sign > 0 ? std::fabs(start) : 0.0;
  const double drive = alpha * std::fabs(trace) - c;
  const double lower = (D * b + drive) / (D + q), upper = (D * b + drive + q) / (D + q);
  const double fraction = std::fmin(1.0, std::fmax(0.0, std::fmin(upper, std::fmax(lower, held))));
  return fraction == 0.0 ? 0.0 : sign * fraction;
}

// Every point: chi in/out (previous -> new), s = alpha chi. kappa, b, start per point. Returns how
// many points changed fraction.
inline std::size_t project_fractions(const ThermalLaw& law, span<const double> trace,
                                     span<const double> alpha, span<const double> c,
                                     span<const double> kappa, span<const double> b,
                                     span<const double> start, double laminate, span<double> s,
                                     span<double> chi, double dissipation = 0.0) {
  law.validate();
  const std::size_t n = trace.size();
  if (alpha.size() != n || c.size() != n || kappa.size() != n || b.size() != n ||
      start.size() != n || s.size() != n || chi.size() != n)
    throw std::invalid_argument("project_fractions: arrays of different lengths (trace " +
                                std::to_string(n) + ", alpha " + std::to_string(alpha.size()) +
                                ", c " + std::to_string(c.size()) + ", kappa " +
                                std::to_string(kappa.size()) + ", b " + std::to_string(b.size()) +
                                ", start " + std::to_string(start.size()) + ", s " +
                                std::to_string(s.size()) + ", chi " + std::to_string(chi.size()) + ")");
  if (!(laminate >= 0.0)) throw std::domain_error("project_fractions: laminate modulus < 0");
  if (!(dissipation >= 0.0 && std::isfinite(dissipation)))
    throw std::domain_error("project_fractions: dissipation k = " + std::to_string(dissipation) +
                            " must be finite and >= 0 (Pa)");
  std::size_t changed = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(alpha[i] >= 0.0))
      throw std::domain_error("project_fractions: alpha < 0 at point " + std::to_string(i));
    if (!(kappa[i] >= 0.0))
      throw std::domain_error("project_fractions: kappa < 0 at point " + std::to_string(i));
    if (!(b[i] >= 0.0 && b[i] <= 1.0))
      throw std::domain_error("project_fractions: latent fraction b = " + std::to_string(b[i]) +
                              " outside [0, 1] at point " + std::to_string(i));
    const double next =
        project_fraction(law, trace[i], alpha[i], c[i], kappa[i], b[i], chi[i], start[i], laminate,
                         dissipation);
    changed += next != chi[i];
    chi[i] = next;
    s[i] = alpha[i] * next;
  }
  return changed;
}

// The DC loop's move along an unstable mode (fraction model with the dissipative law, called by
// edp/solvers/dc.idp after each local step). The DC loop is a fixed point chi <- local(global(chi))
// whose slope along a mode is M / (D + q): M the mechanical trace response of the mode (alpha^2
// times the compliance it sees, about q = alpha^2 / (lambda + 2 mu) for one point, up to
// alpha^2 / (lambda + mu) for the free ring's uniform mode) against the local step's curvature
// D + q. Where M >= D + q the step's energy is concave along the mode: the point has no
// equilibrium inside its interval and snaps to its end, but DC reaches that end only by steps
// that grow by M / (D + q) per iteration, about 1.003 on the life scene's free ring (a = 2625,
// q 60 times D): thousands of iterations. A point whose last two DC increments have the same sign
// and do not shrink (|d1| >= |d0| > 0: the DC map's slope >= 1 along its motion, energy concave
// there) is moved at once to the end of its interval in that direction: 1 (growing above its held
// fraction), its held fraction (moving towards it), 0 (shrinking below it); held = |start| if
// start has the sign of chi, else 0 (phase_fraction's band). Each point at most once per DC solve
// (snapped: 0/1 per point, in/out), so a wrong move costs iterations, never a cycle: the next
// local step projects it back. s = alpha chi where moved. Returns the number of points moved.
inline std::size_t snap_unstable_fractions(span<const double> before2, span<const double> before,
                                           span<const double> start, span<const double> alpha,
                                           span<double> snapped, span<double> chi, span<double> s) {
  const std::size_t n = chi.size();
  if (before2.size() != n || before.size() != n || start.size() != n || alpha.size() != n ||
      snapped.size() != n || s.size() != n)
    throw std::invalid_argument("snap_unstable_fractions: arrays of different lengths");
  std::size_t moved = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (snapped[i] != 0) continue;
    const double d0 = before[i] - before2[i], d1 = chi[i] - before[i];
    if (!(d0 != 0.0 && d0 * d1 > 0.0 && std::fabs(d1) >= std::fabs(d0))) continue;
    const double sign = chi[i] > 0 ? 1.0 : chi[i] < 0 ? -1.0 : (before[i] < 0 ? -1.0 : 1.0);
    if (before[i] * sign < 0) continue;  // a change of variant: not a motion along one interval
    const double f = std::fabs(chi[i]), grows = f - std::fabs(before[i]);
    if (grows == 0.0) continue;
    const double held = start[i] * sign > 0 ? std::fabs(start[i]) : 0.0;
    const double end = grows > 0 ? (f < held ? held : 1.0) : (f > held ? held : 0.0);
    if (end == f) continue;
    chi[i] = end == 0.0 ? 0.0 : sign * end;
    s[i] = alpha[i] * chi[i];
    snapped[i] = 1;
    ++moved;
  }
  return moved;
}

// Reversals of one time step: a point whose martensite fraction |chi| grew by more than tol over
// the step although it has lost fraction in an earlier step (it returns to martensite after
// turning back towards austenite: the chatter of the on/off scheme when heated). `reverted` (0/1
// per point, in/out) remembers which points have lost fraction so far. Returns the number of
// points that reversed in this step.
inline std::size_t count_reversals(span<const double> chi_start, span<const double> chi,
                                   span<double> reverted, double tol) {
  const std::size_t n = chi.size();
  if (chi_start.size() != n || reverted.size() != n)
    throw std::invalid_argument("count_reversals: arrays of different lengths");
  if (!(tol >= 0)) throw std::invalid_argument("count_reversals: tol must be >= 0");
  std::size_t reversed = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double change = std::fabs(chi[i]) - std::fabs(chi_start[i]);
    if (change > tol && reverted[i] != 0) ++reversed;
    if (change < -tol) reverted[i] = 1;
  }
  return reversed;
}

}  // namespace sma
