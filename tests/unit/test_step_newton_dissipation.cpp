// The step solver with the dissipative law (-dissipation k > 0, plugin/core/step_newton.hpp):
// its law (target()) against the nested loops' local step (phase_fraction.hpp's
// project_fraction) iterated to its heat fixed point on random data, its linearisation with the
// dissipated heat against finite differences, and the radial sleeve's run with k: every
// converged step solves the law with k, the heat with the dissipated heat as a source, and the
// contact.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/phase_fraction.hpp"
#include "core/step_newton.hpp"
#include "radial_sleeve.hpp"

namespace {

using sma_test::RadialSleeve;

// The nested loops' local step at one point iterated as dct.idp does at a fixed temperature:
// b <- |chi| (its heat solve's fraction) until nothing changes; the map's slope is D / (D + q) < 1.
double nested_loops_fixed_point(const sma::ThermalLaw& law, double trace, double alpha, double c, double kappa,
                                double start, double laminate, double k) {
  double chi = start, b = std::fabs(start);
  for (int it = 0; it < 200000; ++it) {
    const double next = sma::project_fraction(law, trace, alpha, c, kappa, b, chi, start, laminate, k);
    const bool same = std::fabs(next - chi) <= 1e-15 && it > 0;
    chi = next;
    b = std::fabs(next);
    if (same) break;
  }
  return chi;
}

TEST(StepNewtonDissipation, TargetIsTheNestedLoopsLocalStepAtItsFixedPoint) {
  const sma::ThermalLaw law{7900, 300, 3000, 210, 280};  // the radial sleeve's
  std::mt19937 gen(28);
  std::uniform_real_distribution<double> unit(0, 1);
  const double laminate = 1.5e11;  // lambda + 2 mu, Pa
  int partial = 0, held_points = 0, moved = 0;
  for (double k : {0.0, 2e5, 1e6}) {
    for (int trial = 0; trial < 4000; ++trial) {
      const double T = 180 + 100 * unit(gen);
      const double alpha = law.alpha(T), c = law.c(T);
      const double q = alpha * alpha / laminate, scale = std::fabs(c) + 2 * k + q + 1;
      const double trace = (unit(gen) - 0.3) * 2 * scale / std::max(alpha, 1.0);
      const double start = unit(gen) < 0.3 ? 0.0 : 2 * unit(gen) - 1;
      // kappa small enough that D << q sometimes, large enough that D >> q sometimes.
      const double kappa = std::pow(10.0, -3 + 5 * unit(gen));
      const double nested = nested_loops_fixed_point(law, trace, alpha, c, kappa, start, laminate, k);
      sma::StepState s;
      s.q = Eigen::VectorXd::Constant(1, q);
      s.drive = Eigen::VectorXd::Constant(1, alpha * std::fabs(trace) - c);
      const double sign = trace > 0 ? 1.0 : trace < 0 ? -1.0 : (start < 0 ? -1.0 : 1.0);
      s.held = Eigen::VectorXd::Constant(1, std::max(start * sign, 0.0));
      const double target = sma::StepSolver::target(s, 0, k);
      EXPECT_NEAR(nested, sign * target, 1e-9) << "k " << k << " T " << T << " trace " << trace << " start " << start
                                               << " kappa " << kappa;
      partial += target > 0 && target < 1;
      held_points += target == s.held[0] && target > 0;
      moved += target != s.held[0];
      if (k == 0.0) {
        EXPECT_EQ(target, sma::StepSolver::target(s, 0)) << "k = 0: the paper's law, the same arithmetic";
      }
    }
  }
  // The random data cover every branch: partly transformed, held, moved.
  EXPECT_GT(partial, 500);
  EXPECT_GT(held_points, 300);
  EXPECT_GT(moved, 500);
}

TEST(StepNewtonDissipation, HeldBandWidensByKOverQ) {
  // One point on the band's edges: the fraction held at 0.4 until the drive passes q 0.4 + k,
  // then lower = (drive - k) / q.
  sma::StepState s;
  const double q = 2e6, k = 5e5;
  s.q = Eigen::VectorXd::Constant(1, q);
  s.held = Eigen::VectorXd::Constant(1, 0.4);
  s.drive = Eigen::VectorXd::Constant(1, 0.4 * q + 0.99 * k);
  EXPECT_EQ(sma::StepSolver::target(s, 0, k), 0.4);
  s.drive[0] = 0.4 * q + k + 0.1 * q;
  EXPECT_NEAR(sma::StepSolver::target(s, 0, k), 0.5, 1e-15);
  s.drive[0] = (0.4 - 1) * q - 0.99 * k;  // the reverting edge
  EXPECT_EQ(sma::StepSolver::target(s, 0, k), 0.4);
  s.drive[0] = (0.4 - 1) * q - k - 0.1 * q;
  EXPECT_NEAR(sma::StepSolver::target(s, 0, k), 0.3, 1e-15);
}

struct SleeveRun {
  int steps = 0, transforming = 0, iterations_max = 0, iterations_sum = 0;
  double dissipated = 0;  // sum over steps of k |chi - chi_start| area (J/m^3 per radian x m^2)
  bool converged = true;
};

// The radial sleeve's time loop with dissipation k; checks every converged step's equations.
SleeveRun run_with_dissipation(RadialSleeve& rs, double k, double tol, bool check_fd) {
  const int n = rs.nr + 1;
  Eigen::VectorXd T = Eigen::VectorXd::Constant(n, rs.Tinit), chi = Eigen::VectorXd::Zero(rs.nr);
  Eigen::VectorXd b_start = Eigen::VectorXd::Zero(rs.nr), r = Eigen::VectorXd::Zero(2), g = Eigen::VectorXd::Zero(1);
  Eigen::VectorXd u(n);
  double theta_factored = -1;
  bool fd_done = false;
  SleeveRun out;
  sma::StepSettings set;
  set.tol = tol;
  for (int step = 0; step < rs.steps; ++step) {
    const double theta = step < 2 ? 1.0 : 0.5;
    if (theta != theta_factored) rs.factor_heat(theta), theta_factored = theta;
    sma::StepProblem p = rs.problem(T, chi, b_start, theta);
    p.dissipation = k;
    p.dissipation_scale = k / rs.dt;
    const Eigen::VectorXd chi_start = chi;
    Eigen::VectorXd T1(n);
    const sma::StepResult res = sma::solve_fraction_step(p, set, chi, r, g, T1, u);
    ++out.steps;
    if (!res.converged) {
      out.converged = false;
      ADD_FAILURE() << "step " << step << " did not converge: " << res.failure;
      break;
    }
    if (res.iterations > 0) {
      ++out.transforming;
      out.iterations_sum += res.iterations;
      out.iterations_max = std::max(out.iterations_max, res.iterations);
    }
    // Heat with the dissipated heat: (M/dt + theta (Kt + G)) T = rhs + Q (rho L / dt (|chi| - b_start)
    // + k / dt |chi - chi_start|).
    const Eigen::VectorXd rhs = p.heat_rhs + p.latent_scale * (p.latent * (chi.cwiseAbs() - p.b_start)) +
                                (k / rs.dt) * (p.latent * (chi - chi_start).cwiseAbs());
    EXPECT_LE((rs.heat_lhs * T1 - rhs).lpNorm<Eigen::Infinity>(), 1e-9 * rhs.lpNorm<Eigen::Infinity>()) << "step " << step;
    // Contact: Signorini at the inner node.
    EXPECT_GE(r[0], 0.0);
    EXPECT_GE(u[0] + p.gap[0], -1e-12 * std::fabs(p.gap[0]));
    // The law with k, recomputed here: |chi| = clamp(clamp(held, (d - k)/q, (d + k)/q + 1), 0, 1).
    const Eigen::VectorXd Tq = rs.interp * T1, trace = (rs.B.transpose() * u).cwiseQuotient(rs.area);
    for (int e = 0; e < rs.nr; ++e) {
      const double alpha = p.law.alpha(Tq[e]), c = p.law.c(Tq[e]);
      const double q = alpha * alpha / p.laminate, drive = alpha * std::fabs(trace[e]) - c;
      const double sign = trace[e] > 0 ? 1.0 : trace[e] < 0 ? -1.0 : (chi[e] < 0 ? -1.0 : 1.0);
      const double held = std::max(chi_start[e] * sign, 0.0);
      const double target = q > 0 ? std::clamp(std::clamp(held, (drive - k) / q, (drive + k) / q + 1), 0.0, 1.0)
                                  : (drive > k ? 1.0 : drive < -k ? 0.0 : held);
      EXPECT_LE(std::fabs(chi[e] - sign * target), tol) << "step " << step << " point " << e;
    }
    out.dissipated += k * rs.area.dot((chi - chi_start).cwiseAbs());
    // The linearisation with the dissipated heat against finite differences, at the first state
    // with two points strictly inside their intervals.
    if (check_fd && !fd_done) {
      sma::StepResult stats;
      sma::StepSolver solver(p, stats);
      const Eigen::VectorXd r0 = Eigen::VectorXd::Zero(2), g0 = Eigen::VectorXd::Zero(1);
      const sma::StepState s = solver.evaluate(chi, r0, g0);
      const Eigen::VectorXd beta = chi.cwiseAbs();
      Eigen::VectorXd w = Eigen::VectorXd::Zero(rs.nr);
      std::vector<char> upper((std::size_t)rs.nr, 0);
      int inside = 0;
      for (int e = 0; e < rs.nr; ++e) {
        if (!(beta[e] > 1e-3 && beta[e] < 1 - 1e-3 && std::fabs(beta[e] - s.held[e]) > 1e-3)) continue;
        w[e] = (e % 2 ? 1.0 : -0.7);
        upper[(std::size_t)e] = beta[e] < s.held[e];
        ++inside;
      }
      if (inside >= 2 && s.r[0] > 0) {
        fd_done = true;
        const Eigen::VectorXd analytic = solver.force_derivative(s, w, upper);
        const double h = 1e-7;
        auto forces = [&](double t) {
          const Eigen::VectorXd moved = beta + t * w;
          Eigen::VectorXd trial(rs.nr);
          for (int e = 0; e < rs.nr; ++e) trial[e] = s.sign[e] * moved[e];
          const sma::StepState st = solver.evaluate(trial, r0, g0);
          Eigen::VectorXd f = st.drive - st.q.cwiseProduct(moved);
          for (int e = 0; e < rs.nr; ++e) f[e] += upper[(std::size_t)e] ? st.q[e] : 0.0;  // the reverting side's + q
          return f;
        };
        const Eigen::VectorXd fd = (forces(h) - forces(-h)) / (2 * h);
        EXPECT_LE((analytic - fd).lpNorm<Eigen::Infinity>(), 1e-5 * fd.lpNorm<Eigen::Infinity>())
            << "force_derivative with the dissipated heat, step " << step;
        // Without the dissipated heat's term the linearisation is off by about k / (rho L).
        sma::StepProblem plain = p;
        plain.dissipation_scale = 0;
        plain.dissipation = 1e-300;  // the heat source's derivative off, the law the same to round-off
        sma::StepResult stats2;
        sma::StepSolver other(plain, stats2);
        const Eigen::VectorXd without = other.force_derivative(s, w, upper);
        EXPECT_GT((without - fd).lpNorm<Eigen::Infinity>(), 1e-3 * fd.lpNorm<Eigen::Infinity>());
      }
    }
    T = T1;
    b_start = chi.cwiseAbs();
  }
  EXPECT_TRUE(!check_fd || fd_done) << "no state with two partly transformed points in contact";
  return out;
}

TEST(StepNewtonDissipation, RadialSleeveStepsSolveTheLawWithKAndTheHeatWithItsSource) {
  RadialSleeve rs;
  rs.build();
  const double k = 1e6;  // Pa: 4 % of rho L
  const SleeveRun result = run_with_dissipation(rs, k, 1e-8, true);
  ASSERT_TRUE(result.converged);
  ASSERT_GT(result.transforming, 10);
  EXPECT_LE(result.iterations_max, 15);
  EXPECT_GT(result.dissipated, 0.0);
  std::printf("radial sleeve, k = %g Pa: %d transforming steps, iterations max %d, mean %.2f\n", k, result.transforming,
              result.iterations_max, double(result.iterations_sum) / result.transforming);
}

}  // namespace
