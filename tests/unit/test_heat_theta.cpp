// The heat theta step's right-hand side and energy terms (plugin/core/heat_theta.hpp) against the
// scheme's discrete energy balance: with T1 the solution of the step's system, the stored heat
// 1'M (T1 - T0) equals the boundary heat plus the latent heat (1'Kt = 0), with and without an
// imposed node; and the right-hand side against the formula written out here.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "core/heat_theta.hpp"

namespace {

// A 4-node P1 chain: Kt = k [1 -1; -1 1] per element (rows sum to zero), dense.
struct Chain {
  Eigen::MatrixXd kt = Eigen::MatrixXd::Zero(4, 4);
  Chain() {
    const double k[3] = {2.0, 3.5, 1.25};
    for (int e = 0; e < 3; ++e) {
      kt(e, e) += k[e], kt(e + 1, e + 1) += k[e];
      kt(e, e + 1) -= k[e], kt(e + 1, e) -= k[e];
    }
  }
  void operator()(const double* x, double* y) const {
    Eigen::Map<Eigen::VectorXd>(y, 4) = kt * Eigen::Map<const Eigen::VectorXd>(x, 4);
  }
};

struct Problem {
  std::vector<double> capacity{3.0, 5.0, 4.0, 2.0}, length{0.5, 0.0, 0.0, 0.25}, imposed{0, 0, 0, 0},
      free_mask{1, 1, 1, 1}, ti{0, 0, 0, 0}, g0{10, 0, 0, 40}, g1{20, 0, 0, 30}, text0{290, 0, 0, 310},
      text1{295, 0, 0, 305};
  sma::HeatThetaArrays arrays() const { return {capacity, length, imposed, free_mask, ti, g0, g1, text0, text1}; }
};

const double dt = 0.1, theta = 0.5, tgv = 1e30;
const std::vector<double> t0{300, 301, 303, 299}, s0{0.0, 7.0, -2.0, 0.0}, s1{1.0, 4.0, 0.5, 0.0};

// Solves the step's system (heat.idp's HeatFactorize: M/dt + theta (Kt + G1), masked, tgv rows).
std::vector<double> Step(const Problem& p, const Chain& chain, const std::vector<double>& rhs) {
  Eigen::MatrixXd lhs = theta * chain.kt;
  for (int i = 0; i < 4; ++i)
    lhs(i, i) += (p.capacity[i] / dt + theta * p.g1[i] * p.length[i]) * p.free_mask[i] + tgv * p.imposed[i];
  Eigen::VectorXd t1 = lhs.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(rhs.data(), 4));
  return {t1.data(), t1.data() + 4};
}

double Stored(const Problem& p, const std::vector<double>& t1) {
  double s = 0;
  for (int i = 0; i < 4; ++i) s += p.capacity[i] * (t1[i] - t0[i]);
  return s;
}

TEST(HeatTheta, RhsIsTheSchemesRightSide) {
  Problem p;
  p.imposed = {0, 0, 1, 0}, p.free_mask = {1, 1, 0, 1}, p.ti = {0, 0, 320, 0};
  const Chain chain;
  std::vector<double> rhs(4);
  sma::heat_theta_rhs(p.arrays(), dt, theta, tgv, t0, s0, s1, chain, rhs);
  const Eigen::VectorXd kt0 = chain.kt * Eigen::Map<const Eigen::VectorXd>(t0.data(), 4);
  for (int i = 0; i < 4; ++i) {
    const double G0 = p.g0[i] * p.length[i], G1 = p.g1[i] * p.length[i];
    const double expected = (p.capacity[i] * t0[i] / dt - (1 - theta) * (kt0[i] + G0 * t0[i]) +
                             (1 - theta) * (G0 * p.text0[i] + s0[i]) + theta * (G1 * p.text1[i] + s1[i])) *
                                p.free_mask[i] +
                            tgv * p.ti[i] * p.imposed[i];
    EXPECT_NEAR(rhs[i], expected, 1e-12 * std::abs(expected)) << "node " << i;
  }
}

TEST(HeatTheta, EnergyTermsBalanceTheStoredHeat) {
  for (bool withImposed : {false, true}) {
    Problem p;
    if (withImposed) p.imposed = {0, 0, 1, 0}, p.free_mask = {1, 1, 0, 1}, p.ti = {0, 0, 320, 0};
    const Chain chain;
    std::vector<double> rhs(4);
    sma::heat_theta_rhs(p.arrays(), dt, theta, tgv, t0, s0, s1, chain, rhs);
    const std::vector<double> t1 = Step(p, chain, rhs);
    if (withImposed) {
      EXPECT_NEAR(t1[2], 320, 1e-9);
    }
    const sma::HeatStepEnergy e = sma::heat_theta_energy(p.arrays(), dt, theta, t0, t1, s0, s1, chain);
    EXPECT_NEAR(e.latent, dt * (theta * 5.5 + (1 - theta) * 5.0), 1e-15);
    const double stored = Stored(p, t1);
    // Heat really enters: the test is not 0 = 0 (the imposed node heats its neighbours by 17 K).
    EXPECT_GT(std::abs(stored), 1.0);
    EXPECT_NEAR(stored, e.boundary + e.latent, 1e-10 * std::abs(stored)) << (withImposed ? "imposed" : "free");
  }
}

TEST(HeatTheta, ArraysOfAnotherSizeAreRefused) {
  Problem p;
  p.g1.pop_back();
  std::vector<double> rhs(4);
  EXPECT_THROW(sma::heat_theta_rhs(p.arrays(), dt, theta, tgv, t0, s0, s1, Chain(), rhs), std::invalid_argument);
}

}  // namespace

namespace {
TEST(HeatTheta, SameValuesSeesSizeValueAndNaN) {
  const std::vector<double> a{1.0, 2000.0, 0.0}, b{1.0, 2000.0, -0.0}, c{1.0, 2000.0 + 1e-12, 0.0}, d{1.0, 2000.0};
  const std::vector<double> nan{1.0, std::nan(""), 0.0};
  EXPECT_TRUE(sma::same_values(a, b));  // 0 - (-0) = 0: the script's linfty of the difference is 0 too
  EXPECT_FALSE(sma::same_values(a, c));
  EXPECT_FALSE(sma::same_values(a, d));
  EXPECT_FALSE(sma::same_values(nan, nan));
}
}  // namespace
