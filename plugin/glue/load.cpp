// The SMA plugin's entry: FreeFEM loads it as "sma" (plugin/build/sma.so). Its glue converts
// FreeFEM arrays to spans and calls the core (plugin/glue/*.cpp, one unit per concern, compiled in
// parallel); everything numerical lives in plugin/core (tested without FreeFEM).
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
//   long SpdExternal(long n, long handle)   a slot (< 0: a new one) whose solver of n unknowns is
//       the script's, given at each StepSolveFractionBy (sparse_spd.hpp ExternalSolver)
//   long SpdDelassusScriptColumns(long handle, matrix H, real[] free, real[int,int] W, long normalOnly)
//       the external slot's contact problem: W the script solved for, the columns
//       C = S A^-1 S H' (dofs x the rows formed) kept by the script, which gives their product
//       C' z to StepSolveFractionBy (its third function): each MPI rank a slice of their rows.
//   long SpdContactStep(long handle, real[] rhs, real[int,int] contactTable, real[] tangentFree,
//                       real[] [omega, tol, maxit, polish], real[] r, real[] u, real[] info)
//       one condensed contact global step (plugin/core/contact_step.hpp): the free motion of the
//       contact rows, the PSOR on W (r warm start in/out), u = K^-1 (rhs + S H' r), by one forward
//       and one backward solve; returns the sweep count.
//   long PsorCone(real[int,int] W, real[] q, real[int,int] table, real[] [omega, tol, maxit, polish],
//                 real[] r, real[] info)   the 3D contact problem (n, t1, t2 per node) on a given W;
//       table one row per node [g] or [g, mu] (Coulomb's cone at once); returns the sweeps.
//   long SpdConeStep(long handle, real[] rhs, real[int,int] table, real[] [omega, tol, maxit, polish],
//                    real[] r, real[] u, real[] info)
//       the same for a 3D contact problem (three rows per node (n, t1, t2), SpdDelassus with
//       normalOnly 0): table [gap, threshold g, t1.u, t2.u at the stage's start] per node, the
//       Tresca disk |r_t| <= g by psor_cone (plugin/core/psor_cone.hpp); r = (r_n, r_t1, r_t2).
//   long StepOperatorsSet(long handle, matrix B, matrix Q, matrix Interp)   keeps the fraction
//       model's step operators (B: dofs x points, Q: heat nodes x points int s phi, Interp: points x
//       heat nodes) in a slot (< 0: a new one); returns the slot.
//   long StepSolveFraction(real[] settings, real[] data, real[int,int] contactTable,
//                          real[] contact, real[] chi, real[] T, real[] u, real[] stats)
//       one time step of the fraction model by the globalised Newton method of
//       plugin/core/step_newton.hpp (the packing of the arrays: at the function below); returns
//       its iterations; settings[20] = 1 keeps chi, u and the slip thresholds of a step that does
//       not converge at the step's start (the caller's fall-back; not one at its residual's floor,
//       stats[15]). A step that does not converge returns stats[0] = 0, and
//   string StepFailureMessage(long)   says why ("" after a converged step).
//   long StepSolveFractionBy(heatSolve, stiffnessSolve, settings, data, contactTable, contact, chi,
//                            T, u, stats)   StepSolveFraction whose heat and stiffness slots are
//       SpdExternal's: their solves are the two script functions, func real f(real[int] & x)
//       (x = A^-1 x in place), bound for the call (the distributed run's ffddm solves).
//   long StepSolveFractionBy(heatSolve, stiffnessSolve, contactMotion, settings, ...)   the same on
//       a contact problem of SpdDelassusScriptColumns: contactMotion(x) makes x (dofs) C' x.
//   long StepFractionRecord(real[] [rho L / dt, rho, a, L, T0, Tc], matrix Q, matrix Interp,
//                           real[] chi, real[] T, real[] b, real[] load, real[] s)
//       the record of a step the step solver solved (plugin/core/step_record.hpp): load =
//       Q ((|chi| - b) rho L / dt), s = alpha(Interp T) chi, then b = |chi| (in/out); the products
//       are FreeFEM's own (the script's numbers to the bit). Returns the number of points.
//   long RoundToFloat(real[] x)   rounds every value to the nearest single-precision float
//       (IEEE round to nearest even), in place; returns how many values changed.
//   real SmaPluginVersion()  version stamp, checked by edp/lib/plugin.idp (and, in the file, by the launchers).
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
//                                                  goes when the process exits), move a complete
//                                                  run's listed entries into previous-run/ (else
//                                                  remove them), start a manifest
//   string ResultsClaimResumed(string dir, string scene, string patterns)   the same for a
//                                                  resumed run: removes only the listed entries
//                                                  that match the patterns
//   string ResultsRecord(string path)              lists path in the manifest of its results folder
//   int ResultsRelease(string dir)                 removes this process's lock of dir now
//   string ResultsPublished(string path)           path published: a claimed folder's summary.json
//                                                  completes its run (previous-run/ removed)
//   string StreamWriteError(ofstream f)            flushes f; "" if every write so far succeeded
//   string JsonFileError(string path)              "" if the file is valid JSON, finite numbers
//   string JsonQuote(string s), string ShellQuote(string s)
//   long RunCommand(string command)   /bin/sh -c command, waited for: its exit status (128 + the
//       signal that ended it, -1 if it did not start); unlike exec() (system()), the caller keeps
//       its INT and QUIT meanwhile (plugin/core/process.hpp)
//   long StopBySignal(long n)          ends the process by signal n (its default action; after
//       flushing cout and cerr): a stop passed on as a stop (plugin/core/process.hpp)
//   string TemporaryDirectory(string prefix)   a new empty $TMPDIR/<prefix>XXXXXX (else /tmp) ("" on failure), removed
//                                              with its contents when the process exits
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

#include "glue/glue.hpp"

// The plugin's version: SmaPluginVersion() for the scripts (edp/lib/plugin.idp), and a stamp in
// the file that the launchers read before FreeFEM starts (tools/launcher-common.sh): FreeFEM
// compiles a whole script before running any of it, so a plugin that lacks a function the scene
// calls stops at compilation ("The Identifier ... does not exist") before plugin.idp's check runs.
#define SMA_PLUGIN_VERSION 28
#define SMA_STRINGIFY(x) #x
#define SMA_VERSION_STAMP(v) "sma-plugin-version " SMA_STRINGIFY(v) ";"
extern "C" __attribute__((used, visibility("default")))
const char sma_plugin_version_stamp[] = SMA_VERSION_STAMP(SMA_PLUGIN_VERSION);

namespace sma_glue {
namespace {

double SmaPluginVersion() { return SMA_PLUGIN_VERSION; }

}  // namespace
}  // namespace sma_glue

static void Load_Init() {
  using namespace sma_glue;
  Global.Add("SmaPluginVersion", "(", new OneOperator0<double>(SmaPluginVersion));
  AddLawFunctions();
  AddSolverFunctions();
  AddStepFunctions();
  AddOutputFunctions();
}

LOADFUNC(Load_Init)
