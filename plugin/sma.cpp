// FreeFEM glue of the SMA plugin: converts FreeFEM arrays to spans and calls the core.
// Everything numerical lives in plugin/core (tested without FreeFEM).
//
// Functions added to the FreeFEM language:
//   long PhaseProject(real[] trace, real[] alpha, real[] c, real[] s, real[] phase)
//       local DC step at every quadrature point; phase is in/out (previous -> new);
//       returns the number of points whose phase changed.
//   long PhaseFractionProject(real[] trace, real[] alpha, real[] c, real[] law, real[] local,
//                             real[] s, real[] chi)
//       local step with signed martensite fractions chi in [-1, 1] (in/out), s = alpha chi
//       (plugin/core/phase_fraction.hpp); law = [rho, a, L, T0, Tc, M], M = lambda + 2 mu for the
//       laminate (0: none); local = [kappa; b; chi at the step's start], n values each (kappa: K
//       per unit fraction, b: the fraction the heat solve saw); kappa = M = 0 is the on/off step.
//       Returns the number of points whose fraction changed.
//   long FractionReversals(real[] chiStart, real[] chi, real[] reverted, real tol)
//       points whose martensite fraction grew by > tol over a step after having lost fraction
//       earlier (reverted: 0/1 per point, in/out; plugin/core/phase_fraction.hpp).
//   long FractionSnapUnstable(real[] chiBefore2, real[] chiBefore, real[] chiStart, real[] alpha,
//                             real[] snapped, real[] chi, real[] s)
//       the DC loop's move of points whose fraction runs away (increments that do not shrink)
//       to the end of their interval (plugin/core/phase_fraction.hpp); returns how many moved.
//   real AuchmutyLocal(real[] trace, real[] alpha, real[] c, real[] s, real[] weight)
//   real AuchmutyLocalDissipative(real[] trace, alpha, c, s, weight, law (7 values), local)
//       sum_i w_i (phi2*(s_i) - trace_i s_i), the sigma2 part of L_II [45].
//   long PhaseCoefficients(real[] T, real[] law = [rho, a, L, T0, Tc], real[] alpha, real[] c)
//       alpha(T) and c(T) (Pa) at every point (docs/model.md#temperature-dependence).
//   long ObstacleGap(real[] x, real[] y, real[] pipe = [cx, cy, A, B], real[] gap, real[] nx, real[] ny)
//       signed gap and outward pipe normal of reference points (circle when A == B).
//   long PsorCondensed(real[int,int] W, real[] q, real[] g, real[] [omega, tol, maxit, polish],
//                      real[] r, real[] info)   projected SOR on the Delassus problem
//       (r warm start in/out; info = [residual, converged]); returns the sweep count. polish > 0
//       (optional): try an exact active-set solve every `polish` sweeps.
//   long PsorFull(matrix K, real[] b, real[int,int] contact, real[] [omega, tol, maxit], real[] u,
//                 real[] r, real[] info)   projected SOR on the full system K u = b (mode a);
//       contact has one row per contact node: [vertex, nx, ny, gap, threshold g, t.u previous];
//       u warm start in/out; r = interleaved (r_n, r_t) per node; info = [residual, converged].
//   long SpdFactorize(matrix A, long handle)   factorises the symmetric positive definite A in the
//       plugin (sparse LDL', AMD ordering: plugin/core/sparse_spd.hpp) into the slot `handle`
//       (< 0: a new slot); returns the slot. Refactorising a slot with the same pattern is numeric
//       only. Fails, naming the fault, on a non-square, non-symmetric or indefinite A.
//   long SpdSolve(long handle, real[] b, real[] x)   x = A^-1 b (x resized)
//   long SpdDelassus(long handle, matrix H, real[] free, real[int,int] W, long normalOnly)
//       W = H S A^-1 S H', S = diag(free), from sparse forward solves (no dense A^-1 H' kept);
//       normalOnly: only the even (normal) rows and columns, the others 0. Keeps W and its factor
//       Y = L^-1 P S H' in the slot for SpdContactStep.
//   long SpdDelassusAddCompliance(long handle, real[int,int] C, real[int,int] W)
//       adds a second deformable body's compliance C (k x k, W's layout) to the slot's W (an
//       elastic pipe: sparse_spd.hpp add_obstacle_compliance); W receives the new W + C.
//   long SpdContactStep(long handle, real[] rhs, real[int,int] contactTable, real[] tangentFree,
//                       real[] [omega, tol, maxit, polish], real[] r, real[] u, real[] info)
//       one condensed contact global step (plugin/core/contact_step.hpp): the free motion of the
//       contact rows, the PSOR on W (r warm start in/out), u = K^-1 (rhs + S H' r), by one forward
//       and one backward solve; returns the sweep count.
//   long StepOperatorsSet(long handle, matrix B, matrix Q, matrix Interp)   keeps the fraction
//       model's step operators (B: dofs x points, Q: heat nodes x points int s phi, Interp: points x
//       heat nodes) in a slot (< 0: a new one); returns the slot.
//   long StepSolveFraction(real[] settings, real[] data, real[int,int] contactTable,
//                          real[] contact, real[] chi, real[] T, real[] u, real[] stats)
//       one time step of the fraction model by the globalised Newton method of
//       plugin/core/step_newton.hpp (the packing of the arrays: at the function below); returns
//       its iterations; settings[20] = 1 keeps chi, u and the slip thresholds of a step that does
//       not converge at the step's start (the caller's fall-back). A step that does not converge returns stats[0] = 0, and
//   string StepFailureMessage(long)   says why ("" after a converged step).
//   long StepFractionRecord(real[] [rho L / dt, rho, a, L, T0, Tc], matrix Q, matrix Interp,
//                           real[] chi, real[] T, real[] b, real[] load, real[] s)
//       the record of a step the step solver solved (plugin/core/step_record.hpp): load =
//       Q ((|chi| - b) rho L / dt), s = alpha(Interp T) chi, then b = |chi| (in/out); the products
//       are FreeFEM's own (the script's numbers to the bit). Returns the number of points.
//   long RoundToFloat(real[] x)   rounds every value to the nearest single-precision float
//       (IEEE round to nearest even), in place; returns how many values changed.
//   real SmaPluginVersion()  version stamp, checked by edp/lib/plugin.idp.
//   real WallSeconds()       monotonic wall clock (s), for timings.
//   string RealDigits(real x, long digits)   x as a stream of precision `digits` writes it (an
//       ofstream's `f.precision(12); f << x`), for a text built once and written many times.
// Result files, without a shell (plugin/core/files.hpp, json.hpp; edp/lib/output.idp wraps them):
// each string function returns "" on success, else the reason naming the path.
//   string FileMakeDirectory(string path)          mkdir -p
//   string FileRename(string from, string to)      rename, replacing `to`
//   string FileRemoveMatching(string dir, string patterns)   entries of dir matching the patterns
//   int FileKind(string path)                      0 none, 1 file, 2 directory, 3 other
//   string FileAbsolute(string path)               path made absolute (for messages)
//   int FileEndsWith(string path, string tail)     1 if the file ends with tail (+ white space)
//   string FileTruncate(string path, real length)  cuts the file to its first length bytes
//   string FileChecksum(string path, real length)  FNV-1a 64 of the first length bytes (< 0: all), hex;
//                                                  "" if unreadable or shorter
//   string FileSeal(string path)                   appends "checksum <hex>" of the content
//   string FileSealError(string path)              "" if the last line is the rest's checksum
//   string StreamReadNumbers(ifstream f, real[int] values, string name, int integer)   reads
//       values.n number words of a checkpoint's array into values (files.hpp read_numbers:
//       whole decimal words, finite; integers when integer != 0); "" or the bad value named
//   string ResultsClaim(string dir, string scene)  refuse a folder holding anything its manifest
//                                                  does not list, lock it for this run (the lock
//                                                  goes when the process exits), remove the
//                                                  listed entries, start a manifest
//   string ResultsClaimResumed(string dir, string scene, string patterns)   the same for a
//                                                  resumed run: removes only the listed entries
//                                                  that match the patterns
//   string ResultsRecord(string path)              lists path in the manifest of its results folder
//   int ResultsRelease(string dir)                 removes this process's lock of dir now
//   string StreamWriteError(ofstream f)            flushes f; "" if every write so far succeeded
//   string JsonFileError(string path)              "" if the file is valid JSON, finite numbers
//   string JsonQuote(string s), string ShellQuote(string s)
//   long PlaneStressAtCentroids(mesh Th, matrix Dx, matrix Dy, real[] u, real[] [lambda, mu],
//                               real[] sxx, real[] syy, real[] sxy)   the P0 interpolations of
//       SigmaXX, SigmaYY, SigmaXY (edp/lib/elasticity.idp) of the [P1, P1] array u, to the last bit
//       (plugin/core/output.hpp); Dx, Dy = interpolate(Ph, Wh, op = 1), op = 2
//   long ContactTouching(real[] r)   contact nodes touching: normal reaction r[2i] > 0
//   long ContactRecordPeaks(real[] pressure, real[] peak, int[] peakStep, int step)   per node: the
//       step where the pressure exceeds its peak so far, and the peak (max)
//   long ContactRecordSlip(real[] slip, real[] r, real noise, int[] lastSlipStep, int step)   per
//       node: the step, where |slip| > noise while touching (plugin/core/contact_history.hpp)
//   long AreaFractions(real[] chi, real[] area, real[] fractions)   fractions = the area fractions
//       [austenite, martensite 1, martensite 2] of signed martensite fractions chi (resized to 3;
//       plugin/core/step_record.hpp, as the script's FractionsOfChi computed them)
//   long PhaseLabels(real[] chi, real[] labels)   labels = 1 where chi > 0, 2 where chi < 0, else 0
//       (resized to chi's size; dct.idp PhaseLabelsOfChi, step_record.hpp phase_labels)
//   long StepDataSet(real[] data, real[] chi, real[] b, real[] heatRhs, real[] heatMask, real[] force)
//       writes a step's five changing segments of StepSolveFraction's data array (step_record.hpp
//       set_step_data: the layout), copies bit for bit; returns the number of points
//   long HeatOperatorsSet(long handle, matrix Kt, real[] capacity, real[] exchangeLength,
//                         real[] imposedMask, real[] freeMask, real[] TI)   a slot (handle < 0: a
//       new one) keeping the heat problem's arrays (edp/solvers/heat.idp's variables: pointers, read
//       at each call); long HeatBoundarySet(long handle, real[] G0, real[] G1, real[] Text0,
//       real[] Text1) its boundary data
//   long HeatThetaRhs(real[] [slot, dt, theta, tgv], real[] T0, real[] S0, real[] S1, real[] rhs)
//       heat.idp's HeatRhs; long HeatThetaEnergy(real[] [slot, dt, theta], real[] T0, real[] T1,
//       real[] S0, real[] S1, real[] energy)   heat.idp's HeatEnergy, energy = [boundary, latent]
//       (plugin/core/heat_theta.hpp: the script's arithmetic and order, FreeFEM's product)
//   long SameValues(real[] a, real[] b)   1 when b has a's size and every a_i - b_i is 0 (a NaN:
//       0), else 0 (heat.idp's HeatPrepare)
//   real HeatBalanceResidual(real[] capacity, real[] T1, real[] T0, real entered, real released,
//                            real dissipated)   a step's discrete heat balance (time-loop.idp):
//       |stored - budget| / scale, stored = capacity' (T1 - T0), budget = entered + released +
//       dissipated, scale = max(|stored|, |entered| + |released| + dissipated); 0 when the scale is
//       0 (plugin/core/heat_balance.hpp)
//   long ContactHeatExchange(real[int,int] contactTable, real[] r, int m, real gContact, real gPipe,
//                            real Tpipe, real[] g, real[] Text)   the sleeve's default heat condition
//       at its m contact nodes (edp/problems/sleeve/time-loop.idp): g = gContact where the node
//       presses on the pipe (r[2i] > 0), gPipe elsewhere, Text = Tpipe (the nodes: the table's
//       column 0); returns how many press (plugin/core/contact_history.hpp)
//   long CsvWriteRow(ofstream f, real[] values)   writes the values comma-separated (no line end),
//       each in the characters f << value would write (f's precision; plugin/core/output.hpp)
//   long CsvWriteRows(ofstream f, real[int,int] table)   the same for every row of table, each
//       followed by a line end
//   long ProbeRowWrite(ofstream f, real[] [step, time, pipeElastic], real[] [node, vertex, ...],
//                      real[] T, real[] pressure, real[] u, real[int,int] contactTable,
//                      real[] pipeNormalMotion)   points.csv's row (sleeve-2d.idp) and its line end
//       (not flushed: the caller's CheckWritten flushes): step, time, then per probe point (a contact node and its vertex) the
//       temperature, the pressure and the gap ((nx ux + ny uy) - motion) + gap0, the table's
//       columns 1-3 (motion only when pipeElastic is not 0; contact_history.hpp probe_columns)
//   long VtuWrite(string path, mesh Th, string vectorName, real[] vector, string scalarName,
//                 real[] scalar, string cellNames, real[int,int] cells)   a ParaView VTU file in
//       the bytes of savevtk(path, Th, [vector, 0], scalar, cells' columns, order = [1, 1, 0...],
//       withsurfacemesh = false) (plugin/core/output.hpp): vector 2 values per vertex, scalar 1,
//       cells one row per triangle, one column per word of cellNames; 0, or -1 if not written.
//   string MeshFileError(string path, real minQuality)   "" if gmshload may read the MSH file
//       (plugin/core/mesh_check.hpp: format, cut off, clockwise, area < 1e-8, quality)

#include <ff++.hpp>
#include <AFunction_ext.hpp>

#include <cerrno>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <unordered_map>
#include <unistd.h>
#include <vector>

#include "core/files.hpp"
#include "core/output.hpp"
#include "core/contact_history.hpp"
#include "core/json.hpp"
#include "core/material.hpp"
#include "core/mesh_check.hpp"
#include "core/obstacle.hpp"
#include "core/psor.hpp"
#include "core/psor_full.hpp"
#include "core/sparse_spd.hpp"
#include "core/contact_step.hpp"
#include "core/phase_fraction.hpp"
#include "core/phase_projection.hpp"
#include "core/step_newton.hpp"
#include "core/step_record.hpp"
#include "core/heat_theta.hpp"
#include "core/heat_balance.hpp"

using namespace Fem2D;

namespace {

sma::span<double> view(KN<double>* a) { return {a->N() ? &(*a)[0] : nullptr, (std::size_t)a->N()}; }
sma::span<const double> cview(KN<double>* a) {
  return {a->N() ? &(*a)[0] : nullptr, (std::size_t)a->N()};
}

// Eigen throws std::bad_alloc when malloc fails (FreeFEM's own operator new returns null
// instead). Under tools/ff plugin/oomguard.c ends the run before either; run without it, a failed
// allocation in the plugin still ends in one line and exit 12, not in FreeFEM's Exec error.
[[noreturn]] void OutOfMemory(const char* name) {
  struct rlimit as;
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
    std::fprintf(stderr, "error: out of memory in %s under the address-space limit (ulimit -v %llu kB): "
                 "raise it, or use a coarser mesh\n", name, (unsigned long long)as.rlim_cur / 1024);
  else
    std::fprintf(stderr, "error: out of memory in %s (the machine's memory is used up): free some, or "
                 "use a coarser mesh\n", name);
  std::exit(12);
}

template <class F>
auto guarded(const char* name, F f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    OutOfMemory(name);
  } catch (const std::exception& e) {
    ExecError((std::string(name) + ": " + e.what()).c_str());
  }
  return {};
}

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
    Eigen::MatrixXd w(n, n);
    for (long i = 0; i < n; ++i)
      for (long j = 0; j < n; ++j) w(i, j) = (*W)(i, j);
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

// A value no earlier call returned (the versions of the factor slots and the step operators).
std::uint64_t NewVersion() {
  static std::uint64_t counter = 0;
  return ++counter;
}

// The factorisations of SpdFactorize, by slot, each with the contact problem SpdDelassus formed
// on it: glue state, as the step slots and VtuWrite's mesh text are (the core holds none). They
// live until the process ends.
struct FactorSlot {
  sma::SpdFactor factor;
  std::unique_ptr<sma::DelassusFactor> contact;
  // Renewed at every change of the factor or its contact operator, unique over all slots: the
  // step solver's contact memo (StepProblem::mechanics_version) holds for one version only.
  std::uint64_t version = 0;
  void changed() { version = NewVersion(); }
};
std::vector<std::unique_ptr<FactorSlot>>& Factors() {
  static std::vector<std::unique_ptr<FactorSlot>> factors;
  return factors;
}
FactorSlot& SlotAt(long handle) {
  if (handle < 0 || handle >= (long)Factors().size())
    throw std::invalid_argument("no factorisation in slot " + std::to_string(handle) + " (SpdFactorize first)");
  return *Factors()[handle];
}
sma::SpdFactor& FactorAt(long handle) { return SlotAt(handle).factor; }
// The row of each of A's entries in their storage order, in A's index base: its triplets' rows, or
// its row pointers expanded into `expanded`. Throws when A holds neither.
const int* EntryRows(const HashMatrix<int, double>& A, std::vector<int>& expanded) {
  if (A.i) return A.i;
  if (!A.p) throw std::invalid_argument("the matrix has neither triplets nor row pointers");
  const int shift = A.fortran ? 1 : 0;
  expanded.resize(A.nnz);
  for (int r = 0; r < A.n; ++r)
    for (int k = A.p[r] - shift; k < A.p[r + 1] - shift; ++k) expanded[k] = r + shift;
  return expanded.data();
}
// A FreeFEM sparse matrix as an Eigen one (its triplets; the FreeFEM matrix is not modified: sorting
// it in place (HashMatrix::CSR) spoilt the factorisation FreeFEM keeps of it for K^-1, measured).
sma::SparseMatrix ToEigen(Matrice_Creuse<double>* M) {
  HashMatrix<int, double>* A = M->pHM();
  if (!A) throw std::invalid_argument("the matrix is empty");
  if (A->half)
    throw std::invalid_argument("the matrix is stored as a half (symmetric solver): build it with"
                                " solver = sparsesolver or UMFPACK");
  std::vector<int> expanded;
  const int* rows = EntryRows(*A, expanded);
  std::vector<Eigen::Triplet<double, int>> t;
  t.reserve(A->nnz);
  const int shift = A->fortran ? 1 : 0;
  for (size_t k = 0; k < A->nnz; ++k) t.emplace_back(rows[k] - shift, A->j[k] - shift, A->aij[k]);
  sma::SparseMatrix a(A->n, A->m);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

long SpdFactorize(Matrice_Creuse<double>* const& M, long const& handle) {
  return guarded("SpdFactorize", [&] {
    const sma::SparseMatrix a = ToEigen(M);
    long slot = handle;
    if (slot < 0) {
      Factors().push_back(std::make_unique<FactorSlot>());
      slot = (long)Factors().size() - 1;
    }
    SlotAt(slot).factor.factorize(a);
    SlotAt(slot).contact.reset();  // its W was of the previous matrix
    SlotAt(slot).changed();
    return slot;
  });
}

long SpdSolve(long const& handle, KN<double>* const& b, KN<double>* const& x) {
  return guarded("SpdSolve", [&] {
    const sma::SpdFactor& f = FactorAt(handle);
    if (b->N() != f.size())
      throw std::invalid_argument("right-hand side of " + std::to_string(b->N()) + " values for a " +
                                  std::to_string(f.size()) + " x " + std::to_string(f.size()) + " matrix");
    if (x->N() != f.size()) x->resize(f.size());
    f.solve(cview(b), view(x));
    return (long)f.size();
  });
}

long SpdDelassus(long const& handle, Matrice_Creuse<double>* const& H, KN<double>* const& free,
                 KNM<double>* const& W, long const& normalOnly) {
  return guarded("SpdDelassus", [&] {
    auto contact = std::make_unique<sma::DelassusFactor>(
        sma::delassus_factor(FactorAt(handle), ToEigen(H), cview(free), normalOnly != 0));
    const Eigen::MatrixXd& w = contact->w;
    const long k = w.rows();
    W->resize(k, k);
    for (long i = 0; i < k; ++i)
      for (long j = 0; j < k; ++j) (*W)(i, j) = w(i, j);
    SlotAt(handle).contact = std::move(contact);
    SlotAt(handle).changed();
    return k;
  });
}

long SpdDelassusAddCompliance(long const& handle, KNM<double>* const& C, KNM<double>* const& W) {
  return guarded("SpdDelassusAddCompliance", [&] {
    FactorSlot& slot = SlotAt(handle);
    if (!slot.contact) throw std::invalid_argument("no contact problem in slot " + std::to_string(handle) + " (SpdDelassus first)");
    Eigen::MatrixXd c(C->N(), C->M());
    for (long i = 0; i < C->N(); ++i)
      for (long j = 0; j < C->M(); ++j) c(i, j) = (*C)(i, j);
    sma::add_obstacle_compliance(*slot.contact, c);
    slot.changed();
    const Eigen::MatrixXd& w = slot.contact->w;
    const long k = w.rows();
    W->resize(k, k);
    for (long i = 0; i < k; ++i)
      for (long j = 0; j < k; ++j) (*W)(i, j) = w(i, j);
    return k;
  });
}

// One condensed contact global step (plugin/core/contact_step.hpp) on the contact problem
// SpdDelassus formed in slot `handle`; table: one row per node [vertex, nx, ny, gap, threshold g,
// t.u previous] (contact.idp's contactTable); settings = [omega, tol, maxit, polish].
long SpdContactStep(long const& handle, KN<double>* const& rhs, KNM<double>* const& table,
                    KN<double>* const& tangentFree, KN<double>* const& settings, KN<double>* const& r,
                    KN<double>* const& u, KN<double>* const& info) {
  return guarded("SpdContactStep", [&] {
    FactorSlot& slot = SlotAt(handle);
    if (!slot.contact) throw std::invalid_argument("no contact problem in slot " + std::to_string(handle) + " (SpdDelassus first)");
    const long m = table->N(), n = slot.factor.size();
    if (m > 0 && table->M() != 6) throw std::invalid_argument("the table must have 6 columns");
    if (settings->N() != 4) throw std::invalid_argument("settings must be [omega, tol, maxit, polish]");
    if (info->N() != 2) throw std::invalid_argument("info must have 2 entries");
    if (rhs->N() != n) throw std::invalid_argument("rhs of " + std::to_string(rhs->N()) + " values for " + std::to_string(n) + " dofs");
    if (r->N() != 2 * m) throw std::invalid_argument("r must have 2 entries per contact node");
    std::vector<double> gap(m), threshold(m), reference(m);
    for (long i = 0; i < m; ++i) {
      gap[i] = (*table)(i, 3L);
      threshold[i] = (*table)(i, 4L);
      reference[i] = (*table)(i, 5L);
    }
    if (u->N() != n) u->resize(n);
    sma::ContactStepSettings set;
    set.omega = (*settings)[0];
    set.tol = (*settings)[1];
    set.maxit = (int)(*settings)[2];
    set.polish = (int)(*settings)[3];
    Eigen::VectorXd rv = Eigen::Map<const Eigen::VectorXd>(&(*r)[0], 2 * m);
    const sma::PsorResult res = sma::condensed_global_step(slot.factor, *slot.contact, cview(rhs), gap, threshold,
                                                           reference, cview(tangentFree), set, rv, view(u));
    for (long i = 0; i < 2 * m; ++i) (*r)[i] = rv[i];
    (*info)[0] = res.residual;
    (*info)[1] = res.converged ? 1 : 0;
    return (long)res.iterations;
  });
}

// The operators of the fraction model's step solver (StepOperatorsSet), by slot, and the reason
// the last StepSolveFraction stopped unconverged.
std::vector<std::unique_ptr<sma::StepProblem>>& StepSlots() {
  static std::vector<std::unique_ptr<sma::StepProblem>> slots;
  return slots;
}
std::string& StepFailure() {
  static std::string failure;
  return failure;
}

long StepOperatorsSet(long const& handle, Matrice_Creuse<double>* const& B, Matrice_Creuse<double>* const& Q,
                      Matrice_Creuse<double>* const& interp) {
  return guarded("StepOperatorsSet", [&] {
    long slot = handle;
    if (slot < 0) {
      StepSlots().push_back(std::make_unique<sma::StepProblem>());
      slot = (long)StepSlots().size() - 1;
    }
    if (slot >= (long)StepSlots().size()) throw std::invalid_argument("no step slot " + std::to_string(slot));
    sma::StepProblem& p = *StepSlots()[slot];
    p.load = ToEigen(B);
    p.latent = ToEigen(Q);
    p.interp = ToEigen(interp);
    p.operators_version = NewVersion();
    return slot;
  });
}

// a[start .. start + length) into `out`, whose storage is reused when its size is right (the step
// problem's vectors, refilled at every step: a new vector each cost an allocation and a release).
void SegmentInto(Eigen::VectorXd& out, KN<double>* a, long start, long length, const char* what) {
  if (start + length > a->N())
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(a->N()) + " values, " +
                                std::to_string(start + length) + " needed");
  out.resize(length);
  // (a copy of the contiguous values, vectorised: an element loop cost 0.6 % of the default run)
  if (length > 0) out = Eigen::Map<const Eigen::VectorXd>(&(*a)[start], length);
}
// The same as a new vector.
Eigen::VectorXd Segment(KN<double>* a, long start, long length, const char* what) {
  Eigen::VectorXd out;
  SegmentInto(out, a, start, length, what);
  return out;
}

// One time step of the fraction model (plugin/core/step_newton.hpp). settings = [operator slot,
// heat factor slot, stiffness factor slot, rho, a, L, T0, Tc, laminate, rho L / dt, tol, maxit,
// omega, psor tol, psor maxit, polish, slip tol, slip maxit, dissipation k, k / dt]; data = [area; kappa; threshold
// offset; chi at the step's start; b_start] (n points each), [heat right side without the
// latent load; free-node mask] (per heat node), [load f; free-dof mask] (per dof) in one array
// (FreeFEM's plugin functions take at most 8 arguments); table = contact.idp's contactTable
// (column 4, the slip thresholds, in/out); contact = [tangentFree; mu; r (2 per node, in/out)];
// chi in/out; T, u out; stats = [converged, iterations, gradient steps, evaluations, products,
// heat solves, stiffness solves, PSOR sweeps, slip iterations, residual, curvature moves, saddle
// moves, dense Newton moves]. Returns the iterations.
// settings[20] (optional) = 1: a step that does not converge leaves chi, u and the table's slip
// thresholds as they came in (the step's start, for the caller's fall-back: no copies of them).
long StepSolveFraction(KN<double>* const& settings, KN<double>* const& data, KNM<double>* const& table,
                       KN<double>* const& contact, KN<double>* const& chi, KN<double>* const& T,
                       KN<double>* const& u, KN<double>* const& stats) {
  return guarded("StepSolveFraction", [&] {
    if (settings->N() != 20 && settings->N() != 21) throw std::invalid_argument("settings must have 20 or 21 values");
    const bool keepStartUnconverged = settings->N() == 21 && (*settings)[20] != 0;
    const long slot = lrint((*settings)[0]);
    if (slot < 0 || slot >= (long)StepSlots().size())
      throw std::invalid_argument("no step operators in slot " + std::to_string(slot) + " (StepOperatorsSet first)");
    sma::StepProblem& p = *StepSlots()[slot];
    FactorSlot& heatSlot = SlotAt(lrint((*settings)[1]));
    FactorSlot& mechSlot = SlotAt(lrint((*settings)[2]));
    p.heat = &heatSlot.factor;
    p.stiffness = &mechSlot.factor;
    p.contact = mechSlot.contact.get();
    p.mechanics_version = mechSlot.version;
    p.law = sma::ThermalLaw{(*settings)[3], (*settings)[4], (*settings)[5], (*settings)[6], (*settings)[7]};
    p.laminate = (*settings)[8];
    p.latent_scale = (*settings)[9];
    sma::StepSettings set;
    set.tol = (*settings)[10];
    set.maxit = (int)lrint((*settings)[11]);
    if (std::getenv("SMA_STEP_TRACE")) set.trace = stderr;  // docs/parameters.md, "Step solver"
    p.psor.omega = (*settings)[12];
    p.psor.tol = (*settings)[13];
    p.psor.maxit = (int)lrint((*settings)[14]);
    p.psor.polish = (int)lrint((*settings)[15]);
    p.slip_tol = (*settings)[16];
    p.slip_maxit = (int)lrint((*settings)[17]);
    p.dissipation = (*settings)[18];
    p.dissipation_scale = (*settings)[19];
    // m contact nodes: contact's length / 4 (a scene without contact passes none, and its table
    // is not read).
    const long n = chi->N(), nodes = p.heat->size(), dofs = p.stiffness->size(), m = contact->N() / 4;
    if (data->N() != 5 * n + 2 * nodes + 2 * dofs)
      throw std::invalid_argument("data must hold 5 arrays of " + std::to_string(n) + " points, 2 of " +
                                  std::to_string(nodes) + " heat nodes and 2 of " + std::to_string(dofs) +
                                  " dofs; it has " + std::to_string(data->N()) + " values");
    SegmentInto(p.area, data, 0, n, "data");
    SegmentInto(p.kappa, data, n, n, "data");
    SegmentInto(p.threshold_offset, data, 2 * n, n, "data");
    SegmentInto(p.chi_start, data, 3 * n, n, "data");
    SegmentInto(p.b_start, data, 4 * n, n, "data");
    SegmentInto(p.heat_rhs, data, 5 * n, nodes, "data");
    SegmentInto(p.heat_mask, data, 5 * n + nodes, nodes, "data");
    SegmentInto(p.force, data, 5 * n + 2 * nodes, dofs, "data");
    SegmentInto(p.free, data, 5 * n + 2 * nodes + dofs, dofs, "data");
    if (m > 0 && (table->M() != 6 || table->N() != m))
      throw std::invalid_argument("the contact table must have 6 columns and a row per contact node (" +
                                  std::to_string(m) + ", from contact's length)");
    if (contact->N() != 4 * m) throw std::invalid_argument("contact must hold tangentFree, mu and r: 4 values per node");
    if (stats->N() != 14) throw std::invalid_argument("stats must have 14 entries");
    p.gap.resize(m);
    p.slip_reference.resize(m);
    Eigen::VectorXd threshold(m);
    for (long i = 0; i < m; ++i) {
      p.gap[i] = (*table)(i, 3L);
      threshold[i] = (*table)(i, 4L);
      p.slip_reference[i] = (*table)(i, 5L);
    }
    SegmentInto(p.tangent_free, contact, 0, m, "contact");
    SegmentInto(p.mu, contact, m, m, "contact");
    Eigen::VectorXd r = Segment(contact, 2 * m, 2 * m, "contact");
    if (!p.contact && m > 0) throw std::invalid_argument("the stiffness slot has no contact problem (SpdDelassus first)");
    Eigen::VectorXd x = Segment(chi, 0, n, "chi"), temperature(nodes), displacement(dofs);
    const sma::StepResult res = sma::solve_fraction_step(p, set, x, r, threshold, temperature, displacement);
    if (T->N() != nodes) T->resize(nodes);
    for (long i = 0; i < nodes; ++i) (*T)[i] = temperature[i];
    for (long i = 0; i < 2 * m; ++i) (*contact)[2 * m + i] = r[i];
    if (res.converged || !keepStartUnconverged) {
      for (long i = 0; i < n; ++i) (*chi)[i] = x[i];
      if (u->N() != dofs) u->resize(dofs);
      for (long i = 0; i < dofs; ++i) (*u)[i] = displacement[i];
      for (long i = 0; i < m; ++i) (*table)(i, 4L) = threshold[i];
    }
    const double values[14] = {res.converged ? 1.0 : 0.0, (double)res.iterations, (double)res.gradient_steps,
                               (double)res.evaluations, (double)res.products, (double)res.heat_solves,
                               (double)res.stiffness_solves, (double)res.psor_sweeps, (double)res.slip_iterations,
                               res.residual, (double)res.curvature_steps, (double)res.saddle_steps,
                               (double)res.dense_steps, (double)res.reused_solves};
    for (int k = 0; k < 14; ++k) (*stats)[k] = values[k];
    StepFailure() = res.failure;
    return (long)res.iterations;
  });
}

// y = M x by FreeFEM's own product (HashMatrix::addMatMul, as `y = M * x` in a script: the same
// sums in the same order).
void FreeFemProduct(Matrice_Creuse<double>* M, const double* x, double* y, long rows, const char* what) {
  HashMatrix<int, double>* A = M->pHM();
  if (!A) throw std::invalid_argument(std::string(what) + " is empty");
  if (A->n != rows) throw std::invalid_argument(std::string(what) + " has " + std::to_string(A->n) + " rows, " +
                                                std::to_string(rows) + " needed");
  std::fill(y, y + rows, 0.0);
  A->addMatMul(const_cast<double*>(x), y);
}

long StepFractionRecord(KN<double>* const& settings, Matrice_Creuse<double>* const& Q,
                        Matrice_Creuse<double>* const& interp, KN<double>* const& chi, KN<double>* const& T,
                        KN<double>* const& b, KN<double>* const& load, KN<double>* const& s) {
  return guarded("StepFractionRecord", [&] {
    if (settings->N() != 6) throw std::invalid_argument("settings must be [rho L / dt, rho, a, L, T0, Tc]");
    const long n = chi->N(), nodes = T->N();
    const HashMatrix<int, double>* q = Q->pHM();
    const HashMatrix<int, double>* in = interp->pHM();
    if (!q || !in) throw std::invalid_argument("Q and Interp must be set");
    if (q->m != n || in->m != nodes)
      throw std::invalid_argument("Q must be nodes x " + std::to_string(n) + " points and Interp points x " +
                                  std::to_string(nodes) + " nodes");
    if (b->N() != n) throw std::invalid_argument("b must have one value per point");
    if (load->N() != q->n) load->resize(q->n);
    if (s->N() != n) s->resize(n);
    const sma::ThermalLaw law{(*settings)[1], (*settings)[2], (*settings)[3], (*settings)[4], (*settings)[5]};
    sma::fraction_step_record(
        law, (*settings)[0], cview(chi), view(b), cview(T),
        [&](const double* x, double* y) { FreeFemProduct(Q, x, y, q->n, "Q"); },
        [&](const double* x, double* y) { FreeFemProduct(interp, x, y, n, "Interp"); }, view(load), view(s));
    return n;
  });
}

// The heat problem's arrays by slot (HeatOperatorsSet and HeatBoundarySet, once a run): the
// script's own arrays (globals of edp/solvers/heat.idp, resized in place), kept as pointers to its
// variables and read at each call.
struct HeatSlot {
  Matrice_Creuse<double>* conduction = nullptr;
  KN<double>*capacity = nullptr, *length = nullptr, *imposed = nullptr, *free_mask = nullptr, *imposed_t = nullptr;
  KN<double>*g0 = nullptr, *g1 = nullptr, *text0 = nullptr, *text1 = nullptr;
};
std::vector<HeatSlot>& HeatSlots() {
  static std::vector<HeatSlot> slots;
  return slots;
}
HeatSlot& HeatSlotAt(double handle) {
  const long slot = lrint(handle);
  if (slot < 0 || slot >= (long)HeatSlots().size() || !HeatSlots()[slot].g0)
    throw std::invalid_argument("no heat arrays in slot " + std::to_string(slot) +
                                " (HeatOperatorsSet, then HeatBoundarySet, first)");
  return HeatSlots()[slot];
}

long HeatOperatorsSet(long const& handle, Matrice_Creuse<double>* const& conduction, KN<double>* const& capacity,
                      KN<double>* const& length, KN<double>* const& imposed, KN<double>* const& freeMask,
                      KN<double>* const& TI) {
  return guarded("HeatOperatorsSet", [&] {
    long slot = handle;
    if (slot < 0) {
      HeatSlots().emplace_back();
      slot = (long)HeatSlots().size() - 1;
    }
    if (slot >= (long)HeatSlots().size()) throw std::invalid_argument("no heat slot " + std::to_string(slot));
    HeatSlot& h = HeatSlots()[slot];
    h.conduction = conduction, h.capacity = capacity, h.length = length, h.imposed = imposed;
    h.free_mask = freeMask, h.imposed_t = TI;
    return slot;
  });
}

long HeatBoundarySet(long const& handle, KN<double>* const& g0, KN<double>* const& g1, KN<double>* const& text0,
                     KN<double>* const& text1) {
  return guarded("HeatBoundarySet", [&] {
    if (handle < 0 || handle >= (long)HeatSlots().size() || !HeatSlots()[handle].conduction)
      throw std::invalid_argument("no heat slot " + std::to_string(handle) + " (HeatOperatorsSet first)");
    HeatSlot& h = HeatSlots()[handle];
    h.g0 = g0, h.g1 = g1, h.text0 = text0, h.text1 = text1;
    return handle;
  });
}

sma::HeatThetaArrays HeatArraysOf(const HeatSlot& h) {
  return {cview(h.capacity), cview(h.length), cview(h.imposed), cview(h.free_mask), cview(h.imposed_t),
          cview(h.g0),       cview(h.g1),     cview(h.text0),   cview(h.text1)};
}

long HeatThetaRhs(KN<double>* const& settings, KN<double>* const& T0, KN<double>* const& S0, KN<double>* const& S1,
                  KN<double>* const& rhs) {
  return guarded("HeatThetaRhs", [&] {
    if (settings->N() != 4) throw std::invalid_argument("settings must be [heat slot, dt, theta, tgv]");
    const HeatSlot& h = HeatSlotAt((*settings)[0]);
    const long n = T0->N();
    if (rhs->N() != n) rhs->resize(n);
    sma::heat_theta_rhs(
        HeatArraysOf(h), (*settings)[1], (*settings)[2], (*settings)[3], cview(T0), cview(S0), cview(S1),
        [&](const double* x, double* y) { FreeFemProduct(h.conduction, x, y, n, "the heat conduction matrix"); },
        view(rhs));
    return n;
  });
}

long HeatThetaEnergy(KN<double>* const& settings, KN<double>* const& T0, KN<double>* const& T1,
                     KN<double>* const& S0, KN<double>* const& S1, KN<double>* const& energy) {
  return guarded("HeatThetaEnergy", [&] {
    if (settings->N() != 3) throw std::invalid_argument("settings must be [heat slot, dt, theta]");
    const HeatSlot& h = HeatSlotAt((*settings)[0]);
    const long n = T0->N();
    const sma::HeatStepEnergy e = sma::heat_theta_energy(
        HeatArraysOf(h), (*settings)[1], (*settings)[2], cview(T0), cview(T1), cview(S0), cview(S1),
        [&](const double* x, double* y) { FreeFemProduct(h.conduction, x, y, n, "the heat conduction matrix"); });
    if (energy->N() != 2) energy->resize(2);
    (*energy)[0] = e.boundary;
    (*energy)[1] = e.latent;
    return n;
  });
}

long SameValues(KN<double>* const& a, KN<double>* const& b) {
  return guarded("SameValues", [&] { return sma::same_values(cview(a), cview(b)) ? 1L : 0L; });
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

// Projected SOR on the full stiffness system; the matrix is read in CSR form (a row-major copy
// through ToEigen: O(nnz) per call).
long PsorFull(Matrice_Creuse<double>* const& K, KN<double>* const& b, KNM<double>* const& contact,
              KN<double>* const& settings, KN<double>* const& u, KN<double>* const& r,
              KN<double>* const& info) {
  return guarded("PsorFull", [&] {
    const Eigen::SparseMatrix<double, Eigen::RowMajor, int> rows = ToEigen(K);
    if (rows.rows() != rows.cols() || rows.rows() != b->N() || rows.rows() != u->N())
      throw std::invalid_argument("K must be square, of the size of b and u");
    const long m = contact->N();
    if (m > 0 && contact->M() != 6)
      throw std::invalid_argument("contact must have 6 columns [vertex, nx, ny, gap, g, t.u previous]");
    if (settings->N() < 3) throw std::invalid_argument("settings must be [omega, tol, maxit, ...]");
    if (info->N() != 2) throw std::invalid_argument("info must have 2 entries");
    if (r->N() != 2 * m) throw std::invalid_argument("r must have 2 entries per contact node");
    std::vector<int> vertex(m);
    std::vector<double> nx(m), ny(m), gap(m), g(m), ref(m), rn(m), rt(m);
    for (long i = 0; i < m; ++i) {
      vertex[i] = (int)lrint((*contact)((long)i, 0L));
      nx[i] = (*contact)((long)i, 1L), ny[i] = (*contact)((long)i, 2L), gap[i] = (*contact)((long)i, 3L);
      g[i] = (*contact)((long)i, 4L), ref[i] = (*contact)((long)i, 5L);
    }
    sma::CsrView csr{(int)rows.rows(), rows.outerIndexPtr(), rows.innerIndexPtr(), rows.valuePtr()};
    sma::FullPsorSettings set;
    set.omega = (*settings)[0];
    set.tol = (*settings)[1];
    set.maxit = (int)(*settings)[2];
    const sma::ContactNodesView nodes{vertex, nx, ny, gap, g, ref};
    const sma::PsorResult res = sma::psor_full(csr, cview(b), nodes, set, view(u), rn, rt);
    for (long i = 0; i < m; ++i) (*r)[2 * i] = rn[i], (*r)[2 * i + 1] = rt[i];
    (*info)[0] = res.residual;
    (*info)[1] = res.converged ? 1 : 0;
    return (long)res.iterations;
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

double SmaPluginVersion() { return 21.0; }

// FreeFEM's time() has a resolution of one second and clock() counts CPU time; timings of the
// scenes are wall-clock seconds from a monotonic clock.
double WallSeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

string* NewString(Stack stack, const std::string& text) { return Add2StackOfPtr2Free(stack, new string(text)); }

// The reason the last StepSolveFraction stopped unconverged ("" after a converged step); the
// argument is unused (FreeFEM's string functions of no argument need a Stack-less form).
string* StepFailureMessage(Stack stack, long const&) { return NewString(stack, StepFailure()); }

string* RealDigits(Stack stack, double const& x, long const& digits) {
  std::ostringstream text;
  text.precision(std::clamp(digits, 1L, 17L));
  text << x;
  return NewString(stack, text.str());
}

string* FileMakeDirectory(Stack stack, string* const& path) {
  return NewString(stack, sma::files::make_directory(*path));
}
string* FileRename(Stack stack, string* const& from, string* const& to) {
  return NewString(stack, sma::files::rename_file(*from, *to));
}
string* FileRemoveMatching(Stack stack, string* const& dir, string* const& patterns) {
  return NewString(stack, sma::files::remove_matching(*dir, *patterns));
}
long FileKind(string* const& path) { return sma::files::kind(*path); }
string* FileAbsolute(Stack stack, string* const& path) { return NewString(stack, sma::files::absolute(*path)); }
long FileEndsWith(string* const& path, string* const& tail) { return sma::files::ends_with(*path, *tail); }
string* FileChecksum(Stack stack, string* const& path, double const& length) {
  return NewString(stack, sma::files::checksum(*path, std::llround(length)));
}
string* FileSeal(Stack stack, string* const& path) { return NewString(stack, sma::files::seal(*path)); }
string* FileSealError(Stack stack, string* const& path) { return NewString(stack, sma::files::seal_error(*path)); }
string* StreamReadNumbers(Stack stack, std::istream* const& in, KN<double>* const& values, string* const& name,
                          long const& integer) {
  return NewString(stack, sma::files::read_numbers(*in, values->N() ? &(*values)[0] : nullptr,
                                                   (std::size_t)values->N(), integer != 0, *name));
}
string* FileTruncate(Stack stack, string* const& path, double const& length) {
  return NewString(stack, sma::files::truncate_file(*path, std::llround(length)));
}

// The folders this process locked: their locks are removed at exit, however the script ends
// (normal end, Fail's exit(1), FreeFEM's own error exit). A killed process leaves a lock that the
// next run finds stale (its process is gone) and takes.
std::vector<std::string>& ClaimedFolders() {
  static std::vector<std::string> folders;
  return folders;
}
void ReleaseClaimedFolders() {
  for (const auto& dir : ClaimedFolders()) sma::files::release_results(dir, (long)getpid());
}
// The entries this process has recorded in a manifest (files.hpp record_result).
sma::files::RecordedResults& RecordedResults() {
  static sma::files::RecordedResults known;
  return known;
}
string* Claim(Stack stack, const std::string& dir, const std::string& scene, bool resume, const std::string& patterns) {
  std::string error = sma::files::claim_results(dir, scene, (long)getpid(), resume, patterns);
  RecordedResults().clear();  // a fresh claim started a new manifest
  if (error.empty()) {
    if (ClaimedFolders().empty()) std::atexit(ReleaseClaimedFolders);
    ClaimedFolders().push_back(dir);
  }
  return NewString(stack, error);
}
string* ResultsClaim(Stack stack, string* const& dir, string* const& scene) {
  return Claim(stack, *dir, *scene, false, "");
}
string* ResultsClaimResumed(Stack stack, string* const& dir, string* const& scene, string* const& patterns) {
  return Claim(stack, *dir, *scene, true, *patterns);
}
string* ResultsRecord(Stack stack, string* const& path) {
  return NewString(stack, sma::files::record_result(*path, RecordedResults()));
}

long ResultsRelease(string* const& dir) {
  sma::files::release_results(*dir, (long)getpid());
  return 0;
}

// FreeFEM never checks its ofstreams: a full disk leaves a short file and no message. Flushing
// and reading the stream's state tells whether every write so far reached the file.
string* StreamWriteError(Stack stack, std::ostream* const& stream) {
  errno = 0;
  stream->flush();
  if (stream->good()) return NewString(stack, "");
  const int saved = errno;
  return NewString(stack, std::string("a write failed (") + (saved ? std::strerror(saved) : "disk full?") + ")");
}

string* JsonFileError(Stack stack, string* const& path) {
  std::ifstream in(*path, std::ios::binary);
  if (!in) return NewString(stack, "cannot read " + *path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string error = sma::json::validate(text.str());
  return NewString(stack, error.empty() ? "" : *path + " is not valid JSON: " + error);
}
string* MeshFileError(Stack stack, string* const& path, double const& min_quality) {
  return NewString(stack, sma::mesh::check_msh(*path, min_quality));
}
// A ParaView VTU file of mesh Th in savevtk's bytes (plugin/core/output.hpp): point fields, a
// vector (2 values per vertex, interleaved: a [P1, P1] function's array) and a scalar (a P1
// function's array), and cell fields, the columns of `cells` (one row per triangle: P0 arrays)
// named by the words of cellNames. Returns 0, or -1 when the file could not be written.
long VtuWrite(string* const& path, pmesh const& Th, string* const& vectorName, KN<double>* const& vector,
              string* const& scalarName, KN<double>* const& scalar, string* const& cellNames,
              KNM<double>* const& cells) {
  return guarded("VtuWrite", [&] {
    const Mesh& mesh = *Th;
    const long nv = mesh.nv, nt = mesh.nt;
    std::istringstream words(*cellNames);
    std::vector<std::string> names{std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
    if (vector->N() != 2 * nv || scalar->N() != nv)
      throw std::invalid_argument("the point fields need 2 and 1 values per vertex (" + std::to_string(nv) + " vertices)");
    if (cells->N() != nt || cells->M() != (long)names.size())
      throw std::invalid_argument("the cell fields need one row per triangle (" + std::to_string(nt)
                                  + ") and one column per name of '" + *cellNames + "'");
    sma::output::VtuMesh m;
    m.x.resize(nv); m.y.resize(nv); m.triangles.resize(3 * nt); m.labels.resize(nt);
    for (long v = 0; v < nv; ++v) { m.x[v] = mesh(v).x; m.y[v] = mesh(v).y; }
    for (long t = 0; t < nt; ++t) {
      for (int k = 0; k < 3; ++k) m.triangles[3 * t + k] = mesh(t, k);
      m.labels[t] = mesh[t].lab;
    }
    std::vector<sma::output::VtuField> cellFields, pointFields;
    for (std::size_t j = 0; j < names.size(); ++j) {
      sma::output::VtuField f{names[j], 1, std::vector<double>(nt)};
      for (long t = 0; t < nt; ++t) f.values[t] = (*cells)(t, (long)j);
      cellFields.push_back(f);
    }
    pointFields.push_back({*vectorName, 2, std::vector<double>(&(*vector)[0], &(*vector)[0] + 2 * nv)});
    pointFields.push_back({*scalarName, 1, std::vector<double>(&(*scalar)[0], &(*scalar)[0] + nv)});
    // The mesh's part once a run (and again when the mesh changes): the frames share it.
    static sma::output::VtuMeshText meshText;
    std::string text = meshText.of(m);
    sma::output::vtu_fields_part(m, cellFields, pointFields, text);
    std::FILE* file = std::fopen(path->c_str(), "wb");
    if (!file) return -1L;
    const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    return (std::fclose(file) == 0 && written) ? 0L : -1L;
  });
}

// The in-plane stresses of the P1 displacement u per triangle (plugin/core/output.hpp
// plane_stress_p1): Dx, Dy the P0 <- P1 interpolation matrices of the derivatives
// (interpolate(Ph, Wh, op = 1) and op = 2: the coefficients FreeFEM's element computes), lame =
// [lambda, mu]; sxx, syy, sxy receive one value per triangle.
long PlaneStressAtCentroids(pmesh const& Th, Matrice_Creuse<double>* const& Dx, Matrice_Creuse<double>* const& Dy,
                            KN<double>* const& u, KN<double>* const& lame, KN<double>* const& sxx,
                            KN<double>* const& syy, KN<double>* const& sxy) {
  return guarded("PlaneStressAtCentroids", [&] {
    const Mesh& mesh = *Th;
    const long nv = mesh.nv, nt = mesh.nt;
    if (u->N() != 2 * nv) throw std::invalid_argument("u needs 2 values per vertex");
    if (lame->N() != 2) throw std::invalid_argument("lame must be [lambda, mu]");
    std::vector<int> triangles(3 * nt);
    for (long t = 0; t < nt; ++t)
      for (int k = 0; k < 3; ++k) triangles[3 * t + k] = mesh(t, k);
    // the matrices' entries read in place (not converted to Eigen's matrices at every frame)
    auto gradients = [&](Matrice_Creuse<double>* D) {
      HashMatrix<int, double>* A = D->pHM();
      if (!A || A->n != nt || A->m != nv || A->half)
        throw std::invalid_argument("Dx and Dy must be triangles x vertices (interpolate(Ph, Wh, op = 1), op = 2)");
      std::vector<int> expanded;
      return sma::output::centroid_gradients(triangles, EntryRows(*A, expanded), A->j, A->aij, A->nnz,
                                             A->fortran ? 1 : 0);
    };
    const std::vector<double> gx = gradients(Dx), gy = gradients(Dy);
    sxx->resize(nt); syy->resize(nt); sxy->resize(nt);
    sma::output::plane_stress_p1(triangles, gx, gy, &(*u)[0], (*lame)[0], (*lame)[1], &(*sxx)[0], &(*syy)[0],
                                 &(*sxy)[0]);
    return 0L;
  });
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

// CSV rows at the stream's precision in the characters `f << x` writes (plugin/core/output.hpp):
// a row's values comma-separated (no line end), or every row of a table, each ended by a line end.
int CsvPrecision(std::ostream* f) {
  if ((f->flags() & std::ios::floatfield) != std::ios::fmtflags(0) || (f->flags() & std::ios::showpoint))
    throw std::invalid_argument("the stream must print reals in the default format (no fixed, scientific or showpoint)");
  return static_cast<int>(f->precision());
}
// The rows' formatters by stream (a row's text does not depend on which one formats it: each
// checks its kept texts against the values' bits and the precision), one per stream a run writes
// rows to, so that each keeps the columns of its own file's last row.
sma::output::CsvRowFormatter& RowFormatter(const std::ostream* f) {
  static std::unordered_map<const std::ostream*, sma::output::CsvRowFormatter> formatters;
  return formatters[f];
}
long CsvWriteRow(std::ostream* const& f, KN<double>* const& values) {
  return guarded("CsvWriteRow", [&] {
    const std::string row = RowFormatter(f).row(values->N() ? &(*values)[0] : nullptr, values->N(), CsvPrecision(f));
    f->write(row.data(), (std::streamsize)row.size());
    return 0L;
  });
}
long CsvWriteRows(std::ostream* const& f, KNM<double>* const& table) {
  return guarded("CsvWriteRows", [&] {
    const int precision = CsvPrecision(f);
    std::vector<double> row(table->M());
    std::string text;
    sma::output::CsvRowFormatter formatter;  // (a column's repeated values formatted once)
    for (long i = 0; i < table->N(); ++i) {
      for (long j = 0; j < table->M(); ++j) row[j] = (*table)(i, j);
      text += formatter.row(row.data(), row.size(), precision);
      text += '\n';
    }
    f->write(text.data(), (std::streamsize)text.size());
    return 0L;
  });
}

long ProbeRowWrite(std::ostream* const& f, KN<double>* const& head, KN<double>* const& at, KN<double>* const& T,
                   KN<double>* const& pressure, KN<double>* const& u, KNM<double>* const& contact,
                   KN<double>* const& pipeNormalMotion) {
  return guarded("ProbeRowWrite", [&] {
    if (head->N() != 3) throw std::invalid_argument("the row's head must be [step, time, pipeElastic]");
    if (at->N() % 2 != 0) throw std::invalid_argument("the probe points must be pairs [contact node, vertex]");
    const long count = at->N() / 2, m = contact->N();
    const bool elastic = (*head)[2] != 0;
    if (contact->M() < 4) throw std::invalid_argument("contactTable must have the columns [vertex, nx, ny, gap, ...]");
    if (pressure->N() != m || (elastic && pipeNormalMotion->N() != m))
      throw std::invalid_argument("pressure (and the pipe's motion) need one value per contact node");
    std::vector<sma::contact_history::ProbePoint> points(count);
    for (long p = 0; p < count; ++p) {
      const long node = lrint((*at)[2 * p]), vertex = lrint((*at)[2 * p + 1]);
      if (node < 0 || node >= m || vertex < 0 || vertex >= T->N() || 2 * vertex + 1 >= u->N())
        throw std::invalid_argument("probe point " + std::to_string(p) + ": no contact node " + std::to_string(node)
                                    + " or vertex " + std::to_string(vertex));
      points[p] = {node, vertex, (*contact)(node, 1L), (*contact)(node, 2L), (*contact)(node, 3L)};
    }
    std::vector<double> row(2 + 3 * count);
    row[0] = (*head)[0];
    row[1] = (*head)[1];
    if (count > 0)
      sma::contact_history::probe_columns(points.data(), count, &(*T)[0], &(*pressure)[0], &(*u)[0],
                                          elastic ? &(*pipeNormalMotion)[0] : nullptr, &row[2]);
    std::string text = RowFormatter(f).row(row.data(), row.size(), CsvPrecision(f));
    text += '\n';
    f->write(text.data(), (std::streamsize)text.size());
    return 0L;
  });
}

string* JsonQuote(Stack stack, string* const& text) { return NewString(stack, sma::json::quote(*text)); }
string* ShellQuote(Stack stack, string* const& text) { return NewString(stack, sma::files::shell_quote(*text)); }

}  // namespace

static void Load_Init() {
  typedef KN<double>* A;
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
  Global.Add("PsorFull", "(",
             new OneOperator7_<long, Matrice_Creuse<double>*, A, KNM<double>*, A, A, A, A>(PsorFull));
  Global.Add("SpdFactorize", "(", new OneOperator2_<long, Matrice_Creuse<double>*, long>(SpdFactorize));
  Global.Add("SpdSolve", "(", new OneOperator3_<long, long, A, A>(SpdSolve));
  Global.Add("SpdDelassus", "(",
             new OneOperator5_<long, long, Matrice_Creuse<double>*, A, KNM<double>*, long>(SpdDelassus));
  Global.Add("SpdDelassusAddCompliance", "(",
             new OneOperator3_<long, long, KNM<double>*, KNM<double>*>(SpdDelassusAddCompliance));
  Global.Add("SpdContactStep", "(",
             new OneOperator8_<long, long, A, KNM<double>*, A, A, A, A, A>(SpdContactStep));
  Global.Add("StepOperatorsSet", "(",
             new OneOperator4_<long, long, Matrice_Creuse<double>*, Matrice_Creuse<double>*,
                               Matrice_Creuse<double>*>(StepOperatorsSet));
  Global.Add("StepFractionRecord", "(",
             new OneOperator8_<long, A, Matrice_Creuse<double>*, Matrice_Creuse<double>*, A, A, A, A, A>(
                 StepFractionRecord));
  Global.Add("HeatOperatorsSet", "(",
             new OneOperator7_<long, long, Matrice_Creuse<double>*, A, A, A, A, A>(HeatOperatorsSet));
  Global.Add("HeatBoundarySet", "(", new OneOperator5_<long, long, A, A, A, A>(HeatBoundarySet));
  Global.Add("SameValues", "(", new OneOperator2_<long, A, A>(SameValues));
  Global.Add("HeatBalanceResidual", "(",
             new OneOperator6_<double, A, A, A, double, double, double>(HeatBalanceResidual));
  Global.Add("HeatThetaRhs", "(", new OneOperator5_<long, A, A, A, A, A>(HeatThetaRhs));
  Global.Add("HeatThetaEnergy", "(", new OneOperator6_<long, A, A, A, A, A, A>(HeatThetaEnergy));
  Global.Add("StepSolveFraction", "(",
             new OneOperator8_<long, A, A, KNM<double>*, A, A, A, A, A>(StepSolveFraction));
  Global.Add("AuchmutyLocal", "(", new OneOperator5_<double, A, A, A, A, A>(AuchmutyLocal));
  Global.Add("AuchmutyLocalDissipative", "(",
             new OneOperator7_<double, A, A, A, A, A, A, A>(AuchmutyLocalDissipative));
  Global.Add("RoundToFloat", "(", new OneOperator1_<long, A>(RoundToFloat));
  Global.Add("SmaPluginVersion", "(", new OneOperator0<double>(SmaPluginVersion));
  Global.Add("WallSeconds", "(", new OneOperator0<double>(WallSeconds));
  typedef string* S;
  Global.Add("StepFailureMessage", "(", new OneOperator1s_<S, long>(StepFailureMessage));
  Global.Add("FileMakeDirectory", "(", new OneOperator1s_<S, S>(FileMakeDirectory));
  Global.Add("FileRename", "(", new OneOperator2s_<S, S, S>(FileRename));
  Global.Add("RealDigits", "(", new OneOperator2s_<S, double, long>(RealDigits));
  Global.Add("FileRemoveMatching", "(", new OneOperator2s_<S, S, S>(FileRemoveMatching));
  Global.Add("FileKind", "(", new OneOperator1_<long, S>(FileKind));
  Global.Add("FileAbsolute", "(", new OneOperator1s_<S, S>(FileAbsolute));
  Global.Add("FileEndsWith", "(", new OneOperator2_<long, S, S>(FileEndsWith));
  Global.Add("FileTruncate", "(", new OneOperator2s_<S, S, double>(FileTruncate));
  Global.Add("FileChecksum", "(", new OneOperator2s_<S, S, double>(FileChecksum));
  Global.Add("FileSeal", "(", new OneOperator1s_<S, S>(FileSeal));
  Global.Add("FileSealError", "(", new OneOperator1s_<S, S>(FileSealError));
  Global.Add("StreamReadNumbers", "(", new OneOperator4s_<S, std::istream*, A, S, long>(StreamReadNumbers));
  Global.Add("ResultsClaim", "(", new OneOperator2s_<S, S, S>(ResultsClaim));
  Global.Add("ResultsClaimResumed", "(", new OneOperator3s_<S, S, S, S>(ResultsClaimResumed));
  Global.Add("ResultsRecord", "(", new OneOperator1s_<S, S>(ResultsRecord));
  Global.Add("ResultsRelease", "(", new OneOperator1_<long, S>(ResultsRelease));
  Global.Add("StreamWriteError", "(", new OneOperator1s_<S, std::ostream*>(StreamWriteError));
  Global.Add("JsonFileError", "(", new OneOperator1s_<S, S>(JsonFileError));
  Global.Add("VtuWrite", "(", new OneOperator8_<long, S, pmesh, S, A, S, A, S, KNM<double>*>(VtuWrite));
  Global.Add("PlaneStressAtCentroids", "(",
             new OneOperator8_<long, pmesh, Matrice_Creuse<double>*, Matrice_Creuse<double>*, A, A, A, A, A>(
                 PlaneStressAtCentroids));
  Global.Add("ContactTouching", "(", new OneOperator1_<long, A>(ContactTouching));
  Global.Add("ContactRecordPeaks", "(", new OneOperator4_<long, A, A, KN<long>*, long>(ContactRecordPeaks));
  Global.Add("ContactRecordSlip", "(", new OneOperator5_<long, A, A, double, KN<long>*, long>(ContactRecordSlip));
  Global.Add("AreaFractions", "(", new OneOperator3_<long, A, A, A>(AreaFractions));
  Global.Add("PhaseLabels", "(", new OneOperator2_<long, A, A>(PhaseLabels));
  Global.Add("StepDataSet", "(", new OneOperator6_<long, A, A, A, A, A, A>(StepDataSet));
  Global.Add("ContactHeatExchange", "(",
             new OneOperator8_<long, KNM<double>*, A, long, double, double, double, A, A>(ContactHeatExchange));
  Global.Add("CsvWriteRow", "(", new OneOperator2_<long, std::ostream*, A>(CsvWriteRow));
  Global.Add("CsvWriteRows", "(", new OneOperator2_<long, std::ostream*, KNM<double>*>(CsvWriteRows));
  Global.Add("ProbeRowWrite", "(", new OneOperator8_<long, std::ostream*, A, A, A, A, A, KNM<double>*, A>(ProbeRowWrite));
  Global.Add("JsonQuote", "(", new OneOperator1s_<S, S>(JsonQuote));
  Global.Add("MeshFileError", "(", new OneOperator2s_<S, S, double>(MeshFileError));
  Global.Add("ShellQuote", "(", new OneOperator1s_<S, S>(ShellQuote));
}

LOADFUNC(Load_Init)
