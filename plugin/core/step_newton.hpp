// One time step of the fraction model solved as one nonsmooth system (-stepsolver newton): the
// heat solve, the law at the points, the mechanics with Signorini-Coulomb contact and the
// fractions' complementarity, all at once, by a globalised projected Newton method.
//
// The step's unknowns are the martensite fractions beta = |chi| per point (the sign is the
// strain trace's). Given beta, the rest is a function of it:
//   T     = H^-1 (heat_rhs + mask .* latent (beta - b_start))     (the theta step; linear)
//   alpha, c at the points (Interp T), q = alpha^2 / laminate, drive = alpha |tr e| - c
//   u     the Signorini-Coulomb solution of K u = f + B (alpha chi) + H' r (the condensed contact
//         problem of contact_step.hpp, the slip thresholds g = mu r_n to their fixed point)
// and the step is solved when every point satisfies Frémond's law with the laminate band of
// phase_fraction.hpp at the converged temperature:
//   beta = clamp(clamp(held, drive / q, drive / q + 1), 0, 1),     held = the fraction at the
//   step's start (of this variant),
// which is the fixed point the nested loops of dct.idp converge to (their enthalpy regularisation
// vanishes there); with the dissipation k the band widens by k / q on each side (target()). Stopping criterion: the residual F = chi - sign(tr e) beta_target, in
// fraction units, max_i |F_i| <= tol, each evaluation solving the heat exactly (a back-solve)
// and the contact problem to its PSOR and slip-threshold tolerances.
//
// Why not the nested fixed point: its contraction factor is set by a nearly neutral mode (the
// partly transformed zone's eigenstrain against its own mechanical response through the contact:
// on the paper's scale the step's Jacobian on that zone has eigenvalues down to 7e-6 of its
// largest), so it crawls for hundreds of iterations. The step is instead, to 0.1 % (the measured
// asymmetry of its Jacobian, from alpha(T)), the stationarity condition of an incremental energy
//   W(beta) = Pi(alpha beta) + sum_i area_i (c_i beta_i + q_i beta_i^2 / 2 + psi_i(beta_i - held_i))
//             + (rho L / T0) / 2 beta' A Interp H^-1 latent beta
// (Pi the contact-mechanical energy, concave in the eigenstress: the paper's DC structure;
// psi_i(x) = q_i max(-x, 0) + k |x| the laminate's dissipation and the dissipative law's, k in
// Pa, 0 for the paper's law; the heat quadratic convex), with -dW/dbeta_i = area_i f_i,
// f = drive - q beta - k (+ q + 2 k on the reverting side of held). With k the heat also receives
// the dissipated heat k |chi - chi_start| / dt (the nested loops' source): its feedback on the
// drive is not a gradient (a relative asymmetry of about k / (rho L) in the Jacobian), which
// GMRES and the moves' acceptance tests below do not need. Each iteration:
//   1. classify the points: free in their interval [0, held] or [held, 1], or bound at 0, held,
//      1 when the force pushes them outward; the intervals are cut to a trust region;
//   2. Newton on the free points: (-df/dbeta)_FF d_F = f_F, by GMRES on the exact linearisation
//      (a heat back-solve and a stiffness back-solve per product, the contact statuses frozen),
//      in rounds of an active-set method (newton_direction): points leaving their interval are
//      pinned to its end; an unstable block (a Ritz value of non-positive real part: part of the
//      front snaps) is followed along its Ritz vector to the first interval end;
//   3. the move is accepted when W falls by at least a tenth of its quadratic model's prediction
//      (W's change by the trapezoid rule on the forces at both ends: exact for a quadratic W, no
//      energy evaluated), or when a full Newton move halves the smallest residual so far; the
//      trust region grows or shrinks with that ratio; a Newton move to a stationary point that
//      is not a minimum of W (GMRES solves the block but finds W concave on it: the solution of
//      the step itself may be such a saddle, e.g. between the triangles of one layer of the
//      front, which the nested loops converge to and an energy descent leaves) is taken only on
//      the residual test, which cannot cycle either (the best residual halves each time);
//   4. fall-back, always a descent direction: the preconditioned gradient step
//      d = f / (D + q), D = (rho a |tr e| [alpha > 0] + rho L / T0) kappa, which is the nested
//      loops' enthalpy-regularised local step, with Armijo backtracking on W: the iteration
//      cannot cycle.
//   5. a step these moves stop advancing (`stall` iterations without halving the residual) with
//      at most `dense_block` free points is finished by dense Newton moves on the law itself
//      (dense_newton): the block's linearisation built one product a point, the linearised law
//      solved exactly (its solution may be a saddle of W, which the moves above creep toward),
//      the move accepted when the residual falls (which cannot cycle either).
// A transformed point whose trace changed sign takes the other martensite (switch_variants).
// Measured (docs/parameters.md, "Step solver"; tests/step_solver_test.py): 2 to 3 iterations per
// transforming step on average, at most 6 once the ring has dilated, on the project's and the
// paper's scale, friction included, where the nested loops take 11 to 114 on average.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact_step.hpp"
#include "coarse_space.hpp"
#include "deflation.hpp"
#include "gmres.hpp"
#include "material.hpp"
#include "psor.hpp"
#include "sparse_spd.hpp"

namespace sma {

// What stays fixed over a time step (the operators over a whole run).
struct StepProblem {
  // Heat: T = heat^-1 (heat_rhs + heat_mask .* latent (beta - b_start)).
  const LinearSolver* heat = nullptr;
  Eigen::VectorXd heat_rhs, heat_mask;
  SparseMatrix latent;  // nodes x points: int s phi_i (the P0 -> P1 load)
  double latent_scale = 1.0;  // rho L / dt
  SparseMatrix interp;  // points x nodes: T at the points
  // Mechanics: rhs = (f + B s) .* free, tr e = (B' u) ./ area. B is the script's: with a
  // transformation direction D (edp/lib/elasticity.idp, PhaseDirection) it loads s D and this
  // "trace" is the driving strain D:e; nothing here depends on D but the laminate modulus.
  const LinearSolver* stiffness = nullptr;
  const DelassusFactor* contact = nullptr;  // null: no contact
  SparseMatrix load;                        // dofs x points: B
  Eigen::VectorXd area, force, free;
  // Contact, per node: gap, t.u at the step's start, 0 where a support blocks the tangential
  // motion, the Coulomb coefficient.
  Eigen::VectorXd gap, slip_reference, tangent_free, mu;
  // The contact's rows per node: 2, (n, t) (the 2D layout: one tangential row, a Tresca interval),
  // or 3, (n, t1, t2) (Coulomb's cone in 3D, psor_cone.hpp: the two tangential reactions bounded
  // together); with 3, slip_reference holds (t1.u, t2.u) per node, interleaved, and r 3 per node.
  int contact_rows = 2;
  ContactStepSettings psor;
  double slip_tol = 1e-9;
  int slip_maxit = 200;
  // The law: c gets threshold_offset added (empty: none); laminate = lambda + 2 mu.
  ThermalLaw law{};
  double laminate = 0.0;
  Eigen::VectorXd threshold_offset;
  Eigen::VectorXd kappa;  // K per unit fraction (the gradient step's preconditioner)
  // The dissipative law (docs/model.md, "A dissipative law"): k (Pa) and k / dt, the dissipated
  // heat's source per unit fraction moved (0: the paper's law, the same arithmetic).
  double dissipation = 0.0, dissipation_scale = 0.0;
  // The step's start: chi (the held fractions) and the fractions its heat load starts from.
  Eigen::VectorXd chi_start, b_start;
  // Names the stiffness factor and its contact operator as they are now: the caller gives a new
  // value whenever either changes (the glue: a counter over all refactorisations); 0: unknown,
  // no contact solve is reused (StepSolver::contact_solve).
  std::uint64_t mechanics_version = 0;
  // Names latent, interp and load as they are now, the same way (the glue: a counter over
  // StepOperatorsSet's calls); 0: unknown, what is derived from them is made again at each step.
  std::uint64_t operators_version = 0;
  // interp by rows (T at a point, row by row: the products' T at the points), made once per
  // operators_version (a conversion of the whole matrix at every step that takes a product otherwise).
  struct OperatorCache {
    std::uint64_t version = 0;
    Eigen::SparseMatrix<double, Eigen::RowMajor, int> interp_rows;
  };
  mutable OperatorCache operator_cache;
  // The last frictionless contact solve of a state without fraction that kept its warm start
  // (its input reactions solve it): the same load, gap, settings and reactions give the same
  // displacement, which a tail step then takes without a back-solve.
  struct ContactMemo {
    std::uint64_t version = 0;
    Eigen::VectorXd mech, gap, slip_reference, tangent_free, r, threshold, u, trace;
    double omega = 0, tol = 0;
  };
  mutable ContactMemo contact_memo;
};

struct StepSettings {
  double tol = 1e-8;    // max |F| (fraction units)
  int maxit = 50;       // iterations (each: one Newton or gradient move)
  int gmres_maxit = 300;
  double forcing = 0.1;  // the largest relative accuracy asked of GMRES (inexact Newton's forcing term)
  int pdas_rounds = 12;
  // Active-set rounds once a negative-curvature move has failed to halve the residual: an unstable
  // block then pins its points one per round, and 12 rounds left a 35-point block creeping (a
  // 1.5 % fall of the residual an iteration, elliptic-friction at a = 2875, step 599).
  int pdas_rounds_stalled = 48;
  // Deflation space recycled over the step's linearised solves (deflation.hpp): the vectors kept
  // (0: none), taken from solves of at least recycle_from products, recycle_harvest from each.
  // Off by default: measured on the scaling series' transient (30 steps) it cost more products
  // than it saved at 72 and 108 layers (471 -> 516, 891 -> 967) and saved 12 % at 140 (1489 ->
  // 1309): the front's small eigenvalues form a continuum, and the harmonic Ritz vectors found by
  // one solve are not eigenvectors of the next rounds' operators (other free points); on the
  // paper-scale runs it moves the curves' extrema by up to 1.2 % (docs/measurements.md#m-deflation).
  int recycle = 0, recycle_from = 16, recycle_harvest = 8;
  // Two-level preconditioner (coarse_space.hpp), off: on (coarse), it serves the linearised solves
  // of blocks of at least coarse_points unpinned points (above the 6480 points of the largest
  // default mesh, sleeve-half: no default run can reach it) once a solve of such a block in the
  // same step has taken coarse_after GMRES iterations (0: from the first), with smoothed aggregates
  // of about coarse_aggregate points (coarse_smooth averaging passes), one product each per Newton
  // iteration; coarse_additive: P = I + Q |E|^-1 Q' D instead of (I - Q Q' D) + Q |E|^-1 Q' D. It
  // replaces the recycled deflation on the blocks it serves. Off because it did not cut products
  // on the scaling transient (108 layers 812 -> 901, 140: 1479 -> 1832 with plain aggregates): the
  // slowest Ritz vectors are not smooth, the coarse span holds 1-2 % of them
  // (docs/measurements.md#m-coarse-space).
  bool coarse = false;
  int coarse_points = 8000, coarse_after = 40, coarse_aggregate = 400, coarse_smooth = 8;
  bool coarse_additive = false;
  bool saddle_newton = true;  // Newton moves to a stationary point that is not a minimum of W (solve)
  bool snap_trial = true;     // a block the law sends wholly to its interval ends tried at once (snap_trial)
  // Consecutive creeping iterations (the gradient step taken after Newton rounds that cost more
  // products than the block's free points, at most dense_block of them) after which the dense
  // move is tried, once a step (solve); 0: only the stall rule. 2: one such iteration also
  // happens where the moves then converge (the radial sleeve at the paper's a: a dense move there
  // cost 523 products against 463), two in a row did not.
  int early_dense = 2;
  int stall = 10;  // iterations without halving the residual that stop the step unconverged
  // The same with the dissipation k > 0: the free ring's first transforming step (its uniform
  // mode snapping, k = 5e5 Pa, 2 s steps) crept 11 iterations at about 1e-2 and then converged
  // at iteration 14; the paper's law keeps 10 (its steps' fall-backs unchanged).
  int stall_dissipative = 20;
  // A step that would stop on `stall` and has at most this many free points is finished by
  // dense Newton moves instead (solve(), dense_newton): the block's linearisation built column
  // by column (one product a point), its linearised law solved exactly, the move accepted when
  // it lowers the residual. 0: never (the step stops as before).
  int dense_block = 128;
  // A trial's budget of products (0: the step is not a trial, its caller cannot take it shorter):
  // a step that has spent more stops unconverged with StepResult::trial_given_up, for the caller
  // to take again shorter (a 3 s step into the reversion's onset spent 14 255 products, the same
  // span taken as a 0.87 s step 674). A trial also gives up where it stalls (below).
  int product_budget = 0;
  // In a trial (product_budget > 0), negative-curvature moves in a row that each fail to halve the
  // residual, after which the step stops as over its budget (0: never); one is enough where the
  // residual it left is at least trial_stall_residual (fraction units). A step too long for the
  // transformation's onset creeps so (sleeve-offset -tol 1e-3: six trials of 1.0-0.4 s, each at
  // 2e-3 to 6e-2 for 3-6 moves of 500-1000 products, 14 570 products in all); the defaults' steps
  // take no two such moves in a row and none above 5e-4 (sleeve-offset's two, which converge).
  int trial_curvature_stalls = 2;
  double trial_stall_residual = 1e-3;
  // A step that stops unconverged is solved once more at its last iterate, its contact from the
  // step's start (reactions and slip thresholds) instead of from the last evaluation's: the two
  // residuals differ by the noise of the contact solves (their tolerances, -psortol and
  // -sliptol). A residual within floor_factor of that noise is the floor of the step's equations
  // as solved, not a hard step: a shorter step or the nested loops cannot meet a tolerance below
  // it (StepResult::at_floor). 0: no such probe. Without contact (or below its noise) the floor is
  // round-off's: a step that stops at a residual of at most roundoff_floor (fraction units) is at
  // it too (free-ring -phasemodel fraction: -steptol 1e-13 met, 1e-14 stalls at 2.2e-14).
  double floor_factor = 10;
  double roundoff_floor = 1e-12;
  std::FILE* trace = nullptr;  // one line per iteration there when set (the glue: SMA_STEP_TRACE=1)
};

struct StepResult {
  bool converged = false;
  int iterations = 0, gradient_steps = 0, curvature_steps = 0, saddle_steps = 0, variant_switches = 0, evaluations = 0,
      products = 0;
  int dense_steps = 0;  // the dense Newton moves of a step that stalled (StepSettings::dense_block)
  int snaps = 0;        // steps solved by the snap trial (StepSolver::snap_trial)
  // Active-set rounds of newton_direction that had every free point pinned (the release rule then
  // applied without a solve).
  int pinned_blocks = 0;
  int heat_solves = 0, stiffness_solves = 0, psor_sweeps = 0, slip_iterations = 0;
  int reused_solves = 0;  // stiffness solves the contact memo answered without a back-solve (contact_solve)
  double residual = 0.0;
  std::string failure;  // why it stopped unconverged (empty when converged)
  bool trial_given_up = false;  // a trial stopped for the caller to take shorter (StepSettings::product_budget)
  // An unconverged step's residual noise (StepSettings::floor_factor: the largest change of a
  // point's residual when its last iterate's contact is solved again from the step's start), and
  // whether its residual is within floor_factor of it: a tolerance below the floor, not a hard
  // step (never a trial given up).
  double residual_noise = 0.0;
  bool at_floor = false;
  bool floor_is_noise = false;  // the contact's noise set that floor (else round-off's, roundoff_floor)
};

// The state at one iterate chi: everything the step's equations give for it.
struct StepState {
  Eigen::VectorXd chi, T, alpha, c, q, u, trace, sign, held, drive, residual;
  Eigen::VectorXd r, threshold;  // contact reactions (n, t interleaved) and slip thresholds
  // Frozen contact statuses for the linearisation: the unknowns of the contact rows that move
  // (active normal rows, sticking tangential rows), the factorised system on them, the sliding
  // nodes' direction (+-1, 0 for none). Formed by the first product at this state (frozen), not
  // by evaluate: most evaluated states are line-search trials that take no product.
  mutable std::vector<int> moving;
  mutable std::vector<double> slide;
  mutable Eigen::PartialPivLU<Eigen::MatrixXd> statuses;
  mutable bool frozen = false;
  // The cone's (contact_rows 3): per moving unknown a, the node's three rows it tests (cone_test)
  // and moves (cone_trial), 3 values each, and its compliance (cone_compliance: |w_t| / g for a
  // sliding node's motion across its slip, 0 otherwise); slip[i] = |w_t| of node i at the solve.
  mutable std::vector<double> cone_test, cone_trial, cone_compliance;
  Eigen::VectorXd slip;
  double residual_norm = 0.0;
};

namespace step_detail {

// Whether some entry of v is not zero (a plain loop, stopping at the first: Eigen's
// (v.array() != 0).any() cost a tail step's evaluation 6k instructions a vector).
inline bool any_nonzero(const Eigen::VectorXd& v) {
  const double* const x = v.data();
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (x[i] != 0.0) return true;
  return false;
}

// 0 .. n - 1: every point, as the increasing point lists of a product or a block take them.
inline std::vector<Eigen::Index> all_points(Eigen::Index n) {
  std::vector<Eigen::Index> points((std::size_t)n);
  for (Eigen::Index i = 0; i < n; ++i) points[(std::size_t)i] = i;
  return points;
}

// out += (scale m) x for a column-major sparse m, x given per column by x_of(j): Eigen's sparse *
// dense product order (column by column from 0; a scale on the product scales the matrix's values,
// and a scale of 1 changes no bit), through raw pointers (a store through a vector's operator[]
// could alias its own members, which the loop would otherwise reload at every term). A column
// whose x is zero is skipped: its terms are exact zeros, which leave every sum (started at +0 by
// the caller) as it is, so the bits are Eigen's; most columns are zero when few points transform
// (the whole tail of a run: chi = 0).
template <class ColumnValue>
inline void add_scaled_columns(const SparseMatrix& m, double scale, ColumnValue x_of, double* out) {
  const int* const outer = m.outerIndexPtr();
  const int* const inner = m.innerIndexPtr();
  const double* const value = m.valuePtr();
  for (Eigen::Index j = 0; j < m.outerSize(); ++j) {
    const double x = x_of(j);
    if (x == 0.0) continue;
    for (int e = outer[j]; e < outer[j + 1]; ++e) out[inner[e]] += (scale * value[e]) * x;
  }
}

inline span<const double> as_span(const Eigen::VectorXd& v) { return {v.data(), (std::size_t)v.size()}; }

// The linearised law on a block of points, solved exactly: each point of the block moves by
// d_i within its box [l_i, u_i] (its interval on one side of its held fraction, less its
// fraction), under the force f_i + (M d)_i (M = df/dbeta on the block, its -q diagonal
// included), and its law, linearised, is
//   Phi_i(d) = d_i - clamp(d_i + (f + M d)_i / q_i, l_i, u_i) = 0
// (evaluate()'s residual F to first order: F_i = b_i - clamp(b_i + f_i / q_i, lo_i, hi_i) on a
// free point). Solved by the primal-dual active-set method (the semismooth Newton method on
// Phi): the points whose d + (f + M d) / q leaves their box are held at its end, the others
// solve their rows of f + M d = 0 by LU, until the sets repeat. Plain for `plain` iterations
// (it solves the measured blocks in 2 to 3, where a damped one crawled: the full move changes
// many sets at once), then, should it cycle (an indefinite M, W concave on the block), from the
// best d met, each change damped until ||Phi|| falls. Returns the d of the smallest ||Phi||
// met (phi_norm).
inline Eigen::VectorXd solve_linearised_law(const Eigen::MatrixXd& M, const Eigen::VectorXd& f, const Eigen::VectorXd& q,
                                            const Eigen::VectorXd& l, const Eigen::VectorXd& u, double& phi_norm) {
  const Eigen::Index k = f.size();
  auto phi = [&](const Eigen::VectorXd& d) {
    const Eigen::VectorXd z = d + (f + M * d).cwiseQuotient(q);
    return Eigen::VectorXd(d - z.cwiseMax(l).cwiseMin(u));
  };
  Eigen::VectorXd d = Eigen::VectorXd::Zero(k), best = d;
  double norm = phi(d).norm(), best_norm = norm;
  const int plain = 30;
  std::vector<char> sets, last;  // per point: 0 inside, 1 at l, 2 at u
  for (int it = 0; it < 100 && norm > 0; ++it) {
    if (it == plain) d = best, norm = best_norm;
    const Eigen::VectorXd z = d + (f + M * d).cwiseQuotient(q);
    Eigen::VectorXd next = Eigen::VectorXd::Zero(k);
    std::vector<Eigen::Index> inside;
    sets.assign((std::size_t)k, 0);
    for (Eigen::Index i = 0; i < k; ++i) {
      if (z[i] <= l[i]) next[i] = l[i], sets[(std::size_t)i] = 1;
      else if (z[i] >= u[i]) next[i] = u[i], sets[(std::size_t)i] = 2;
      else inside.push_back(i);
    }
    if (it < plain && sets == last) break;  // d solves its own sets' equations: the solution
    last = sets;
    const Eigen::Index m = (Eigen::Index)inside.size();
    if (m > 0) {
      Eigen::MatrixXd A(m, m);
      Eigen::VectorXd rhs(m);
      const Eigen::VectorXd bound_force = f + M * next;  // next is 0 on the inside points
      for (Eigen::Index a = 0; a < m; ++a) {
        rhs[a] = -bound_force[inside[(std::size_t)a]];
        for (Eigen::Index b = 0; b < m; ++b) A(a, b) = M(inside[(std::size_t)a], inside[(std::size_t)b]);
      }
      const Eigen::VectorXd x = A.fullPivLu().solve(rhs);
      if (!x.allFinite()) break;
      for (Eigen::Index a = 0; a < m; ++a) next[inside[(std::size_t)a]] = x[a];
    }
    double t = 1.0, trial = phi(next).norm();
    Eigen::VectorXd moved = next;
    if (it >= plain) {
      for (int halving = 0; halving < 30; ++halving, t *= 0.5) {
        moved = d + t * (next - d);
        trial = phi(moved).norm();
        if (trial < (1 - 1e-4 * t) * norm) break;
      }
      if (!(trial < norm)) break;
    }
    d = moved, norm = trial;
    if (norm < best_norm) best = d, best_norm = norm;
  }
  phi_norm = best_norm;
  return best;
}

}  // namespace step_detail

class StepSolver {
 public:
  StepSolver(const StepProblem& p, StepResult& stats) : p_(p), stats_(stats) { check(); }

  // The state at chi, with the contact reactions started from r0 (a warm start) and the slip
  // thresholds from threshold0.
  StepState evaluate(const Eigen::VectorXd& chi, const Eigen::VectorXd& r0, const Eigen::VectorXd& threshold0) {
    ++stats_.evaluations;
    StepState s;
    s.chi = chi;
    const Eigen::Index n = chi.size();
    // Heat: heat_rhs + mask .* (rho L / dt) latent (|chi| - b_start), the products summed as
    // Eigen's sparse * dense products sum (column by column from 0; a scale on the product
    // scales the matrix's values), into the solver's work vectors.
    Eigen::VectorXd& rhs = work_.rhs;
    const Eigen::Index nodes = p_.heat_rhs.size(), dofs = p_.force.size();
    rhs.setZero(nodes);
    // No fraction anywhere (the tail of a run, every point austenite): the latent and eigenstress
    // loads are sums of exact zeros, which add_scaled_columns would skip column by column.
    const bool transformed = step_detail::any_nonzero(chi);
    const bool started = step_detail::any_nonzero(p_.b_start);  // a fraction at the step's start
    if (transformed || started)
      step_detail::add_scaled_columns(p_.latent, p_.latent_scale,
                                      [&](Eigen::Index i) { return std::fabs(chi[i]) - p_.b_start[i]; }, rhs.data());
    for (Eigen::Index j = 0; j < nodes; ++j) rhs[j] = p_.heat_rhs[j] + p_.heat_mask[j] * rhs[j];
    if (p_.dissipation > 0) {  // the dissipated heat k |chi - chi_start| / dt, a source beside the latent heat
      Eigen::VectorXd& source = work_.heat;
      source.setZero(nodes);
      step_detail::add_scaled_columns(p_.latent, p_.dissipation_scale,
                                      [&](Eigen::Index i) { return std::fabs(chi[i] - p_.chi_start[i]); }, source.data());
      for (Eigen::Index j = 0; j < nodes; ++j) rhs[j] += p_.heat_mask[j] * source[j];
    }
    s.T.resize(nodes);
    heat_solve(rhs, s.T);
    // T at the points (interp T), the law's coefficients there.
    Eigen::VectorXd& Tq = work_.points;
    Tq.setZero(n);
    step_detail::add_scaled_columns(p_.interp, 1.0, [&](Eigen::Index j) { return s.T[j]; }, Tq.data());
    s.alpha.resize(n);
    s.c.resize(n);
    s.q.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      s.alpha[i] = p_.law.alpha(Tq[i]);
      s.c[i] = p_.law.c(Tq[i]) + (p_.threshold_offset.size() ? p_.threshold_offset[i] : 0.0);
      s.q[i] = s.alpha[i] * s.alpha[i] / p_.laminate;
    }
    // Mechanics with contact: (f + B (alpha chi)) .* free.
    Eigen::VectorXd& mech = work_.mech;
    mech.setZero(dofs);
    if (transformed)
      step_detail::add_scaled_columns(p_.load, 1.0, [&](Eigen::Index i) { return s.alpha[i] * chi[i]; }, mech.data());
    for (Eigen::Index j = 0; j < dofs; ++j) mech[j] = (p_.force[j] + mech[j]) * p_.free[j];
    s.r = r0;
    s.threshold = threshold0;
    s.u.resize(dofs);
    const Memo memo = contact_solve(mech, s, !transformed && !started);
    // The trace (B' u) ./ area (Eigen's row-wise product: each sum from 0, added to 0); the
    // memo's, of the same u, when the contact solve was the memo's.
    if (memo == Memo::Reused && p_.contact_memo.trace.size() == n) {
      s.trace = p_.contact_memo.trace;
    } else {
      s.trace.resize(n);
      const double* const u = s.u.data();
      const int* const outer = p_.load.outerIndexPtr();
      const int* const inner = p_.load.innerIndexPtr();
      const double* const value = p_.load.valuePtr();
      for (Eigen::Index i = 0; i < n; ++i) {
        double t = 0.0;
        for (int e = outer[i]; e < outer[i + 1]; ++e) t += value[e] * u[inner[e]];
        s.trace[i] = (0.0 + 1.0 * t) / p_.area[i];
      }
      if (memo == Memo::Remembered) p_.contact_memo.trace = s.trace;
    }
    // The law.
    s.sign.resize(n);
    s.held.resize(n);
    s.drive.resize(n);
    s.residual.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double t = s.trace[i];
      s.sign[i] = t > 0 ? 1.0 : t < 0 ? -1.0 : (chi[i] < 0 ? -1.0 : 1.0);
      s.held[i] = std::max(p_.chi_start[i] * s.sign[i], 0.0);
      s.drive[i] = s.alpha[i] * std::fabs(t) - s.c[i];
      s.residual[i] = chi[i] - s.sign[i] * target(s, i, p_.dissipation);
    }
    s.residual_norm = n ? s.residual.lpNorm<Eigen::Infinity>() : 0.0;
    return s;
  }

  // The fraction magnitude Frémond's law with the laminate band gives point i at state s; with
  // the dissipation k (Pa) the band widens by k / q on each side: a fraction grows only when its
  // drive passes q beta + k, shrinks only below q (beta - 1) - k (phase_fraction.hpp's local step
  // at its fixed point b = |chi|, whatever D).
  static double target(const StepState& s, Eigen::Index i, double k = 0.0) {
    const double q = s.q[i], drive = s.drive[i], held = s.held[i];
    if (!(q > 0)) return drive > k ? 1.0 : drive < -k ? 0.0 : held;
    const double lower = (drive - k) / q, upper = (drive + k) / q + 1.0;
    return std::clamp(std::clamp(held, lower, upper), 0.0, 1.0);
  }

  // d f / d beta along w at state s (f = drive - q beta, + q where `upper`; the dissipation's
  // -+k is constant): one heat and one stiffness back-solve, the contact statuses of s frozen.
  // With k the dissipated heat k |chi - chi_start| / dt moves by +-k / dt per unit fraction: + on
  // the growing side of held, - on the reverting side (`upper`).
  Eigen::VectorXd force_derivative(const StepState& s, const Eigen::VectorXd& w,
                                   const std::vector<char>& upper) {
    const Eigen::Index n = w.size();
    if (all_.size() != (std::size_t)n) all_ = step_detail::all_points(n);
    Eigen::VectorXd out(n);
    force_derivative_on(s, all_, all_, w.data(), upper, out.data());
    return out;
  }

  // The points a product along w needs when w is zero off `sub` (increasing) and only the
  // product's entries on sub are read: sub and the transformed points (chi != 0), the only ones
  // whose eigenstress (alpha chi) changes; increasing.
  std::vector<Eigen::Index> product_support(const StepState& s, const std::vector<Eigen::Index>& sub) const {
    std::vector<Eigen::Index> rows;
    std::size_t a = 0;
    for (Eigen::Index i = 0; i < s.chi.size(); ++i) {
      const bool in_sub = a < sub.size() && sub[a] == i;
      if (in_sub) ++a;
      if (in_sub || s.chi[i] != 0.0) rows.push_back(i);
    }
    return rows;
  }

  // force_derivative's entries on `sub` (increasing) along w, zero off sub (w_sub[a] = w at
  // sub[a]), into df_sub[a]; `rows`: product_support(s, sub). The same operations in the same
  // order as on the full vectors, on the entries that can be nonzero or are read: the latent
  // load over sub's columns, T at rows, the eigenstress load over rows' columns (the others
  // add exact zeros), the trace change at sub: the same bits.
  void force_derivative_on(const StepState& s, const std::vector<Eigen::Index>& sub,
                           const std::vector<Eigen::Index>& rows, const double* w_sub,
                           const std::vector<char>& upper, double* df_sub) {
    ++stats_.products;
    const Eigen::Index n = s.chi.size(), nodes = p_.heat_rhs.size(), dofs = p_.force.size();
    const std::size_t k = sub.size();
    const double scale = p_.latent_scale;
    // Heat: mask .* (latent (scale w)); with k the source scale w +- (k / dt) w.
    work_.heat.setZero(nodes);
    double* const heat = work_.heat.data();  // (local pointers: see add_scaled_columns)
    const int* outer = p_.latent.outerIndexPtr();
    const int* inner = p_.latent.innerIndexPtr();
    const double* value = p_.latent.valuePtr();
    for (std::size_t a = 0; a < k; ++a) {
      const Eigen::Index i = sub[a];
      const double w = w_sub[a];
      if (w == 0.0) continue;  // exact zeros, which leave the (+0 started) sums as they are
      if (p_.dissipation > 0) {
        double source = p_.latent_scale * w;
        source += (upper[(std::size_t)i] ? -p_.dissipation_scale : p_.dissipation_scale) * w;
        for (int e = outer[i]; e < outer[i + 1]; ++e) heat[inner[e]] += value[e] * source;
      } else {
        for (int e = outer[i]; e < outer[i + 1]; ++e) heat[inner[e]] += (scale * value[e]) * w;
      }
    }
    const double* const mask = p_.heat_mask.data();
    for (Eigen::Index j = 0; j < nodes; ++j) heat[j] = mask[j] * heat[j];
    work_.dT.resize(nodes);
    heat_solve(work_.heat, work_.dT);
    // T, alpha, c and the eigenstress change at rows.
    const RowMajorMatrix& interp_rows = interp_by_rows();
    work_.dalpha.resize(n);
    work_.dc.resize(n);
    const double rhoa = p_.law.rho * p_.law.a, latent_slope = p_.law.rho * p_.law.latent / p_.law.T0;
    const int* const row_outer = interp_rows.outerIndexPtr();
    const int* const row_inner = interp_rows.innerIndexPtr();
    const double* const row_value = interp_rows.valuePtr();
    const double* const dT = work_.dT.data();
    double* const dalpha = work_.dalpha.data();
    double* const dc = work_.dc.data();
    const double* const alpha = s.alpha.data();
    const double* const chi = s.chi.data();
    const double* const sign = s.sign.data();
    // Mechanics: (B ds) .* free, the linearised contact step; B ds summed in the same loop, column
    // by column in rows' (increasing) order as before.
    work_.mech.setZero(dofs);
    outer = p_.load.outerIndexPtr();
    inner = p_.load.innerIndexPtr();
    value = p_.load.valuePtr();
    double* const mech = work_.mech.data();
    std::size_t a = 0;
    for (const Eigen::Index i : rows) {
      double dTq = 0.0;
      for (int e = row_outer[i], end = row_outer[i + 1]; e < end; ++e) dTq += row_value[e] * dT[row_inner[e]];
      const bool in_sub = a < k && sub[a] == i;
      const double w = in_sub ? w_sub[a] : 0.0;
      if (in_sub) ++a;
      dalpha[i] = alpha[i] > 0 ? -rhoa * dTq : 0.0;
      dc[i] = latent_slope * dTq;
      const double ds = dalpha[i] * chi[i] + alpha[i] * sign[i] * w;
      if (ds == 0.0) continue;  // exact zeros, which leave the (+0 started) sums as they are
      #pragma GCC unroll 4
      for (int e = outer[i], end = outer[i + 1]; e < end; ++e) mech[inner[e]] += value[e] * ds;
    }
    const double* const dof_free = p_.free.data();
    for (Eigen::Index j = 0; j < dofs; ++j) mech[j] = mech[j] * dof_free[j];
    work_.du.resize(dofs);
    contact_linear(s, work_.mech, work_.du);
    // The trace change (B' du) ./ area and the force's change at sub.
    const double* const du = work_.du.data();
    const double* const area = p_.area.data();
    const double* const trace = s.trace.data();
    const double* const q = s.q.data();
    const double laminate = p_.laminate;
    for (std::size_t b = 0; b < k; ++b) {
      const Eigen::Index i = sub[b];
      double t = 0.0;
      for (int e = outer[i], end = outer[i + 1]; e < end; ++e) t += value[e] * du[inner[e]];
      const double dtrace = (0.0 + 1.0 * t) / area[i];  // as Eigen's row-major product: 0 + 1 t
      const double dalpha_i = dalpha[i], beta = std::fabs(chi[i]);
      const double ddrive = dalpha_i * std::fabs(trace[i]) + alpha[i] * sign[i] * dtrace - dc[i];
      const double dq = 2.0 * alpha[i] * dalpha_i / laminate;
      df_sub[b] = ddrive - q[i] * w_sub[b] - dq * beta + (upper[(std::size_t)i] ? dq : 0.0);
    }
  }

  // Solves the step from chi (in/out), contact reactions r and thresholds (in/out); T and u
  // receive the final state's temperature and displacement.
  void solve(const StepSettings& set, Eigen::VectorXd& chi, Eigen::VectorXd& r, Eigen::VectorXd& threshold,
             Eigen::VectorXd& T, Eigen::VectorXd& u) {
    // (r and threshold keep the step's start until the end: the floor probe's contact start)
    StepState s = evaluate(chi, r, threshold);
    switch_variants(s);
    if (set.snap_trial && s.residual_norm > set.tol) snap_trial(s, set.tol);
    double best = s.residual_norm;  // the smallest residual so far (the watchdog's)
    double radius = 1.0;            // the trust region, fraction units (max norm)
    // Progress: the iteration at which the residual last fell to half of its value there. A step
    // that makes none for `stall` iterations stops (the caller's fall-back takes it over: at
    // the paper's scale such steps crept for their whole 50 iterations).
    double mark = s.residual_norm;
    int marked = 0;
    int rounds = set.pdas_rounds;  // raised for the rest of the step once a curvature move stalls
    bool dense_tried = false;      // dense_newton, at most once a step
    // Iterations that took the gradient step on a block of at most dense_block free points after
    // their Newton rounds had cost more products than the block has points: after early_dense of
    // them in a row the dense move (one product a point) is tried, once a step, instead of after
    // `stall` iterations without halving (sleeve-offset's step 579 crept 20 iterations of about
    // 250 products each).
    int creeping = 0;  // consecutive such iterations
    bool creeping_tried = false;
    int curvature_stalls = 0;  // negative-curvature moves in a row that did not halve the residual
    while (s.residual_norm > set.tol && stats_.iterations < set.maxit) {
      if (set.product_budget > 0 && stats_.products > set.product_budget) {
        stats_.failure = "its " + std::to_string(stats_.products) + " products passed the trial's budget of " +
                         std::to_string(set.product_budget);
        stats_.trial_given_up = true;
        break;
      }
      if (set.product_budget > 0 && set.trial_curvature_stalls > 0 &&
          (curvature_stalls >= set.trial_curvature_stalls ||
           (curvature_stalls > 0 && s.residual_norm >= set.trial_stall_residual))) {
        stats_.failure = std::to_string(curvature_stalls) + " negative-curvature move(s) in a row did not halve the residual (" +
                         std::to_string(s.residual_norm) + ")";
        stats_.trial_given_up = true;
        break;
      }
      const int stall = p_.dissipation > 0 ? set.stall_dissipative : set.stall;
      if (set.early_dense > 0 && creeping >= set.early_dense && !dense_tried && !creeping_tried) {
        creeping_tried = true;
        if (dense_newton(set, s)) break;
        best = std::min(best, s.residual_norm);
        if (s.residual_norm <= 0.5 * mark) mark = s.residual_norm, marked = stats_.iterations;
        continue;
      }
      if (!dense_tried && stats_.iterations - marked >= stall) {
        // The globalisation on W stalls where the solution is a saddle of W on a small unstable
        // block (its curvature moves and gradient steps creep toward it): dense Newton moves
        // on the law itself, judged by the residual, finish such a step (once a step: their
        // moves only lower the residual; should they halve it, the W moves go on from there).
        // Tried earlier (after 3 iterations without halving) it changed default runs' steps the
        // W moves solve (elliptic-friction's peak temperature by 0.5 K, another solution) and
        // left 3 of sleeve-offset a = 2875's steps unsolved (docs/measurements.md#m-dense-newton).
        dense_tried = true;
        if (dense_newton(set, s)) break;
        best = std::min(best, s.residual_norm);
        if (s.residual_norm <= 0.5 * mark) mark = s.residual_norm, marked = stats_.iterations;
        continue;
      }
      if (stats_.iterations - marked >= stall) {
        stats_.failure = "the residual did not halve in " + std::to_string(stall) + " iterations";
        // In a trial the step is taken again shorter rather than by the caller's nested loops, which
        // a trial then stops at their own limits (sleeve-elliptic-friction -tol 1e-3: 1979 products
        // and the nested loops' iterations for nothing); the last try keeps the fall-back.
        stats_.trial_given_up = set.product_budget > 0;
        break;
      }
      ++stats_.iterations;
      const Eigen::VectorXd beta = s.chi.cwiseAbs();
      const Classified cl = classify(s, beta);
      Classified region = cl;  // the intervals cut to the trust region
      for (Eigen::Index i = 0; i < beta.size(); ++i) {
        region.lo[i] = std::max(cl.lo[i], beta[i] - radius);
        region.hi[i] = std::min(cl.hi[i], beta[i] + radius);
      }
      Eigen::VectorXd d;
      const double before = s.residual_norm;
      const int products_before = stats_.products;
      Move tried = newton_direction(s, beta, region, set, d, set.saddle_newton, rounds);
      Search found;
      if (tried == SaddleNewton) {
        // The step's solution is a stationary point of W that is not a minimum (W falls along a
        // mode of the front that breaks the ring's symmetry, as between neighbouring triangles
        // of one layer; the nested loops converge to it, an energy descent leaves it): the Newton
        // move is taken when it halves the smallest residual so far, which cannot cycle, and the
        // energy's moves are tried otherwise.
        found = try_move(s, beta, region, d, set.tol, best, true, false);
        if (found.ok) ++stats_.saddle_steps;
        else tried = newton_direction(s, beta, region, set, d, false, rounds);
      }
      if (!found.ok && tried != Gradient) {
        if (tried == NegativeCurvature) ++stats_.curvature_steps;
        // The move against the quadratic model of W: accepted when W falls by at least a tenth
        // of the model's prediction (or the step is solved, or a Newton move halves the best
        // residual); the region grows after a good full-size move and shrinks after a poor one.
        found = try_move(s, beta, region, d, set.tol, best, tried == Newton, true);
        const double size = d.lpNorm<Eigen::Infinity>();
        if (found.ratio > 0.75 && size >= 0.99 * radius) radius = std::min(1.0, 2 * radius);
        else if (found.ratio < 0.25) radius = std::max(1e-12, 0.25 * size);
        if (!found.ok && tried == Newton && radius > 1e-9) continue;  // a smaller region, the same point
      }
      bool gradient_taken = false;
      if (!found.ok || tried == NegativeCurvature) {
        // The gradient step; after a move along unstable directions, the one of the two that
        // leaves the smaller residual (a snap of the whole ring goes faster by the local steps).
        ++stats_.gradient_steps;
        Search gradient = line_search(s, beta, cl, gradient_direction(s, cl), set.tol);
        if (gradient.ok && (!found.ok || gradient.state.residual_norm < found.state.residual_norm))
          found = std::move(gradient), gradient_taken = true;
      }
      int nfree = 0;
      for (char f : cl.free) nfree += f;
      const bool crept = gradient_taken && nfree <= set.dense_block && stats_.products - products_before > nfree;
      creeping = crept ? creeping + 1 : 0;
      if (!found.ok) {
        stats_.failure = "neither the trust-region move nor the gradient step lowers the step's energy";
        break;
      }
      s = std::move(found.state);
      switch_variants(s);
      const bool curvature_stalled = tried == NegativeCurvature && !(s.residual_norm <= 0.5 * before);
      curvature_stalls = curvature_stalled ? curvature_stalls + 1 : 0;
      if (curvature_stalled) rounds = std::max(rounds, set.pdas_rounds_stalled);
      best = std::min(best, s.residual_norm);
      if (s.residual_norm <= 0.5 * mark) mark = s.residual_norm, marked = stats_.iterations;
      if (set.trace) {
        std::fprintf(set.trace, "step iteration %d: %s move, residual %.3e, %d free points, %d evaluations, %d products\n",
                     stats_.iterations,
                     tried == Newton ? "newton" : tried == NegativeCurvature ? "curvature" : tried == SaddleNewton ? "saddle newton" : "gradient",
                     s.residual_norm, nfree, stats_.evaluations, stats_.products);
      }
    }
    stats_.residual = s.residual_norm;
    stats_.converged = s.residual_norm <= set.tol;
    if (!stats_.converged && stats_.failure.empty())
      stats_.failure = std::to_string(stats_.iterations) + " iterations";
    if (!stats_.converged && set.floor_factor > 0) {
      if (p_.contact && r.size()) {
        const StepState probe = evaluate(s.chi, r, threshold);
        stats_.residual_noise = (probe.residual - s.residual).lpNorm<Eigen::Infinity>();
      }
      stats_.floor_is_noise = s.residual_norm <= set.floor_factor * stats_.residual_noise;
      stats_.at_floor = stats_.floor_is_noise || s.residual_norm <= set.roundoff_floor;
      // (a shorter step meets the floor too: sleeve-3d -mu 0.2 -steptol 1e-11 took 13936 steps,
      // each cut until its start already met the tolerance, to t = 50 s of 100 in 275 s)
      if (stats_.at_floor) stats_.trial_given_up = false;
      if (set.trace)
        std::fprintf(set.trace, "step floor probe: residual %.3e, noise %.3e%s\n", s.residual_norm,
                     stats_.residual_noise, stats_.at_floor ? " (at the floor)" : "");
    }
    if (set.trace)
      std::fprintf(set.trace, "step end: %s, %d products\n", stats_.converged ? "converged" : stats_.failure.c_str(),
                   stats_.products);
    chi = s.chi;
    r = s.r;
    threshold = s.threshold;
    T = s.T;
    u = s.u;
  }

 private:
  struct Classified {
    std::vector<char> free, upper;
    Eigen::VectorXd force, lo, hi;
  };

  void check() const {
    const Eigen::Index n = p_.area.size();
    if (!p_.heat || !p_.stiffness) throw std::invalid_argument("step: the heat and stiffness factors are required");
    const Eigen::Index nodes = p_.heat->size(), dofs = p_.stiffness->size();
    auto need = [](bool ok, const char* what) {
      if (!ok) throw std::invalid_argument(std::string("step: ") + what);
    };
    need(p_.heat_rhs.size() == nodes && p_.heat_mask.size() == nodes, "heat right side and mask of the heat matrix's size");
    need(p_.latent.rows() == nodes && p_.latent.cols() == n, "latent load: nodes x points");
    need(p_.interp.rows() == n && p_.interp.cols() == nodes, "interpolation: points x nodes");
    need(p_.load.rows() == dofs && p_.load.cols() == n, "load operator B: dofs x points");
    need(p_.force.size() == dofs && p_.free.size() == dofs, "load and dof mask of the stiffness's size");
    need(p_.kappa.size() == n && p_.chi_start.size() == n && p_.b_start.size() == n, "per-point data of one length");
    need(p_.threshold_offset.size() == 0 || p_.threshold_offset.size() == n, "threshold offset per point (or none)");
    need(p_.laminate > 0, "the laminate modulus lambda + 2 mu must be > 0");
    need(p_.dissipation >= 0 && std::isfinite(p_.dissipation) && p_.dissipation_scale >= 0 &&
             std::isfinite(p_.dissipation_scale),
         "the dissipation k (Pa) and k / dt must be finite and >= 0");
    for (Eigen::Index i = 0; i < n; ++i)
      if (!(p_.area[i] > 0)) throw std::invalid_argument("step: point " + std::to_string(i) + " has no area");
    p_.law.validate();
    if (p_.contact) {
      const Eigen::Index m = p_.gap.size();
      const Eigen::Index rows = p_.contact_rows;
      need(rows == 2 || rows == 3, "contact rows per node: 2 (n, t) or 3 (n, t1, t2: the cone)");
      need(p_.contact->w.rows() == rows * m && p_.contact->y.rows() == dofs, "contact problem of the step's sizes");
      need(p_.slip_reference.size() == (rows - 1) * m && p_.tangent_free.size() == m && p_.mu.size() == m,
           "per-contact-node data of one length (the slip references: 2 per node on the cone)");
      need(p_.slip_tol >= 0 && p_.slip_maxit >= 1, "slip-threshold tolerance >= 0 and limit >= 1");
    }
  }

  void heat_solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
    ++stats_.heat_solves;
    p_.heat->forward_into(span<const double>(rhs.data(), (std::size_t)rhs.size()), work_.heat_z);
    p_.heat->backward_in_place(work_.heat_z, span<double>(x.data(), (std::size_t)x.size()));
  }

  bool friction() const { return p_.contact && p_.mu.size() && p_.mu.maxCoeff() > 0; }

  // Signorini-Coulomb on the condensed problem for the right side `mech`: one forward solve, the
  // PSOR (inside the slip-threshold fixed point g = mu r_n when there is friction), one backward
  // solve (the statuses for the linearisation: freeze_statuses, at the first product).
  // `untransformed`: no point holds a fraction (the load is f .* free alone, the same from step to
  // step in a run's tail). A frictionless solve of such a state keeps its warm start when the
  // first sweep already finds it converged (that sweep's moves are round-off), so that the same
  // load and reactions give the same reactions and displacement again; such a solve is
  // remembered (p_.contact_memo) and the next identical one takes its displacement without a
  // back-solve. The memo is a cache of that deterministic map: a run resumed from a checkpoint
  // (no memo) computes the same bits.
  enum class Memo { None, Remembered, Reused };  // what contact_solve did with p_.contact_memo
  Memo contact_solve(const Eigen::VectorXd& mech, StepState& s, bool untransformed = false) {
    const bool reusable = untransformed && p_.mechanics_version != 0 && !friction();
    if (reusable && memo_holds(mech, s)) {
      // Counted as the solve it stands for (one stiffness solve, one sweep with contact), so that
      // a run's counts do not depend on whether the memo was there (a resumed run's first step).
      ++stats_.stiffness_solves;
      ++stats_.reused_solves;
      if (p_.contact) ++stats_.psor_sweeps;
      s.u = p_.contact_memo.u;
      return Memo::Reused;
    }
    ++stats_.stiffness_solves;
    span<const double> rhs(mech.data(), (std::size_t)mech.size());
    Eigen::VectorXd& z = work_.stiffness_z;
    p_.stiffness->forward_into(rhs, z);
    if (!p_.contact) {
      p_.stiffness->backward_in_place(z, span<double>(s.u.data(), (std::size_t)s.u.size()));
      if (!reusable) return Memo::None;
      remember(mech, s);
      return Memo::Remembered;
    }
    const DelassusFactor& d = *p_.contact;
    const Eigen::VectorXd q =
        cone() ? cone_free_motion(d, contact_motion(d, z), step_detail::as_span(p_.gap),
                                  step_detail::as_span(p_.slip_reference))
               : contact_free_motion(d, contact_motion(d, z), step_detail::as_span(p_.gap),
                                     step_detail::as_span(p_.slip_reference), step_detail::as_span(p_.tangent_free));
    bool kept = false;
    if (!friction()) {
      if (reusable) {
        const Eigen::VectorXd warm = s.r;
        if (run_psor(q, s) == 1) s.r = warm, kept = true;
      } else {
        run_psor(q, s);
      }
    } else if (cone()) {
      // Coulomb's cone at once: the disk's radius mu r_n inside the sweeps and the polish
      // (psor_cone's coulomb_mu), not the slip-threshold fixed point around Tresca solves, whose
      // every iteration factorised the whole 3m x 3m polish (docs/model.md, the clamping on
      // Coulomb's cone); the thresholds then read mu r_n of the answer.
      update_thresholds(s);
      if (cone_mu_.size() != p_.mu.size()) cone_mu_ = p_.mu.cwiseProduct(p_.tangent_free);
      run_psor(q, s, &cone_mu_);
      update_thresholds(s);
      stats_.slip_iterations += 1;
      cone_slip(q, s);
    } else {
      update_thresholds(s);
      int it = 0;
      double change = 0;
      while (it < p_.slip_maxit) {
        ++it;
        run_psor(q, s);
        change = update_thresholds(s);
        if (change <= p_.slip_tol) break;
      }
      stats_.slip_iterations += it;
      if (change > p_.slip_tol)
        throw std::runtime_error("slip-threshold fixed point (Coulomb) did not converge: " + std::to_string(it) +
                                 " iterations, relative change of g " + std::to_string(change) + " > tol " +
                                 std::to_string(p_.slip_tol));
    }
    add_contact_load_sparse(d, s.r, z, work_.load);
    p_.stiffness->backward_in_place(z, span<double>(s.u.data(), (std::size_t)s.u.size()));
    if (!kept) return Memo::None;
    remember(mech, s);
    return Memo::Remembered;
  }

  // Whether the memo holds the contact solve of (mech, s.r): every input bit for bit.
  bool memo_holds(const Eigen::VectorXd& mech, const StepState& s) const {
    const StepProblem::ContactMemo& m = p_.contact_memo;
    auto same = [](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
      return a.size() == b.size() && std::equal(a.data(), a.data() + a.size(), b.data());
    };
    return m.version == p_.mechanics_version && m.omega == p_.psor.omega && m.tol == p_.psor.tol &&
           same(m.mech, mech) && same(m.r, s.r) && same(m.threshold, s.threshold) && same(m.gap, p_.gap) &&
           same(m.slip_reference, p_.slip_reference) && same(m.tangent_free, p_.tangent_free);
  }

  void remember(const Eigen::VectorXd& mech, const StepState& s) const {
    StepProblem::ContactMemo& m = p_.contact_memo;
    m.version = p_.mechanics_version;
    m.omega = p_.psor.omega;
    m.tol = p_.psor.tol;
    m.mech = mech;
    m.r = s.r;
    m.threshold = s.threshold;
    m.gap = p_.gap;
    m.slip_reference = p_.slip_reference;
    m.tangent_free = p_.tangent_free;
    m.u = s.u;
    m.trace.resize(0);  // evaluate's, once it has formed it from u
  }

  bool tangential(Eigen::Index i) const {
    return p_.tangent_free[i] != 0 && p_.contact->w(2 * i + 1, 2 * i + 1) != 0.0;
  }

  bool cone() const { return p_.contact_rows == 3; }

  int run_psor(const Eigen::VectorXd& q, StepState& s, const Eigen::VectorXd* coulomb_mu = nullptr) {
    const PsorResult res =
        cone() ? psor_cone(p_.contact->w, q, s.threshold, p_.psor.omega, p_.psor.tol, p_.psor.maxit, s.r, p_.psor.polish,
                           coulomb_mu, &polish_memory_)
               : psor_condensed(p_.contact->w, q, s.threshold, p_.psor.omega, p_.psor.tol, p_.psor.maxit, s.r,
                                p_.psor.polish);
    stats_.psor_sweeps += res.iterations;
    if (!res.converged)
      throw std::runtime_error("contact: PSOR (condensed) did not converge: " + std::to_string(res.iterations) +
                               " sweeps, relative change " + std::to_string(res.residual) + " > tol " +
                               std::to_string(p_.psor.tol) +
                               (p_.psor.polish == 0 ? " (plain PSOR, -psorpolish 0: an ill-conditioned contact problem needs "
                                                      "the active-set polish, -psorpolish 10; or raise -psormaxit)"
                                                    : " (raise -psormaxit or check omega)"));
    return res.iterations;
  }

  // g = mu r_n (0 where the tangential motion is blocked); the relative change, as contact.idp's
  // ContactUpdateThresholds.
  double update_thresholds(StepState& s) const {
    const Eigen::Index m = p_.gap.size(), rows = p_.contact_rows;
    double change = 0, size = 0;
    for (Eigen::Index i = 0; i < m; ++i) {
      const double g = p_.mu[i] * std::max(0.0, s.r[rows * i]) * p_.tangent_free[i];
      change = std::max(change, std::fabs(g - s.threshold[i]));
      size = std::max(size, g);
      s.threshold[i] = g;
    }
    return size > 0 ? change / size : change;
  }

  // The contact rows that move under a small change of the load, at the statuses of s: active
  // normal rows (r_n > 0) and sticking tangential rows (|r_t| < g) keep their motion at zero;
  // a sliding node's r_t follows its r_n (r_t = +-mu r_n); the others stay at zero.
  void freeze_statuses(const StepState& s) const {
    if (s.frozen) return;
    s.frozen = true;
    if (cone()) return freeze_cone_statuses(s);
    const Eigen::MatrixXd& W = p_.contact->w;
    const Eigen::Index m = p_.gap.size();
    s.moving.clear();
    s.slide.assign((std::size_t)m, 0.0);
    for (Eigen::Index i = 0; i < m; ++i) {
      if (!(s.r[2 * i] > 0)) continue;
      s.moving.push_back((int)(2 * i));
      if (!tangential(i) || !(s.threshold[i] > 0)) continue;
      if (std::fabs(s.r[2 * i + 1]) < s.threshold[i] * (1 - 1e-9)) s.moving.push_back((int)(2 * i + 1));
      else s.slide[(std::size_t)i] = s.r[2 * i + 1] > 0 ? 1.0 : -1.0;
    }
    const Eigen::Index k = (Eigen::Index)s.moving.size();
    if (k == 0) return;
    Eigen::MatrixXd A(k, k);
    for (Eigen::Index a = 0; a < k; ++a)
      for (Eigen::Index b = 0; b < k; ++b) {
        const int row = s.moving[(std::size_t)a], col = s.moving[(std::size_t)b];
        double v = W(row, col);
        if (col % 2 == 0 && s.slide[(std::size_t)(col / 2)] != 0.0)
          v += W(row, col + 1) * s.slide[(std::size_t)(col / 2)] * p_.mu[col / 2];
        A(a, b) = v;
      }
    s.statuses.compute(A);
  }

  // du = d u / d mech (the linearised contact step): forward, the moving rows' reactions, backward.
  void contact_linear(const StepState& s, const Eigen::VectorXd& dmech, Eigen::VectorXd& du) {
    ++stats_.stiffness_solves;
    span<const double> rhs(dmech.data(), (std::size_t)dmech.size());
    Eigen::VectorXd& z = work_.stiffness_z;
    p_.stiffness->forward_into(rhs, z);
    if (!p_.contact) {
      p_.stiffness->backward_in_place(z, span<double>(du.data(), (std::size_t)du.size()));
      return;
    }
    const DelassusFactor& d = *p_.contact;
    freeze_statuses(s);
    const Eigen::Index k = (Eigen::Index)s.moving.size();
    if (k > 0) {
      if (column_of_row_.empty()) {  // the column of Y standing for each contact row (-1: none)
        column_of_row_.assign((std::size_t)d.w.rows(), -1);
        for (std::size_t j = 0; j < d.rows.size(); ++j) column_of_row_[(std::size_t)d.rows[j]] = (int)j;
      }
      // Columns the caller keeps give their whole product at once (one call: the ranks' sum), not
      // a column's entry a row.
      if (d.caller_columns) work_.caller_motion = contact_motion(d, z);
      if (cone()) {
        cone_linear(s, z);
        p_.stiffness->backward_in_place(z, span<double>(du.data(), (std::size_t)du.size()));
        return;
      }
      Eigen::VectorXd& b = work_.moving_motion;
      b.resize(k);
      for (Eigen::Index a = 0; a < k; ++a)  // W dr = dq = -d(H u_free), on the moving rows only
        b[a] = -motion_at(s.moving[(std::size_t)a], z);
      Eigen::VectorXd& x = work_.moving_reaction;
      x.resize(k);
      x = s.statuses.solve(b);  // into x's storage (the same operations as a new vector's)
      Eigen::VectorXd& dr = work_.dr;
      dr.setZero(p_.contact->w.rows());
      for (Eigen::Index a = 0; a < k; ++a) {
        const int row = s.moving[(std::size_t)a];
        dr[row] = x[a];
        if (row % 2 == 0 && s.slide[(std::size_t)(row / 2)] != 0.0)
          dr[row + 1] = s.slide[(std::size_t)(row / 2)] * p_.mu[row / 2] * x[a];
      }
      add_contact_load_sparse(d, dr, z, work_.load);
    }
    p_.stiffness->backward_in_place(z, span<double>(du.data(), (std::size_t)du.size()));
  }

  // H S K^-1 b at contact row `row`, from the forward half z of b: the factor's entry
  // (contact_motion_at), or that of the caller's whole product (contact_linear's caller_motion).
  double motion_at(int row, const Eigen::VectorXd& z) const {
    if (p_.contact->caller_columns) return work_.caller_motion[row];
    return contact_motion_at(*p_.contact, column_of_row_[(std::size_t)row], z);
  }

  // |w_t| of each node at the cone's solve (w = W r - q): a sliding node's slip, whose size sets how
  // far its direction turns under a change of the load (freeze_cone_statuses).
  void cone_slip(const Eigen::VectorXd& q, StepState& s) const {
    const Eigen::Index m = p_.gap.size();
    const Eigen::VectorXd w = p_.contact->w * s.r - q;
    s.slip.resize(m);
    for (Eigen::Index i = 0; i < m; ++i) s.slip[i] = std::hypot(w[3 * i + 1], w[3 * i + 2]);
  }

  // freeze_statuses on the cone (contact_rows 3). Per pressing node (r_n > 0): its normal row; a
  // sticking node's free tangential rows (|r_t| < g); a sliding node's tangential reaction follows
  // its normal one along its direction e = r_t / |r_t| (r_t = g e, g = mu r_n: dr_t = mu dr_n e +
  // g de). Where both tangential motions are free the direction turns with the slip w_t = -|w_t| e:
  // g de = -(g / |w_t|) (I - e e') dw_t, so across it (e_perp = (-e_2, e_1)) the node keeps
  // dw_perp + (|w_t| / g) dr_perp = 0, a stick of compliance |w_t| / g (the derivative of the
  // disk's projection that psor_cone's polish takes). Each moving unknown a tests the rows of its
  // node along cone_test and moves them along cone_trial.
  void freeze_cone_statuses(const StepState& s) const {
    const Eigen::MatrixXd& W = p_.contact->w;
    const Eigen::Index m = p_.gap.size();
    s.moving.clear();
    s.cone_test.clear();
    s.cone_trial.clear();
    s.cone_compliance.clear();
    auto add = [&s](Eigen::Index i, const double (&test)[3], const double (&trial)[3], double compliance) {
      s.moving.push_back((int)(3 * i));
      s.cone_test.insert(s.cone_test.end(), test, test + 3);
      s.cone_trial.insert(s.cone_trial.end(), trial, trial + 3);
      s.cone_compliance.push_back(compliance);
    };
    const double normal[3] = {1, 0, 0}, first[3] = {0, 1, 0}, second[3] = {0, 0, 1};
    for (Eigen::Index i = 0; i < m; ++i) {
      const Eigen::Index n = 3 * i;
      if (!(s.r[n] > 0)) continue;
      const double g = s.threshold[i], rt = std::hypot(s.r[n + 1], s.r[n + 2]);
      const bool free1 = W(n + 1, n + 1) != 0.0, free2 = W(n + 2, n + 2) != 0.0;
      if (!(g > 0) || (!free1 && !free2)) {
        add(i, normal, normal, 0.0);
      } else if (rt < g * (1 - 1e-9)) {
        add(i, normal, normal, 0.0);
        if (free1) add(i, first, first, 0.0);
        if (free2) add(i, second, second, 0.0);
      } else {
        const double mu = p_.mu[i] * p_.tangent_free[i], e1 = s.r[n + 1] / rt, e2 = s.r[n + 2] / rt;
        const double follows[3] = {1, mu * e1, mu * e2}, across[3] = {0, -e2, e1};
        add(i, normal, follows, 0.0);
        if (free1 && free2) add(i, across, across, s.slip.size() == m ? s.slip[i] / g : 0.0);
      }
    }
    const Eigen::Index k = (Eigen::Index)s.moving.size();
    if (k == 0) return;
    Eigen::MatrixXd A(k, k);
    for (Eigen::Index a = 0; a < k; ++a)
      for (Eigen::Index b = 0; b < k; ++b) {
        const Eigen::Index row = s.moving[(std::size_t)a], col = s.moving[(std::size_t)b];
        const double* test = &s.cone_test[(std::size_t)(3 * a)];
        const double* trial = &s.cone_trial[(std::size_t)(3 * b)];
        double v = a == b ? s.cone_compliance[(std::size_t)a] : 0.0;
        for (int c = 0; c < 3; ++c)
          for (int e = 0; e < 3; ++e) v += test[c] * W(row + c, col + e) * trial[e];
        A(a, b) = v;
      }
    s.statuses.compute(A);
  }

  // contact_linear's contact part on the cone: the moving unknowns' reactions for the forward
  // half z of the load's change, added into z.
  void cone_linear(const StepState& s, Eigen::VectorXd& z) {
    const DelassusFactor& d = *p_.contact;
    const Eigen::Index k = (Eigen::Index)s.moving.size();
    Eigen::VectorXd& b = work_.moving_motion;
    b.resize(k);
    for (Eigen::Index a = 0; a < k; ++a) {  // W dr = dq = -d(H u_free), tested along cone_test
      double v = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double t = s.cone_test[(std::size_t)(3 * a + c)];
        if (t != 0.0) v -= t * motion_at(s.moving[(std::size_t)a] + c, z);
      }
      b[a] = v;
    }
    Eigen::VectorXd& x = work_.moving_reaction;
    x.resize(k);
    x = s.statuses.solve(b);
    Eigen::VectorXd& dr = work_.dr;
    dr.setZero(d.w.rows());
    for (Eigen::Index a = 0; a < k; ++a)
      for (int c = 0; c < 3; ++c) dr[s.moving[(std::size_t)a] + c] += s.cone_trial[(std::size_t)(3 * a + c)] * x[a];
    add_contact_load_sparse(d, dr, z, work_.load);
  }

  // The force f = -dW/dbeta / area on point i of state s at fraction b, on the side of its held
  // fraction that `below` names: psi's slope there, q + k below held and -k above (k the
  // dissipation, 0 for the paper's law). classify and energy_change read the law's sides here.
  double side_force(const StepState& s, Eigen::Index i, double b, bool below) const {
    return s.drive[i] - s.q[i] * b + (below ? s.q[i] + p_.dissipation : -p_.dissipation);
  }

  // Per point: free (may move) or bound, the force it feels in its interval, the interval.
  Classified classify(const StepState& s, const Eigen::VectorXd& beta) const {
    const Eigen::Index n = beta.size();
    Classified cl;
    cl.free.assign((std::size_t)n, 0);
    cl.upper.assign((std::size_t)n, 0);
    cl.force = Eigen::VectorXd::Zero(n);
    cl.lo = Eigen::VectorXd::Zero(n);
    cl.hi = Eigen::VectorXd::Ones(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double q = s.q[i], held = s.held[i], b = beta[i];
      if (!(q > 0)) continue;  // alpha = 0: the law has no free fraction (the target is 0 or 1)
      // Moving up from b, and down (at b == held the two sides differ by q + 2 k).
      const double right = side_force(s, i, b, b < held), left = side_force(s, i, b, b <= held);
      bool free = false;
      double force = 0, lo = 0, hi = 1;
      if (b <= 0) {
        free = right > 0, force = std::max(right, 0.0), lo = 0, hi = held > 0 ? held : 1.0;
      } else if (b >= 1) {
        free = left < 0, force = std::min(left, 0.0), lo = held < 1 ? held : 0.0, hi = 1;
      } else if (b == held) {
        if (right > 0) free = true, force = right, lo = held, hi = 1;
        else if (left < 0) free = true, force = left, lo = 0, hi = held;
      } else if (b > held) {
        free = true, force = right, lo = held, hi = 1;
      } else {
        free = true, force = right, lo = 0, hi = held;
      }
      cl.free[(std::size_t)i] = free;
      cl.force[i] = force;
      cl.lo[i] = lo;
      cl.hi[i] = hi;
      cl.upper[(std::size_t)i] = hi == held;
    }
    return cl;
  }

  // A transformed point whose strain trace has the other sign takes the other martensite (the
  // variant the trace selects, as the local step does: a lower energy at the same fraction),
  // and the state is evaluated again; repeated while the variants change (at most 5 times).
  // The fraction moves of W cannot express a change of variant: without this, a point whose
  // trace changed sign would keep a residual of 2 |chi|.
  // With the dissipation k the switch is not weighed against its cost k (|chi| + |chi_start|):
  // the nested loops' local step (project_fraction) takes the trace's variant unconditionally,
  // the new one then growing from none (held = 0) only past drive = k, and both solvers solve
  // the same law; its dissipated heat is counted by evaluate()'s source |chi - chi_start|.
  void switch_variants(StepState& s) {
    for (int pass = 0; pass < 5; ++pass) {
      Eigen::VectorXd chi = s.chi;
      int switched = 0;
      for (Eigen::Index i = 0; i < chi.size(); ++i)
        if (chi[i] != 0.0 && chi[i] * s.sign[i] < 0) chi[i] = -chi[i], ++switched;
      if (switched == 0) return;
      stats_.variant_switches += switched;
      s = evaluate(chi, s.r, s.threshold);
    }
  }

  // The snap (header, step 0): when the law moves at least half of the points at once (a whole-ring
  // transformation, as the austenite ring's first step to martensite), the state with each moving
  // point at the end of its interval that its target lies toward is evaluated once, and kept when
  // it solves the step. Such a block's linearisation is unstable (W concave on it: each point's
  // eigenstrain raises its neighbours' drive), and the moves below reach that vertex one pinned
  // point per active-set round (the default run's first step: 205 products). Kept only on the
  // residual test, so it cannot cycle; a trial that fails costs one evaluation.
  void snap_trial(StepState& s, double tol) {
    const Eigen::Index n = s.chi.size();
    const Eigen::VectorXd beta = s.chi.cwiseAbs();
    const Classified cl = classify(s, beta);  // the intervals: [0, held] or [held, 1]
    Eigen::VectorXd chi = s.chi;
    Eigen::Index moved = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!(std::fabs(s.residual[i]) > tol)) continue;
      chi[i] = s.sign[i] * (target(s, i, p_.dissipation) > beta[i] ? cl.hi[i] : cl.lo[i]);
      ++moved;
    }
    if (2 * moved < n) return;
    StepState trial = evaluate(chi, s.r, s.threshold);
    if (trial.residual_norm <= tol) {
      ++stats_.snaps;
      s = std::move(trial);
    }
  }

  enum Move { Gradient = 0, Newton = 1, NegativeCurvature = 2, SaddleNewton = 3 };
  // The Newton move on the free points (header, step 2): rounds of an active-set method on the
  // linearised step, from the model point d (the move so far; model = the linearised force there):
  //   - GMRES on the free, unpinned points gives the Newton correction from d;
  //   - a stable block (every Ritz value with a positive real part): d += correction; the points
  //     that leave their interval are pinned to its end, pinned points whose model force points
  //     back inside are released; the rounds stop when nothing changes or the pinned set repeats;
  //   - an unstable block (W concave along its Ritz vector v; a snap of part of the front): d
  //     moves along v, the way the model force pushes, until the first point reaches the end of
  //     its interval, where it is pinned (the active-set method of nonconvex quadratic programs).
  // Newton: the rounds ended on a stable block and d is a descent direction of W;
  // NegativeCurvature: they ran out on an unstable block and d is a descent direction; Gradient
  // otherwise.
  Move newton_direction(const StepState& s, const Eigen::VectorXd& beta, const Classified& cl,
                        const StepSettings& set, Eigen::VectorXd& d, bool allow_saddle, int rounds) {
    const Eigen::Index n = beta.size();
    d = Eigen::VectorXd::Zero(n);
    std::vector<char> pinned((std::size_t)n, 0);
    std::vector<std::vector<char>> seen;
    bool any_free = false;
    for (Eigen::Index i = 0; i < n; ++i) any_free |= cl.free[(std::size_t)i] != 0;
    if (!any_free) return Gradient;
    // Inexact Newton: the linearised step solved to a relative accuracy of the step's residual
    // (which makes the Newton iteration converge quadratically near the solution), but never
    // tighter than `forcing` needs far from it, where a new active set or a pinned point makes
    // the next linearisation differ anyway (docs/parameters.md, "Step solver": 0.01 cost the
    // transient of the 72-layer mesh 3.2 times the back-solves of 0.1).
    const double rtol = std::max(1e-12, std::min(set.forcing, s.residual_norm));
    recycled_.capacity = set.recycle;
    recycled_.stale = !recycled_.empty();  // a new linearisation
    const Eigen::VectorXd weight = s.q.cwiseProduct(p_.area);  // D of deflation.hpp
    double first_rhs = 0;
    bool stable = false, saddle = false;
    bool pinned_by_curvature = false;  // the last round moved along a Ritz vector
    Eigen::VectorXd model = cl.force;
    // The release rule: pinned point i sits at an end of its interval at the move's end, and the
    // model force there points back inside.
    auto points_back_inside = [&](Eigen::Index i) {
      const double end = beta[i] + d[i];
      const bool at_hi = std::fabs(end - cl.hi[i]) <= 1e-14, at_lo = std::fabs(end - cl.lo[i]) <= 1e-14;
      return (at_hi && model[i] < 0) || (at_lo && model[i] > 0);
    };
    CoarseSpace coarse;  // of this linearisation (built at its first hard round)
    for (int round = 0; round < rounds; ++round) {
      std::vector<Eigen::Index> sub;
      for (Eigen::Index i = 0; i < n; ++i)
        if (cl.free[(std::size_t)i] && !pinned[(std::size_t)i]) sub.push_back(i);
      if (sub.empty() && pinned_by_curvature) {
        stable = true;
        break;
      }
      if (sub.empty()) {
        // A stable round's move left the interval of every point still free (a 3-point block of
        // sleeve-life -phasemodel fraction's step 1387 did): nothing to solve, but the release
        // rule of the rounds still applies, or they would stop on pins the model force
        // contradicts (there the moves then ping-ponged for 20 iterations). Released: the
        // pinned points whose model force at the pinned move points back inside; none: the
        // move solves the linearised step. (Rounds that pinned the last point along a Ritz
        // vector stop as they did: their pins are the nonconvex active-set method's.)
        ++stats_.pinned_blocks;
        std::vector<char> next = pinned;
        int released = 0;
        for (Eigen::Index i = 0; i < n; ++i)
          if (cl.free[(std::size_t)i] && points_back_inside(i)) next[(std::size_t)i] = 0, ++released;
        if (set.trace) std::fprintf(set.trace, "  round %d: every free point pinned, %d released\n", round, released);
        if (released == 0 || std::find(seen.begin(), seen.end(), next) != seen.end()) {
          stable = true;
          break;
        }
        seen.push_back(next);
        pinned = next;
        continue;
      }
      const Eigen::Index k = (Eigen::Index)sub.size();
      Eigen::VectorXd rhs(k), scale(k);
      for (Eigen::Index a = 0; a < k; ++a) {
        scale[a] = s.q[sub[(std::size_t)a]];
        rhs[a] = model[sub[(std::size_t)a]] / scale[a];
      }
      const std::vector<Eigen::Index> support = product_support(s, sub);
      auto apply = [&](const Eigen::VectorXd& x) {
        Eigen::VectorXd out(k);
        force_derivative_on(s, sub, support, x.data(), cl.upper, out.data());
        for (Eigen::Index a = 0; a < k; ++a) out[a] = -out[a] / scale[a];
        return out;
      };
      // No more accuracy than the step's tolerance needs (the residual of the linearised step,
      // in fraction units: its 2-norm bounds its max norm).
      // The first round may be a saddle's Newton move (solve): solved on through an unstable
      // block (up to gmres_maxit products: at the paper's scale such blocks took 68-119), while
      // a block that does not look clearly unstable stops at 64 (nearly singular and stable, its
      // partial solution is still a descent move; the cap measured cheaper than solving on:
      // docs/parameters.md).
      // Later rounds (after pinning) solve for the change of the move to the first round's
      // accuracy, rtol of its right side, not to rtol of their own (smaller) one.
      const bool saddle_round = allow_saddle && round == 0;
      if (round == 0) first_rhs = rhs.norm();
      const double absolute = std::max(0.1 * set.tol, round > 0 ? rtol * first_rhs : 0.0);
      // Right-preconditioned by the deflation space of the step's earlier solves (deflation.hpp:
      // the same residual, the same inertia; P = I when recycling is off); its solution and
      // Ritz vector mapped back by P. Stale images (a new linearisation) are recomputed first.
      const bool large = set.coarse && k >= set.coarse_points;
      if (large && coarse.empty() && (set.coarse_after <= 0 || hard_large_solve_)) {
        const Aggregates agg = aggregate_points(interp_by_rows(), p_.interp, sub, set.coarse_aggregate);
        coarse = build_coarse(sub, coarse_vectors(interp_by_rows(), sub, agg, set.coarse_smooth), apply);
      }
      if (coarse.empty() && recycled_.stale && !recycled_.empty()) refresh(recycled_, sub, weight, apply);
      const DeflationPreconditioner pre =
          coarse.empty() ? deflation_on(recycled_, sub, weight) : coarse_on(coarse, sub, weight, set.coarse_additive);
      auto preconditioned = [&](const Eigen::VectorXd& y) { return pre.empty() ? apply(y) : apply(pre.apply(y)); };
      step_detail::GmresResult g =
          step_detail::gmres(preconditioned, rhs, rtol, set.gmres_maxit, !saddle_round, absolute,
                             saddle_round ? 64 : std::numeric_limits<int>::max(),
                             recycled_.capacity > 0 ? set.recycle_harvest : 0);
      if (large && g.iterations >= set.coarse_after) hard_large_solve_ = true;
      if (!pre.empty()) {
        g.x = pre.apply(g.x);
        g.finite = g.x.allFinite();
        if (g.smallest_ritz_vector.size() == k) {
          g.smallest_ritz_vector = pre.apply(g.smallest_ritz_vector);
          const double norm = g.smallest_ritz_vector.norm();
          if (norm > 0) g.smallest_ritz_vector /= norm;
        }
      }
      if (recycled_.capacity > 0 && g.iterations >= set.recycle_from && g.harvest_vectors.cols() > 0) {
        const Eigen::Index h = g.harvest_vectors.cols();
        Eigen::MatrixXd vectors = Eigen::MatrixXd::Zero(n, h), images = Eigen::MatrixXd::Zero(n, h);
        for (Eigen::Index j = 0; j < h; ++j) {
          const Eigen::VectorXd v = pre.apply(g.harvest_vectors.col(j));
          for (Eigen::Index a = 0; a < k; ++a) {
            vectors(sub[(std::size_t)a], j) = v[a];
            images(sub[(std::size_t)a], j) = g.harvest_images(a, j);
          }
        }
        recycle(recycled_, vectors, images, weight);
      }
      if (set.trace)
        std::fprintf(set.trace, "  round %d: %ld unpinned, gmres %d its (%s), smallest ritz %.3e, rhs %.3e, %ld %s\n",
                     round, (long)k, g.iterations, g.converged ? "converged" : "stopped", g.smallest_ritz_real, rhs.norm(),
                     (long)pre.q.cols(), coarse.empty() ? "deflated" : "coarse");
      if (!g.finite && g.smallest_ritz_real > 0) return Gradient;
      // A converged solve whose correction lowers the model's energy is taken as a Newton
      // correction even when a Ritz value came out non-positive: near a neutral mode round-off
      // puts the smallest ones on either side of zero (the trust region judges the move).
      double descent = 0;
      if (g.converged && g.finite)
        for (Eigen::Index a = 0; a < k; ++a) descent += model[sub[(std::size_t)a]] * p_.area[sub[(std::size_t)a]] * g.x[a];
      const bool solved = g.converged && g.finite;
      if (!(g.smallest_ritz_real > 0) && solved && !(descent > 0) && saddle_round) saddle = true;
      else if (!(g.smallest_ritz_real > 0) && !(solved && descent > 0)) {
        stable = false;
        if (g.smallest_ritz_vector.size() != k) return Gradient;
        Eigen::VectorXd v = g.smallest_ritz_vector;
        double slope = 0;
        for (Eigen::Index a = 0; a < k; ++a) slope += model[sub[(std::size_t)a]] * p_.area[sub[(std::size_t)a]] * v[a];
        if (slope < 0) v = -v;
        double reach = std::numeric_limits<double>::infinity();
        Eigen::Index first = -1;
        double end = 0;
        for (Eigen::Index a = 0; a < k; ++a) {
          const Eigen::Index i = sub[(std::size_t)a];
          const double at = beta[i] + d[i];
          if (v[a] > 0 && (cl.hi[i] - at) / v[a] < reach) reach = (cl.hi[i] - at) / v[a], first = i, end = cl.hi[i];
          if (v[a] < 0 && (cl.lo[i] - at) / v[a] < reach) reach = (cl.lo[i] - at) / v[a], first = i, end = cl.lo[i];
        }
        if (first < 0 || !std::isfinite(reach)) return Gradient;
        for (Eigen::Index a = 0; a < k; ++a) d[sub[(std::size_t)a]] += reach * v[a];
        d[first] = end - beta[first];
        pinned[(std::size_t)first] = 1;
        model = cl.force + force_derivative(s, d, cl.upper);
        pinned_by_curvature = true;
        continue;
      }
      pinned_by_curvature = false;
      stable = true;
      for (Eigen::Index a = 0; a < k; ++a) d[sub[(std::size_t)a]] += g.x[a];
      // The model force at the move's end is read only by the release rule, on pinned points:
      // without any (every first round) it is not formed, and a round that pins points forms it
      // again at the pinned move below (one product fewer per Newton iteration, the same moves).
      bool any_pinned = false;
      for (Eigen::Index i = 0; i < n && !any_pinned; ++i) any_pinned = cl.free[(std::size_t)i] && pinned[(std::size_t)i];
      if (any_pinned) model = cl.force + force_derivative(s, d, cl.upper);
      // Pin the free points whose move leaves their interval; release pinned points whose model
      // force at the move's end points back inside.
      std::vector<char> next = pinned;
      bool changed = false;
      for (Eigen::Index i = 0; i < n; ++i) {
        if (!cl.free[(std::size_t)i]) continue;
        const double end = beta[i] + d[i];
        if (!pinned[(std::size_t)i]) {
          if (end > cl.hi[i]) next[(std::size_t)i] = 1, d[i] = cl.hi[i] - beta[i], changed = true;
          else if (end < cl.lo[i]) next[(std::size_t)i] = 1, d[i] = cl.lo[i] - beta[i], changed = true;
        } else if (points_back_inside(i)) {
          next[(std::size_t)i] = 0, changed = true;
        }
      }
      if (!changed) break;
      if (std::find(seen.begin(), seen.end(), next) != seen.end()) break;
      seen.push_back(next);
      pinned = next;
      model = cl.force + force_derivative(s, d, cl.upper);
    }
    if (saddle) return d.allFinite() ? SaddleNewton : Gradient;
    double slope = 0;
    for (Eigen::Index i = 0; i < n; ++i) slope += cl.force[i] * p_.area[i] * d[i];
    if (!d.allFinite() || !(slope > 0)) return Gradient;
    return stable ? Newton : NegativeCurvature;
  }

  // Dense Newton moves (StepSettings::dense_block) from s, for a step whose moves on W stalled.
  // Per iteration: the block starts as the free points; its columns of the linearisation
  // df/dbeta are built one product a point, the linearised law solved exactly on the block
  // (solve_linearised_law: the Newton move of the law, to a saddle of W as well as to a
  // minimum), and any other point whose linearised law that move breaks (by more than a
  // hundredth of the residual: a neighbour pushed off its bound or out of its band) joins the
  // block, up to 3 times. The move, cut back by halves, is accepted when the step's residual
  // max |F| falls by at least 1e-4 of its length fraction: the residual falls at every move, so
  // the iteration cannot cycle. Stops (false) when no cut of the move lowers the residual, the
  // block outgrows dense_block, or the iterations run out; true when the residual meets the
  // tolerance.
  bool dense_newton(const StepSettings& set, StepState& s) {
    while (s.residual_norm > set.tol) {
      if (stats_.iterations >= set.maxit) return false;
      const Eigen::Index n = s.chi.size();
      const Eigen::VectorXd beta = s.chi.cwiseAbs();
      const Classified cl = classify(s, beta);
      // The block: its points, forces, boxes (moves) and columns of df/dbeta (all points' rows).
      std::vector<Eigen::Index> block;
      std::vector<double> force, low, high;
      std::vector<Eigen::VectorXd> columns;
      std::vector<char> in((std::size_t)n, 0);
      for (Eigen::Index i = 0; i < n; ++i)
        if (cl.free[(std::size_t)i]) {
          block.push_back(i), in[(std::size_t)i] = 1;
          force.push_back(cl.force[i]), low.push_back(cl.lo[i] - beta[i]), high.push_back(cl.hi[i] - beta[i]);
        }
      if (block.empty() || (Eigen::Index)block.size() > set.dense_block) return false;
      ++stats_.iterations;
      Eigen::VectorXd unit = Eigen::VectorXd::Zero(n), d;
      double phi_norm = 0;
      for (int grow = 0;; ++grow) {
        for (std::size_t b = columns.size(); b < block.size(); ++b) {
          unit[block[b]] = 1.0;
          columns.push_back(force_derivative(s, unit, cl.upper));
          unit[block[b]] = 0.0;
        }
        const Eigen::Index k = (Eigen::Index)block.size();
        Eigen::MatrixXd M(k, k);
        Eigen::VectorXd f(k), q(k), l(k), u(k);
        for (Eigen::Index a = 0; a < k; ++a) {
          const Eigen::Index i = block[(std::size_t)a];
          for (Eigen::Index b = 0; b < k; ++b) M(a, b) = columns[(std::size_t)b][i];
          f[a] = force[(std::size_t)a], q[a] = s.q[i], l[a] = low[(std::size_t)a], u[a] = high[(std::size_t)a];
        }
        d = step_detail::solve_linearised_law(M, f, q, l, u, phi_norm);
        if (grow == 3) break;
        // The bound points this move pushes off their bound or out of their band, to first order.
        Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
        for (Eigen::Index b = 0; b < k; ++b) g += d[b] * columns[(std::size_t)b];
        const std::size_t before = block.size();
        for (Eigen::Index i = 0; i < n; ++i) {
          if (in[(std::size_t)i] || !(s.q[i] > 0)) continue;
          const double b = beta[i], held = s.held[i];
          const double right = side_force(s, i, b, b < held) + g[i], left = side_force(s, i, b, b <= held) + g[i];
          const double up = (b < held ? held : 1.0) - b, down = (b > held ? held : 0.0) - b;
          if (up > 0 && right / s.q[i] > 1e-2 * s.residual_norm)
            block.push_back(i), force.push_back(right - g[i]), low.push_back(0.0), high.push_back(up);
          else if (down < 0 && left / s.q[i] < -1e-2 * s.residual_norm)
            block.push_back(i), force.push_back(left - g[i]), low.push_back(down), high.push_back(0.0);
          else
            continue;
          in[(std::size_t)i] = 1;
        }
        if (block.size() == before) break;
        if ((Eigen::Index)block.size() > set.dense_block) return false;
      }
      const Eigen::Index k = (Eigen::Index)block.size();
      bool accepted = false;
      double t = 1.0, taken = t;  // the length tried last (the accepted one)
      for (int halving = 0; halving < 20 && !accepted; ++halving, t *= 0.5) {
        taken = t;
        Eigen::VectorXd moved = beta;
        for (Eigen::Index a = 0; a < k; ++a) {
          const Eigen::Index i = block[(std::size_t)a];
          moved[i] = std::clamp(beta[i] + t * d[a], beta[i] + low[(std::size_t)a], beta[i] + high[(std::size_t)a]);
        }
        if ((moved - beta).lpNorm<Eigen::Infinity>() == 0) break;
        StepState trial = evaluate(signed_fractions(s, moved), s.r, s.threshold);
        if (trial.residual_norm <= set.tol || trial.residual_norm <= (1 - 1e-4 * t) * s.residual_norm) {
          s = std::move(trial);
          switch_variants(s);
          accepted = true;
        }
      }
      if (set.trace)
        std::fprintf(set.trace,
                     "step iteration %d: dense newton move (%ld points, linearised law to %.1e, length %g), %s, residual "
                     "%.3e, %d evaluations, %d products\n",
                     stats_.iterations, (long)k, phi_norm, taken, accepted ? "taken" : "no fall",
                     s.residual_norm, stats_.evaluations, stats_.products);
      if (!accepted) return false;
      ++stats_.dense_steps;
    }
    return true;
  }

  // The nested loops' local step as a gradient step: d = f / (D + q) on the free points.
  Eigen::VectorXd gradient_direction(const StepState& s, const Classified& cl) const {
    const Eigen::Index n = s.chi.size();
    Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
    const double rhoa = p_.law.rho * p_.law.a, latent_slope = p_.law.rho * p_.law.latent / p_.law.T0;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!cl.free[(std::size_t)i]) continue;
      const double D = ((s.alpha[i] > 0 ? rhoa : 0.0) * std::fabs(s.trace[i]) + latent_slope) * p_.kappa[i];
      d[i] = cl.force[i] / (D + s.q[i]);
    }
    return d;
  }

  struct Search {
    bool ok = false;
    double ratio = 0;  // W's change over the quadratic model's (try_move)
    StepState state;
  };
  // W's change over its quadratic model's prediction -sum area (f step + step (df/dbeta) step / 2)
  // for a move `step` from s (one product).
  double model_ratio(const StepState& s, const Classified& region, const Eigen::VectorXd& step, double change) {
    const Eigen::VectorXd curvature = force_derivative(s, step, region.upper);
    double model = 0;
    for (Eigen::Index i = 0; i < step.size(); ++i)
      model -= p_.area[i] * (region.force[i] * step[i] + 0.5 * step[i] * curvature[i]);
    return model < 0 ? change / model : (change < 0 ? 1.0 : 0.0);
  }
  // The signed fractions of magnitudes `moved` with the variants of s.
  static Eigen::VectorXd signed_fractions(const StepState& s, const Eigen::VectorXd& moved) {
    Eigen::VectorXd chi(moved.size());
    for (Eigen::Index i = 0; i < moved.size(); ++i) chi[i] = moved[i] > 0 ? s.sign[i] * moved[i] : 0.0;
    return chi;
  }
  // The change of W from s (at beta) to t (at moved), by the trapezoid rule on the forces at
  // both ends, on the side of held each move lies on (psi is linear there); predicted: the
  // first-order change.
  double energy_change(const StepState& s, const Eigen::VectorXd& beta, const StepState& t,
                       const Eigen::VectorXd& moved, double& predicted) const {
    double change = 0;
    predicted = 0;
    for (Eigen::Index i = 0; i < beta.size(); ++i) {
      const double step = moved[i] - beta[i];
      if (step == 0.0) continue;
      const double f0 = side_force(s, i, beta[i], step > 0 ? beta[i] < s.held[i] : beta[i] <= s.held[i]);
      const bool below = moved[i] < s.held[i] || (moved[i] == s.held[i] && step > 0);
      const double f1 = side_force(t, i, moved[i], below);
      change -= 0.5 * p_.area[i] * (f0 + f1) * step;
      predicted -= p_.area[i] * f0 * step;
    }
    return change;
  }
  // One trust-region move d (within the region's intervals): evaluated, its W change against
  // the quadratic model's -sum area (f d + d (df/dbeta) d / 2).
  Search try_move(const StepState& s, const Eigen::VectorXd& beta, const Classified& region,
                  const Eigen::VectorXd& d, double tol, double best, bool newton, bool by_energy) {
    const Eigen::Index n = beta.size();
    Search out;
    Eigen::VectorXd moved = beta;
    for (Eigen::Index i = 0; i < n; ++i)
      if (region.free[(std::size_t)i]) moved[i] = std::clamp(beta[i] + d[i], region.lo[i], region.hi[i]);
    const Eigen::VectorXd step = moved - beta;
    if (step.lpNorm<Eigen::Infinity>() == 0) return out;
    StepState t = evaluate(signed_fractions(s, moved), s.r, s.threshold);
    double predicted = 0;
    const double change = energy_change(s, beta, t, moved, predicted);
    // The ratio (a product: the model's curvature) is read by the energy's acceptance test and
    // the trust region's update only: not formed for a move judged by the residual alone, nor
    // for one that solves the step, which leaves the region as it is (the step ends there,
    // unless a variant switch raises its residual: the next move then starts from that region;
    // in none of the sleeve defaults).
    if (t.residual_norm <= tol) {
      out.ok = true;
      out.ratio = std::numeric_limits<double>::quiet_NaN();  // neither > 0.75 nor < 0.25: no update
      out.state = std::move(t);
      return out;
    }
    if (by_energy) out.ratio = model_ratio(s, region, step, change);
    if ((by_energy && out.ratio >= 0.1 && change < 0) || (newton && t.residual_norm <= 0.5 * best)) {
      out.ok = true;
      out.state = std::move(t);
    }
    return out;
  }
  // Armijo backtracking along the gradient step projected on the intervals; the change of W by
  // the trapezoid rule on the forces at both ends (energy_change).
  Search line_search(const StepState& s, const Eigen::VectorXd& beta, const Classified& cl, const Eigen::VectorXd& d,
                     double tol) {
    const Eigen::Index n = beta.size();
    Search out;
    double lambda = 1.0;
    for (int halving = 0; halving < 40; ++halving, lambda *= 0.5) {
      Eigen::VectorXd moved = beta;
      bool any = false;
      for (Eigen::Index i = 0; i < n; ++i) {
        if (!cl.free[(std::size_t)i]) continue;
        moved[i] = std::clamp(beta[i] + lambda * d[i], cl.lo[i], cl.hi[i]);
        any |= moved[i] != beta[i];
      }
      if (!any) return out;
      StepState t = evaluate(signed_fractions(s, moved), s.r, s.threshold);
      double predicted = 0;
      const double change = energy_change(s, beta, t, moved, predicted);
      if (change <= 1e-4 * predicted || t.residual_norm <= tol) {
        out.ok = true;
        out.state = std::move(t);
        return out;
      }
    }
    return out;
  }

  using RowMajorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
  // Vectors of the products (force_derivative_on), kept over the step: no allocation per product.
  struct Workspace {
    Eigen::VectorXd heat, dT, dalpha, dc, mech, du;
    Eigen::VectorXd heat_z, stiffness_z, load, dr;  // the back-solves' and the contact load's
    Eigen::VectorXd moving_motion, moving_reaction;  // contact_linear's moving rows: -dq and dr
    Eigen::VectorXd caller_motion;  // contact_linear's H S K^-1 dmech on all rows, by the caller's columns
    Eigen::VectorXd rhs, points;                      // evaluate's heat load and T at the points
  };

  // p_.interp by rows (T at a point, row by row): the problem's copy while operators_version
  // names it, else made at its first use in the step.
  const RowMajorMatrix& interp_by_rows() {
    StepProblem::OperatorCache& cache = p_.operator_cache;
    const bool kept = p_.operators_version != 0 && cache.version == p_.operators_version;
    if (!kept && !interp_rows_made_) {
      cache.interp_rows = p_.interp;
      cache.interp_rows.makeCompressed();
      cache.version = p_.operators_version;
      interp_rows_made_ = true;
    }
    return cache.interp_rows;
  }

  const StepProblem& p_;
  StepResult& stats_;
  RecycledSpace recycled_;  // over the step's linearised solves (newton_direction)
  // A solve of a block of StepSettings::coarse_points took coarse_after GMRES iterations this step.
  bool hard_large_solve_ = false;
  Workspace work_;
  // The cone polish's factor, kept over the step's contact solves (psor_cone.hpp ConePolishMemory):
  // made anew at each step, so that a step's bits depend only on its start (a run resumed from a
  // checkpoint is the uninterrupted one, byte for byte).
  ConePolishMemory polish_memory_;
  bool interp_rows_made_ = false;    // interp_by_rows made the problem's copy in this step
  std::vector<Eigen::Index> all_;    // 0 .. n-1 (force_derivative's support)
  std::vector<int> column_of_row_;   // contact row -> column of the Delassus factor's Y (-1: none)
  Eigen::VectorXd cone_mu_;          // mu .* tangent_free: Coulomb's coefficient per node on the cone (0 where held)
};

// Solves the step (see the header); chi, r, threshold in/out; T, u out.
inline StepResult solve_fraction_step(const StepProblem& problem, const StepSettings& settings,
                                      Eigen::VectorXd& chi, Eigen::VectorXd& r, Eigen::VectorXd& threshold,
                                      Eigen::VectorXd& T, Eigen::VectorXd& u) {
  StepResult stats;
  StepSolver solver(problem, stats);
  try {
    solver.solve(settings, chi, r, threshold, T, u);
  } catch (const std::runtime_error& e) {  // a contact loop that did not converge: named, not thrown
    stats.converged = false;
    stats.failure = e.what();
  }
  return stats;
}

}  // namespace sma
