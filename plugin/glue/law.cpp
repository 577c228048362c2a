// FreeFEM glue of the material law, the obstacle, the condensed PSOR and the contact records
// (plugin/core: phase_projection, phase_fraction, material, obstacle, psor, contact_history,
// heat_balance, step_record). The functions are listed in load.cpp.
#include "glue/glue.hpp"
#include "glue/dense.hpp"

#include "core/contact_history.hpp"
#include "core/heat_balance.hpp"
#include "core/material.hpp"
#include "core/obstacle.hpp"
#include "core/phase_fraction.hpp"
#include "core/phase_projection.hpp"
#include "core/psor.hpp"
#include "core/step_record.hpp"

namespace sma_glue {
namespace {

long PhaseProject(KN<double>* const& trace, KN<double>* const& alpha, KN<double>* const& c,
                  KN<double>* const& s, KN<double>* const& phase) {
  return guarded("PhaseProject", [&] {
    return (long)sma::project_phases(cview(trace), cview(alpha), cview(c), view(s), view(phase));
  });
}

sma::ThermalLaw thermal_law(KN<double>* law) {
  if (law->N() != 5)
    throw std::invalid_argument("law must be [rho, a, L, T0, Tc], got " + std::to_string(law->N()) +
                                " values");
  return sma::ThermalLaw{(*law)[0], (*law)[1], (*law)[2], (*law)[3], (*law)[4]};
}

long PhaseFractionProject(KN<double>* const& trace, KN<double>* const& alpha, KN<double>* const& c,
                          KN<double>* const& law, KN<double>* const& local, KN<double>* const& s,
                          KN<double>* const& chi) {
  return guarded("PhaseFractionProject", [&] {
    if (law->N() != 6 && law->N() != 7)
      throw std::invalid_argument("law must be [rho, a, L, T0, Tc, laminate modulus] or those and "
                                  "the dissipation k, got " + std::to_string(law->N()) + " values");
    const long n = trace->N();
    if (local->N() != 3 * n)
      throw std::invalid_argument("local data must hold kappa, b and chi at the step's start: " +
                                  std::to_string(3 * n) + " values, got " + std::to_string(local->N()));
    KN<double> thermal((*law)(SubArray(5)));
    const double* data = n ? &(*local)[0] : nullptr;
    const sma::span<const double> kappa{data, (std::size_t)n}, b{data + n, (std::size_t)n},
        start{data + 2 * n, (std::size_t)n};
    return (long)sma::project_fractions(thermal_law(&thermal), cview(trace), cview(alpha), cview(c),
                                        kappa, b, start, (*law)[5], view(s), view(chi),
                                        law->N() == 7 ? (*law)[6] : 0.0);
  });
}

// The dissipative law's local part of L_II: sum weight (g**(chi) - s t), chi = s / alpha, with
// the dissipation k = law[6] and chi at the step's start in local[2n, 3n) (PhaseFractionProject's).
double AuchmutyLocalDissipative(KN<double>* const& trace, KN<double>* const& alpha,
                                KN<double>* const& c, KN<double>* const& s, KN<double>* const& weight,
                                KN<double>* const& law, KN<double>* const& local) {
  return guarded("AuchmutyLocalDissipative", [&] {
    const long n = trace->N();
    if (law->N() != 7) throw std::invalid_argument("law must hold 7 values, the 7th the dissipation k");
    if (alpha->N() != n || c->N() != n || s->N() != n || weight->N() != n || local->N() != 3 * n)
      throw std::invalid_argument("arrays of different lengths");
    const double k = (*law)[6];
    if (!(k >= 0.0 && std::isfinite(k))) throw std::domain_error("dissipation k < 0 or not finite");
    double sum = 0.0;
    for (long i = 0; i < n; ++i)
      sum += (*weight)[i] * sma::dissipative_local_energy((*trace)[i], (*alpha)[i], (*c)[i], k, (*s)[i],
                                                           (*local)[2 * n + i]);
    return sum;
  });
}

long FractionReversals(KN<double>* const& chiStart, KN<double>* const& chi,
                       KN<double>* const& reverted, const double& tol) {
  return guarded("FractionReversals", [&] {
    return (long)sma::count_reversals(cview(chiStart), cview(chi), view(reverted), tol);
  });
}

long FractionSnapUnstable(KN<double>* const& before2, KN<double>* const& before,
                          KN<double>* const& start, KN<double>* const& alpha,
                          KN<double>* const& snapped, KN<double>* const& chi, KN<double>* const& s) {
  return guarded("FractionSnapUnstable", [&] {
    return (long)sma::snap_unstable_fractions(cview(before2), cview(before), cview(start), cview(alpha),
                                              view(snapped), view(chi), view(s));
  });
}

double AuchmutyLocal(KN<double>* const& trace, KN<double>* const& alpha, KN<double>* const& c,
                     KN<double>* const& s, KN<double>* const& weight) {
  return guarded("AuchmutyLocal", [&] {
    return sma::auchmuty_local_part(cview(trace), cview(alpha), cview(c), cview(s), cview(weight));
  });
}

// alpha(T), c(T) per point; the law's constants are checked (T0 <= Tc, ...).
long PhaseCoefficients(KN<double>* const& T, KN<double>* const& law, KN<double>* const& alpha,
                       KN<double>* const& c) {
  return guarded("PhaseCoefficients", [&] {
    sma::phase_coefficients(thermal_law(law), cview(T), view(alpha), view(c));
    return (long)T->N();
  });
}

// Gap and normal of points against a circular (A == B) or elliptic pipe.
long ObstacleGap(KN<double>* const& x, KN<double>* const& y, KN<double>* const& pipe,
                 KN<double>* const& gap, KN<double>* const& nx, KN<double>* const& ny) {
  return guarded("ObstacleGap", [&] {
    const long n = x->N();
    if (y->N() != n || gap->N() != n || nx->N() != n || ny->N() != n)
      throw std::invalid_argument("x, y, gap, nx, ny must have the same length");
    if (pipe->N() != 4) throw std::invalid_argument("pipe must be [cx, cy, A, B]");
    const double cx = (*pipe)[0], cy = (*pipe)[1], A = (*pipe)[2], B = (*pipe)[3];
    for (long i = 0; i < n; ++i) {
      const sma::ContactGeometry g = A == B ? sma::circle_gap((*x)[i], (*y)[i], cx, cy, A)
                                            : sma::ellipse_gap((*x)[i], (*y)[i], cx, cy, A, B);
      (*gap)[i] = g.gap;
      (*nx)[i] = g.nx;
      (*ny)[i] = g.ny;
    }
    return n;
  });
}

// Condensed projected SOR; settings = [omega, tol, maxit]; info receives [residual, converged].
long PsorCondensed(KNM<double>* const& W, KN<double>* const& q, KN<double>* const& g,
                   KN<double>* const& settings, KN<double>* const& r, KN<double>* const& info) {
  return guarded("PsorCondensed", [&] {
    const long n = q->N();
    if (W->N() != n || W->M() != n) throw std::invalid_argument("W must be square of the size of q");
    if (settings->N() != 3 && settings->N() != 4)
      throw std::invalid_argument("settings must be [omega, tol, maxit] or [omega, tol, maxit, polish]");
    if (info->N() != 2) throw std::invalid_argument("info must have 2 entries");
    const int polish = settings->N() == 4 ? (int)(*settings)[3] : 0;
    const Eigen::MatrixXd w = DenseOf(W);
    Eigen::Map<const Eigen::VectorXd> qv(&(*q)[0], n), gv(&(*g)[0], g->N());
    Eigen::VectorXd rv = Eigen::Map<const Eigen::VectorXd>(&(*r)[0], n);
    const sma::PsorResult res = sma::psor_condensed(w, qv, gv, (*settings)[0], (*settings)[1],
                                                    (int)(*settings)[2], rv, polish);
    for (long i = 0; i < n; ++i) (*r)[i] = rv[i];
    (*info)[0] = res.residual;
    (*info)[1] = res.converged ? 1 : 0;
    return (long)res.iterations;
  });
}

double HeatBalanceResidual(KN<double>* const& capacity, KN<double>* const& T1, KN<double>* const& T0,
                           double const& entered, double const& released, double const& dissipated) {
  return guarded("HeatBalanceResidual", [&] {
    const sma::span<const double> c = cview(capacity), t1 = cview(T1), t0 = cview(T0);
    if (t1.size() != c.size() || t0.size() != c.size())
      throw std::invalid_argument("capacity, T1 and T0 need one value per heat node");
    const double stored = sma::heat_balance::stored(c.begin(), t1.begin(), t0.begin(), c.size());
    return sma::heat_balance::relative_residual(stored, entered, released, dissipated);
  });
}

// The 1998 code's single-precision mesh coordinates (paper Fig. 15-16).
long RoundToFloat(KN<double>* const& x) {
  long changed = 0;
  for (long i = 0; i < x->N(); ++i) {
    const double rounded = static_cast<double>(static_cast<float>((*x)[i]));
    changed += rounded != (*x)[i];
    (*x)[i] = rounded;
  }
  return changed;
}

// Per-step records of the contact nodes (plugin/core/contact_history.hpp).
long ContactTouching(KN<double>* const& reactions) {
  return sma::contact_history::touching(reactions->N() ? &(*reactions)[0] : nullptr, reactions->N() / 2);
}
long ContactRecordPeaks(KN<double>* const& pressure, KN<double>* const& peak, KN<long>* const& peakStep,
                        long const& step) {
  return guarded("ContactRecordPeaks", [&] {
    const long n = pressure->N();
    if (peak->N() != n || peakStep->N() != n) throw std::invalid_argument("pressure, peak and peakStep differ in size");
    if (n > 0) sma::contact_history::record_peaks(&(*pressure)[0], n, step, &(*peak)[0], &(*peakStep)[0]);
    return 0L;
  });
}
long ContactRecordSlip(KN<double>* const& slip, KN<double>* const& reactions, double const& noise,
                       KN<long>* const& lastSlipStep, long const& step) {
  return guarded("ContactRecordSlip", [&] {
    const long n = slip->N();
    if (reactions->N() != 2 * n || lastSlipStep->N() != n)
      throw std::invalid_argument("slip, reactions (2 per node) and lastSlipStep differ in size");
    if (n > 0) sma::contact_history::record_slip(&(*slip)[0], &(*reactions)[0], n, noise, step, &(*lastSlipStep)[0]);
    return 0L;
  });
}

long AreaFractions(KN<double>* const& chi, KN<double>* const& area, KN<double>* const& fractions) {
  return guarded("AreaFractions", [&] {
    double f[3];
    sma::area_fractions(cview(chi), cview(area), f);
    if (fractions->N() != 3) fractions->resize(3);
    for (int k = 0; k < 3; ++k) (*fractions)[k] = f[k];
    return 3L;
  });
}

long PhaseLabels(KN<double>* const& chi, KN<double>* const& labels) {
  return guarded("PhaseLabels", [&] {
    if (labels->N() != chi->N()) labels->resize(chi->N());
    sma::phase_labels(cview(chi), view(labels));
    return (long)chi->N();
  });
}

long StepDataSet(KN<double>* const& data, KN<double>* const& chi, KN<double>* const& b, KN<double>* const& heatRhs,
                 KN<double>* const& heatMask, KN<double>* const& force) {
  return guarded("StepDataSet", [&] {
    sma::set_step_data(view(data), cview(chi), cview(b), cview(heatRhs), cview(heatMask), cview(force));
    return (long)chi->N();
  });
}

long ContactHeatExchange(KNM<double>* const& table, KN<double>* const& r, long const& m, double const& gContact,
                         double const& gPipe, double const& Tpipe, KN<double>* const& g, KN<double>* const& Text) {
  return guarded("ContactHeatExchange", [&] {
    if (m < 0 || (m > 0 && (table->N() < m || table->M() < 1 || r->N() < 2 * m)))
      throw std::invalid_argument("the contact table and reactions must cover " + std::to_string(m) + " nodes");
    if (Text->N() != g->N()) throw std::invalid_argument("g and Text must have one value per heat node");
    if (m == 0) return 0L;
    std::vector<long> node(m);
    for (long i = 0; i < m; ++i) {
      node[i] = std::lrint((*table)(i, 0L));
      if (node[i] < 0 || node[i] >= g->N())
        throw std::invalid_argument("contact node " + std::to_string(i) + " is heat node " + std::to_string(node[i]) +
                                    ", outside 0.." + std::to_string(g->N() - 1));
    }
    return sma::contact_history::heat_exchange(node.data(), &(*r)[0], (std::size_t)m, gContact, gPipe, Tpipe,
                                               &(*g)[0], &(*Text)[0]);
  });
}

}  // namespace

void AddLawFunctions() {
  typedef KN<double>* A;
  typedef string* S;
  Global.Add("PhaseProject", "(", new OneOperator5_<long, A, A, A, A, A>(PhaseProject));
  Global.Add("PhaseFractionProject", "(",
             new OneOperator7_<long, A, A, A, A, A, A, A>(PhaseFractionProject));
  Global.Add("FractionReversals", "(", new OneOperator4_<long, A, A, A, double>(FractionReversals));
  Global.Add("FractionSnapUnstable", "(",
             new OneOperator7_<long, A, A, A, A, A, A, A>(FractionSnapUnstable));
  Global.Add("PhaseCoefficients", "(", new OneOperator4_<long, A, A, A, A>(PhaseCoefficients));
  Global.Add("ObstacleGap", "(", new OneOperator6_<long, A, A, A, A, A, A>(ObstacleGap));
  Global.Add("PsorCondensed", "(",
             new OneOperator6_<long, KNM<double>*, A, A, A, A, A>(PsorCondensed));
  Global.Add("HeatBalanceResidual", "(",
             new OneOperator6_<double, A, A, A, double, double, double>(HeatBalanceResidual));
  Global.Add("AuchmutyLocal", "(", new OneOperator5_<double, A, A, A, A, A>(AuchmutyLocal));
  Global.Add("AuchmutyLocalDissipative", "(",
             new OneOperator7_<double, A, A, A, A, A, A, A>(AuchmutyLocalDissipative));
  Global.Add("RoundToFloat", "(", new OneOperator1_<long, A>(RoundToFloat));
  Global.Add("ContactTouching", "(", new OneOperator1_<long, A>(ContactTouching));
  Global.Add("ContactRecordPeaks", "(", new OneOperator4_<long, A, A, KN<long>*, long>(ContactRecordPeaks));
  Global.Add("ContactRecordSlip", "(", new OneOperator5_<long, A, A, double, KN<long>*, long>(ContactRecordSlip));
  Global.Add("AreaFractions", "(", new OneOperator3_<long, A, A, A>(AreaFractions));
  Global.Add("PhaseLabels", "(", new OneOperator2_<long, A, A>(PhaseLabels));
  Global.Add("StepDataSet", "(", new OneOperator6_<long, A, A, A, A, A, A>(StepDataSet));
  Global.Add("ContactHeatExchange", "(",
             new OneOperator8_<long, KNM<double>*, A, long, double, double, double, A, A>(ContactHeatExchange));
}

}  // namespace sma_glue
