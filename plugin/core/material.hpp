// Frémond's law coefficients as stresses (Pa) from the temperature (paper [4],
// docs/model.md#temperature-dependence):
//   alpha(T) = rho a (Tc - T) for T <= Tc, 0 above   (the paper's -a(T - T0) is a misprint)
//   c(T)     = rho L / T0 (T - T0)
// rho turns the paper's per-mass energies (J/kg) into J/m^3 = Pa.
#pragma once

#include <stdexcept>
#include <string>

#include "span.hpp"

namespace sma {

struct ThermalLaw {
  double rho;     // kg/m^3
  double a;       // J/(K kg)
  double latent;  // J/kg
  double T0;      // K
  double Tc;      // K

  void validate() const {
    if (!(rho > 0)) throw std::invalid_argument("material: rho = " + std::to_string(rho) + " must be > 0");
    if (!(a >= 0)) throw std::invalid_argument("material: a = " + std::to_string(a) + " must be >= 0");
    if (!(latent >= 0))
      throw std::invalid_argument("material: latent heat L = " + std::to_string(latent) + " must be >= 0");
    if (!(T0 > 0)) throw std::invalid_argument("material: T0 = " + std::to_string(T0) + " K must be > 0");
    if (!(T0 <= Tc))
      throw std::invalid_argument("material: T0 = " + std::to_string(T0) + " K > Tc = " +
                                  std::to_string(Tc) + " K; the law needs T0 <= Tc");
  }
  double alpha(double T) const { return T <= Tc ? rho * a * (Tc - T) : 0.0; }
  double c(double T) const { return rho * latent / T0 * (T - T0); }
};

// alpha and c at every point from its temperature.
inline void phase_coefficients(const ThermalLaw& law, span<const double> T, span<double> alpha,
                               span<double> c) {
  law.validate();
  if (alpha.size() != T.size() || c.size() != T.size())
    throw std::invalid_argument("phase_coefficients: arrays of different lengths");
  for (std::size_t i = 0; i < T.size(); ++i) {
    alpha[i] = law.alpha(T[i]);
    c[i] = law.c(T[i]);
  }
}

}  // namespace sma
