// The radial sleeve (edp/problems/sleeve/radial.idp, tools/bench/oracles/radial_numpy.py) built in C++ for the
// step solver's unit tests: P1 elements in r, one phase point per element, lumped heat capacity,
// Robin exchange on both surfaces, one contact unknown (the inner node against the pipe).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cmath>
#include <vector>

#include "core/material.hpp"
#include "core/sparse_spd.hpp"
#include "core/step_newton.hpp"

namespace sma_test {

struct RadialSleeve {
  // Data (SI; the scenes' defaults).
  int nr = 40, steps = 400;
  double tend = 60.0, E = 85e9, nu = 0.3, rho = 7900, a = 300, latent = 3000, T0 = 210, Tc = 280;
  double C0 = 837, k = 18, g = 500, Text = 293.15, Tinit = 196, Ri = 0.050445, Hr = 0.01, pipe = 0.0505;
  double laminate_scale = 1.0;  // > 1: a laminate band softer than the elastic accommodation

  // Operators.
  std::vector<double> r;
  sma::SparseMatrix K, B, latent_load, interp, heat_lhs;
  Eigen::VectorXd area, capacity, conduction_diag, kappa, exchange;
  Eigen::VectorXd ke;  // conduction per element
  sma::SpdFactor stiffness, heat;
  sma::DelassusFactor contact;
  double shear = 0, lambda = 0, dt = 0;

  void build() {
    dt = tend / steps;
    shear = E / (2 * (1 + nu));
    lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const int n = nr + 1;
    r.resize(n);
    for (int i = 0; i < n; ++i) r[i] = Ri + Hr * i / nr;
    const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0., 0.5384693101056831, 0.9061798459386640};
    const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                          0.2369268850561891};
    std::vector<Eigen::Triplet<double>> kt, bt, qt, it, ct;
    area.resize(nr);
    capacity = Eigen::VectorXd::Zero(n);
    ke.resize(nr);
    for (int e = 0; e < nr; ++e) {
      const double a0 = r[e], b0 = r[e + 1], h = b0 - a0;
      double kaa = 0, kab = 0, kbb = 0;
      for (int q = 0; q < 5; ++q) {
        const double rq = (a0 + b0) / 2 + gx[q] * h / 2, w = gw[q] * h / 2;
        const double Na = (b0 - rq) / h, Nb = (rq - a0) / h, dNa = -1. / h, dNb = 1. / h;
        const double ta = dNa + Na / rq, tb = dNb + Nb / rq;
        kaa += w * rq * (lambda * ta * ta + 2 * shear * (dNa * dNa + Na * Na / (rq * rq)));
        kab += w * rq * (lambda * ta * tb + 2 * shear * (dNa * dNb + Na * Nb / (rq * rq)));
        kbb += w * rq * (lambda * tb * tb + 2 * shear * (dNb * dNb + Nb * Nb / (rq * rq)));
      }
      kt.emplace_back(e, e, kaa);
      kt.emplace_back(e, e + 1, kab);
      kt.emplace_back(e + 1, e, kab);
      kt.emplace_back(e + 1, e + 1, kbb);
      bt.emplace_back(e, e, -a0);
      bt.emplace_back(e + 1, e, b0);
      area[e] = (b0 * b0 - a0 * a0) / 2;
      const double w0 = h * (2 * a0 + b0) / 6, w1 = h * (a0 + 2 * b0) / 6;
      qt.emplace_back(e, e, w0);
      qt.emplace_back(e + 1, e, w1);
      it.emplace_back(e, e, 0.5);
      it.emplace_back(e, e + 1, 0.5);
      capacity[e] += rho * C0 * w0;
      capacity[e + 1] += rho * C0 * w1;
      ke[e] = k * (a0 + b0) / 2 / h;
    }
    K.resize(n, n);
    K.setFromTriplets(kt.begin(), kt.end());
    B.resize(n, nr);
    B.setFromTriplets(bt.begin(), bt.end());
    latent_load.resize(n, nr);
    latent_load.setFromTriplets(qt.begin(), qt.end());
    interp.resize(nr, n);
    interp.setFromTriplets(it.begin(), it.end());
    exchange = Eigen::VectorXd::Zero(n);
    exchange[0] = r[0] * g;
    exchange[n - 1] = r[n - 1] * g;
    // kappa = rho L Interp(Q 1 ./ capacity)
    const Eigen::VectorXd nodal = (latent_load * Eigen::VectorXd::Ones(nr)).cwiseQuotient(capacity);
    kappa = rho * latent * (interp * nodal);
    stiffness.factorize(K);
    sma::SparseMatrix H(2, n);
    H.insert(0, 0) = 1.0;
    std::vector<double> free(n, 1.0);
    contact = sma::delassus_factor(stiffness, H, free, true);
  }

  // Conduction times T.
  Eigen::VectorXd conduct(const Eigen::VectorXd& T) const {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(T.size());
    for (int e = 0; e < nr; ++e) {
      const double flux = ke[e] * (T[e] - T[e + 1]);
      out[e] += flux;
      out[e + 1] -= flux;
    }
    return out;
  }

  // (M/dt + theta (Kt + G)) factorised for theta.
  void factor_heat(double theta) {
    std::vector<Eigen::Triplet<double>> t;
    const int n = nr + 1;
    for (int i = 0; i < n; ++i) t.emplace_back(i, i, capacity[i] / dt + theta * exchange[i]);
    for (int e = 0; e < nr; ++e) {
      t.emplace_back(e, e, theta * ke[e]);
      t.emplace_back(e + 1, e + 1, theta * ke[e]);
      t.emplace_back(e, e + 1, -theta * ke[e]);
      t.emplace_back(e + 1, e, -theta * ke[e]);
    }
    heat_lhs.resize(n, n);
    heat_lhs.setFromTriplets(t.begin(), t.end());
    heat.factorize(heat_lhs);
  }

  // The heat right side without the latent load (constant exchange and outside temperature).
  Eigen::VectorXd heat_rhs(const Eigen::VectorXd& T, double theta) const {
    const Eigen::VectorXd Text_node = Eigen::VectorXd::Constant(T.size(), Text);
    return capacity.cwiseProduct(T) / dt - (1 - theta) * (conduct(T) + exchange.cwiseProduct(T)) +
           exchange.cwiseProduct(Text_node);
  }

  // The step problem at the state (T, chi at the step's start, b_start).
  sma::StepProblem problem(const Eigen::VectorXd& T, const Eigen::VectorXd& chi_start, const Eigen::VectorXd& b_start,
                           double theta) const {
    sma::StepProblem p;
    p.heat = &heat;
    p.heat_rhs = heat_rhs(T, theta);
    p.heat_mask = Eigen::VectorXd::Ones(nr + 1);
    p.latent = latent_load;
    p.latent_scale = rho * latent / dt;
    p.interp = interp;
    p.stiffness = &stiffness;
    p.contact = &contact;
    p.load = B;
    p.area = area;
    p.force = Eigen::VectorXd::Zero(nr + 1);
    p.free = Eigen::VectorXd::Ones(nr + 1);
    p.gap = Eigen::VectorXd::Constant(1, r[0] - pipe);
    p.slip_reference = Eigen::VectorXd::Zero(1);
    p.tangent_free = Eigen::VectorXd::Zero(1);
    p.mu = Eigen::VectorXd::Zero(1);
    p.psor.omega = 1.0;
    p.psor.tol = 1e-12;
    p.psor.maxit = 3;
    p.psor.polish = 0;
    p.law = sma::ThermalLaw{rho, a, latent, T0, Tc};
    p.laminate = (lambda + 2 * shear) * laminate_scale;
    p.kappa = kappa;
    p.chi_start = chi_start;
    p.b_start = b_start;
    return p;
  }
};

}  // namespace sma_test
