// FreeFEM glue of the sparse factorisations, the condensed contact step, the full PSOR and the
// heat's theta scheme (plugin/core: sparse_spd, contact_step, psor_full, step_record,
// heat_theta), with the slots that keep their factors (glue/slots.hpp) and the heat's arrays
// between calls. The functions are listed in load.cpp.
#include "glue/glue.hpp"
#include "glue/dense.hpp"
#include "glue/slots.hpp"

#include "core/heat_theta.hpp"
#include "core/material.hpp"
#include "core/psor_full.hpp"
#include "core/step_record.hpp"

namespace sma_glue {

// A value no earlier call returned (the versions of the factor slots and the step operators).
std::uint64_t NewVersion() {
  static std::uint64_t counter = 0;
  return ++counter;
}
std::vector<std::unique_ptr<FactorSlot>>& Factors() {
  static std::vector<std::unique_ptr<FactorSlot>> factors;
  return factors;
}
FactorSlot& SlotAt(long handle) {
  if (handle < 0 || handle >= (long)Factors().size())
    throw std::invalid_argument("no factorisation in slot " + std::to_string(handle) + " (SpdFactorize first)");
  return *Factors()[handle];
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


namespace {

// The slot's factor; a slot whose solver is the script's (SpdExternal) has none, said.
FactorSlot& FactoredSlotAt(long handle) {
  FactorSlot& slot = SlotAt(handle);
  if (slot.external)
    throw std::invalid_argument("slot " + std::to_string(handle) + " holds the script's solver (SpdExternal): no factor "
                                "to solve with here (StepSolveFractionBy takes its solves)");
  return slot;
}
sma::SpdFactor& FactorAt(long handle) { return FactoredSlotAt(handle).factor; }

// The slot `handle`, or a new one when it is < 0.
long SlotOrNew(long handle) {
  if (handle >= 0) return handle;
  Factors().push_back(std::make_unique<FactorSlot>());
  return (long)Factors().size() - 1;
}

long SpdFactorize(Matrice_Creuse<double>* const& M, long const& handle) {
  return guarded("SpdFactorize", [&] {
    const sma::SparseMatrix a = ToEigen(M);
    const long slot = SlotOrNew(handle);
    SlotAt(slot).factor.factorize(a);
    SlotAt(slot).external.reset();  // (the factor stands for the slot's solver again)
    SlotAt(slot).contact.reset();  // its W was of the previous matrix
    SlotAt(slot).changed();
    return slot;
  });
}

// A slot whose solver is the script's (sparse_spd.hpp ExternalSolver, n unknowns): the distributed
// run's stiffness and heat solves for the step solver (StepSolveFractionBy binds them).
long SpdExternal(long const& n, long const& handle) {
  return guarded("SpdExternal", [&] {
    const long slot = SlotOrNew(handle);
    FactorSlot& s = SlotAt(slot);
    s.external = std::make_unique<sma::ExternalSolver>((int)n);
    s.contact.reset();
    s.changed();
    return slot;
  });
}

// The contact problem of an external slot: W = H S A^-1 S H' the script solved for, the columns
// C = S A^-1 S H_rows' (dofs x the rows formed: all, or the even ones with normalOnly) kept by the
// script (sparse_spd.hpp delassus_from_caller_columns), which gives their product C' z as
// StepSolveFractionBy's third function (the distributed run's: each rank a slice of their rows).
long SpdDelassusScriptColumns(long const& handle, Matrice_Creuse<double>* const& H, KN<double>* const& free,
                              KNM<double>* const& W, long const& normalOnly) {
  return guarded("SpdDelassusScriptColumns", [&] {
    FactorSlot& slot = SlotAt(handle);
    if (!slot.external) throw std::invalid_argument("slot " + std::to_string(handle) + " has no external solver (SpdExternal first)");
    const Eigen::MatrixXd w = DenseOf(W);
    const sma::SparseMatrix h = ToEigen(H);
    if (h.cols() != slot.external->size())
      throw std::invalid_argument("H has " + std::to_string(h.cols()) + " columns for an external solver of " +
                                  std::to_string(slot.external->size()) + " unknowns");
    slot.contact = std::make_unique<sma::DelassusFactor>(sma::delassus_from_caller_columns(h, cview(free), w, normalOnly != 0));
    slot.changed();
    return (long)w.rows();
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
    const long k = contact->w.rows();
    SetDense(W, contact->w);
    SlotAt(handle).contact = std::move(contact);
    SlotAt(handle).changed();
    return k;
  });
}

long SpdDelassusAddCompliance(long const& handle, KNM<double>* const& C, KNM<double>* const& W) {
  return guarded("SpdDelassusAddCompliance", [&] {
    FactorSlot& slot = SlotAt(handle);
    if (!slot.contact) throw std::invalid_argument("no contact problem in slot " + std::to_string(handle) + " (SpdDelassus first)");
    sma::add_obstacle_compliance(*slot.contact, DenseOf(C));
    slot.changed();
    SetDense(W, slot.contact->w);
    return (long)slot.contact->w.rows();
  });
}

// The checks the two contact steps share: the slot's contact problem, the table (one row per node
// of `columns` columns, named by `layout`), the settings [omega, tol, maxit, polish], info, the
// right-hand side and `rows` reactions per node; returns the slot. The settings as the core's.
FactorSlot& ContactSlotChecked(long handle, KN<double>* rhs, KNM<double>* table, long columns, const char* layout,
                               KN<double>* settings, KN<double>* r, long rows, KN<double>* info) {
  FactorSlot& slot = FactoredSlotAt(handle);
  if (!slot.contact) throw std::invalid_argument("no contact problem in slot " + std::to_string(handle) + " (SpdDelassus first)");
  const long m = table->N(), n = slot.factor.size();
  if (m > 0 && table->M() != columns) throw std::invalid_argument(std::string("the table must have ") + layout);
  if (settings->N() != 4) throw std::invalid_argument("settings must be [omega, tol, maxit, polish]");
  if (info->N() != 2) throw std::invalid_argument("info must have 2 entries");
  if (rhs->N() != n) throw std::invalid_argument("rhs of " + std::to_string(rhs->N()) + " values for " + std::to_string(n) + " dofs");
  if (r->N() != rows * m)
    throw std::invalid_argument("r must have " + std::to_string(rows) + " entries per contact node");
  return slot;
}
sma::ContactStepSettings ContactSettingsOf(KN<double>* settings) {
  sma::ContactStepSettings set;
  set.omega = (*settings)[0];
  set.tol = (*settings)[1];
  set.maxit = (int)(*settings)[2];
  set.polish = (int)(*settings)[3];
  return set;
}
// The step's reactions back into r, its residual and convergence into info; returns its sweeps.
long ContactStepReturned(const sma::PsorResult& res, const Eigen::VectorXd& rv, KN<double>* r, KN<double>* info) {
  for (long i = 0; i < (long)rv.size(); ++i) (*r)[i] = rv[i];
  (*info)[0] = res.residual;
  (*info)[1] = res.converged ? 1 : 0;
  return (long)res.iterations;
}

// One condensed 3D contact step (plugin/core/contact_step.hpp condensed_cone_step) on the contact
// problem SpdDelassus formed in slot `handle` with three rows per node (n, t1, t2), all formed;
// table: one row per node [gap, threshold g, t1.u at the stage's start, t2.u at it], and with a
// fifth column mu Coulomb's cone at once (the disk's radius mu r_n inside the sweeps and the
// polish: psor_cone's coulomb_mu; g is then only the radius the sweeps start from);
// settings = [omega, tol, maxit, polish]; r = (r_n, r_t1, r_t2) per node, the warm start, in/out.
long SpdConeStep(long const& handle, KN<double>* const& rhs, KNM<double>* const& table, KN<double>* const& settings,
                 KN<double>* const& r, KN<double>* const& u, KN<double>* const& info) {
  return guarded("SpdConeStep", [&] {
    const bool coulomb = table->N() > 0 && table->M() == 5;
    FactorSlot& slot = ContactSlotChecked(handle, rhs, table, coulomb ? 5 : 4,
                                          "4 columns [gap, g, t1.u, t2.u], or 5 [gap, g, t1.u, t2.u, mu]", settings, r, 3, info);
    const long m = table->N(), n = slot.factor.size();
    std::vector<double> gap(m), threshold(m), reference(2 * m);
    Eigen::VectorXd mu(coulomb ? m : 0);
    for (long i = 0; i < m; ++i) {
      gap[i] = (*table)(i, 0L);
      threshold[i] = (*table)(i, 1L);
      reference[2 * i] = (*table)(i, 2L);
      reference[2 * i + 1] = (*table)(i, 3L);
      if (coulomb) mu[i] = (*table)(i, 4L);
    }
    if (u->N() != n) u->resize(n);
    Eigen::VectorXd rv = Eigen::Map<const Eigen::VectorXd>(&(*r)[0], 3 * m);
    const sma::PsorResult res = sma::condensed_cone_step(slot.factor, *slot.contact, cview(rhs), gap, threshold, reference,
                                                         ContactSettingsOf(settings), rv, view(u), coulomb ? &mu : nullptr);
    return ContactStepReturned(res, rv, r, info);
  });
}

// The 3D contact problem on a Delassus operator W formed by the caller (psor_cone.hpp: the
// distributed run forms W from ffddm's solves, edp/solvers/distributed.idp): W 3m x 3m, q its free
// motion (3 rows per node: n, t1, t2), table one row per node [g] (Tresca's disk) or [g, mu]
// (Coulomb's cone at once, g the radius to start from); settings = [omega, tol, maxit, polish];
// r the warm start, in/out; info = [residual, converged]. Returns the sweeps.
long PsorCone(KNM<double>* const& W, KN<double>* const& q, KNM<double>* const& table, KN<double>* const& settings,
              KN<double>* const& r, KN<double>* const& info) {
  return guarded("PsorCone", [&] {
    const long n = q->N(), m = table->N();
    if (n != 3 * m || W->N() != n || W->M() != n || r->N() != n)
      throw std::invalid_argument("W (" + std::to_string(W->N()) + " x " + std::to_string(W->M()) + "), q (" +
                                  std::to_string(n) + ") and r (" + std::to_string(r->N()) + ") need 3 rows per node of "
                                  "the table (" + std::to_string(m) + " nodes)");
    if (table->M() != 1 && table->M() != 2) throw std::invalid_argument("the table needs 1 column [g] or 2 [g, mu]");
    if (settings->N() != 4) throw std::invalid_argument("settings must be [omega, tol, maxit, polish]");
    if (info->N() != 2) throw std::invalid_argument("info must have 2 entries");
    const bool coulomb = table->M() == 2;
    const Eigen::MatrixXd w = DenseOf(W);
    Eigen::VectorXd g(m), mu(coulomb ? m : 0);
    for (long i = 0; i < m; ++i) {
      g[i] = (*table)(i, 0L);
      if (coulomb) mu[i] = (*table)(i, 1L);
    }
    Eigen::Map<const Eigen::VectorXd> qv(&(*q)[0], n);
    Eigen::VectorXd rv = Eigen::Map<const Eigen::VectorXd>(&(*r)[0], n);
    const sma::PsorResult res = sma::psor_cone(w, qv, g, (*settings)[0], (*settings)[1], (int)(*settings)[2], rv,
                                               (int)(*settings)[3], coulomb ? &mu : nullptr);
    for (long i = 0; i < n; ++i) (*r)[i] = rv[i];
    (*info)[0] = res.residual;
    (*info)[1] = res.converged ? 1 : 0;
    return (long)res.iterations;
  });
}

// One condensed contact global step (plugin/core/contact_step.hpp) on the contact problem
// SpdDelassus formed in slot `handle`; table: one row per node [vertex, nx, ny, gap, threshold g,
// t.u previous] (contact.idp's contactTable); settings = [omega, tol, maxit, polish].
long SpdContactStep(long const& handle, KN<double>* const& rhs, KNM<double>* const& table,
                    KN<double>* const& tangentFree, KN<double>* const& settings, KN<double>* const& r,
                    KN<double>* const& u, KN<double>* const& info) {
  return guarded("SpdContactStep", [&] {
    FactorSlot& slot = ContactSlotChecked(handle, rhs, table, 6, "6 columns", settings, r, 2, info);
    const long m = table->N(), n = slot.factor.size();
    std::vector<double> gap(m), threshold(m), reference(m);
    for (long i = 0; i < m; ++i) {
      gap[i] = (*table)(i, 3L);
      threshold[i] = (*table)(i, 4L);
      reference[i] = (*table)(i, 5L);
    }
    if (u->N() != n) u->resize(n);
    Eigen::VectorXd rv = Eigen::Map<const Eigen::VectorXd>(&(*r)[0], 2 * m);
    const sma::PsorResult res = sma::condensed_global_step(slot.factor, *slot.contact, cview(rhs), gap, threshold,
                                                           reference, cview(tangentFree), ContactSettingsOf(settings), rv,
                                                           view(u));
    return ContactStepReturned(res, rv, r, info);
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


}  // namespace

void AddSolverFunctions() {
  typedef KN<double>* A;
  typedef string* S;
  Global.Add("PsorFull", "(",
             new OneOperator7_<long, Matrice_Creuse<double>*, A, KNM<double>*, A, A, A, A>(PsorFull));
  Global.Add("SpdFactorize", "(", new OneOperator2_<long, Matrice_Creuse<double>*, long>(SpdFactorize));
  Global.Add("SpdSolve", "(", new OneOperator3_<long, long, A, A>(SpdSolve));
  Global.Add("SpdExternal", "(", new OneOperator2_<long, long, long>(SpdExternal));
  Global.Add("SpdDelassusScriptColumns", "(",
             new OneOperator5_<long, long, Matrice_Creuse<double>*, A, KNM<double>*, long>(SpdDelassusScriptColumns));
  Global.Add("SpdDelassus", "(",
             new OneOperator5_<long, long, Matrice_Creuse<double>*, A, KNM<double>*, long>(SpdDelassus));
  Global.Add("SpdDelassusAddCompliance", "(",
             new OneOperator3_<long, long, KNM<double>*, KNM<double>*>(SpdDelassusAddCompliance));
  Global.Add("SpdContactStep", "(",
             new OneOperator8_<long, long, A, KNM<double>*, A, A, A, A, A>(SpdContactStep));
  Global.Add("SpdConeStep", "(", new OneOperator7_<long, long, A, KNM<double>*, A, A, A, A>(SpdConeStep));
  Global.Add("PsorCone", "(", new OneOperator6_<long, KNM<double>*, A, KNM<double>*, A, A, A>(PsorCone));
  Global.Add("StepFractionRecord", "(",
             new OneOperator8_<long, A, Matrice_Creuse<double>*, Matrice_Creuse<double>*, A, A, A, A, A>(
                 StepFractionRecord));
  Global.Add("HeatOperatorsSet", "(",
             new OneOperator7_<long, long, Matrice_Creuse<double>*, A, A, A, A, A>(HeatOperatorsSet));
  Global.Add("HeatBoundarySet", "(", new OneOperator5_<long, long, A, A, A, A>(HeatBoundarySet));
  Global.Add("SameValues", "(", new OneOperator2_<long, A, A>(SameValues));
  Global.Add("HeatThetaRhs", "(", new OneOperator5_<long, A, A, A, A, A>(HeatThetaRhs));
  Global.Add("HeatThetaEnergy", "(", new OneOperator6_<long, A, A, A, A, A, A>(HeatThetaEnergy));
}

}  // namespace sma_glue
