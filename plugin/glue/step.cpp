// FreeFEM glue of the fraction model's step solver (plugin/core/step_newton.hpp: the globalised
// Newton method of a whole time step), on the factorisations of solvers.cpp (glue/slots.hpp). A
// unit of its own: the step solver's header alone is about 30 s of compilation, which the other
// units do not wait for. The functions are listed in load.cpp.

#include "glue/glue.hpp"
#include "glue/slots.hpp"

#include "core/material.hpp"
#include "core/step_newton.hpp"

namespace sma_glue {
namespace {

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
// settings[21] (optional): a trial's budget of products (StepSettings::product_budget; 0: not a
// trial); stats[14] (when stats has 15 entries or more) = 1 when the trial gave up (on the budget,
// on stalled negative-curvature moves or on the stall rule: StepResult::trial_given_up); with 17
// entries, stats[15] > 0 when an unconverged step's residual is at its floor, 1 the contact's noise
// and 2 round-off's, and stats[16] that noise (StepResult::at_floor, floor_is_noise,
// residual_noise); such a step, not a hard one, returns its
// last iterate even with settings[20] (the caller fails naming the tolerance, or goes on from it).
// settings[22] (optional): the contact's rows per node, 2 (n, t; the default) or 3 (n, t1, t2:
// Coulomb's cone, StepProblem::contact_rows); with 3, contact = [tangentFree; mu; t2.u of
// reference; r (3 per node, in/out)] and the table's column 5 holds t1.u of reference.
long StepSolveFraction(KN<double>* const& settings, KN<double>* const& data, KNM<double>* const& table,
                       KN<double>* const& contact, KN<double>* const& chi, KN<double>* const& T,
                       KN<double>* const& u, KN<double>* const& stats) {
  return guarded("StepSolveFraction", [&] {
    if (settings->N() < 20 || settings->N() > 23) throw std::invalid_argument("settings must have 20 to 23 values");
    const bool keepStartUnconverged = settings->N() >= 21 && (*settings)[20] != 0;
    const long slot = lrint((*settings)[0]);
    if (slot < 0 || slot >= (long)StepSlots().size())
      throw std::invalid_argument("no step operators in slot " + std::to_string(slot) + " (StepOperatorsSet first)");
    sma::StepProblem& p = *StepSlots()[slot];
    FactorSlot& heatSlot = SlotAt(lrint((*settings)[1]));
    FactorSlot& mechSlot = SlotAt(lrint((*settings)[2]));
    p.heat = heatSlot.solver();
    p.stiffness = mechSlot.solver();
    p.contact = mechSlot.contact.get();
    p.mechanics_version = mechSlot.version;
    p.law = sma::ThermalLaw{(*settings)[3], (*settings)[4], (*settings)[5], (*settings)[6], (*settings)[7]};
    p.laminate = (*settings)[8];
    p.latent_scale = (*settings)[9];
    sma::StepSettings set;
    set.tol = (*settings)[10];
    set.maxit = (int)lrint((*settings)[11]);
    if (settings->N() >= 22) set.product_budget = (int)lrint((*settings)[21]);
    const long rows = settings->N() == 23 ? lrint((*settings)[22]) : 2;
    if (rows != 2 && rows != 3) throw std::invalid_argument("settings[22]: contact rows per node must be 2 or 3");
    p.contact_rows = (int)rows;
    if (std::getenv("SMA_STEP_TRACE")) set.trace = stderr;  // docs/parameters.md, "Step solver"
    p.psor.omega = (*settings)[12];
    p.psor.tol = (*settings)[13];
    p.psor.maxit = (int)lrint((*settings)[14]);
    p.psor.polish = (int)lrint((*settings)[15]);
    p.slip_tol = (*settings)[16];
    p.slip_maxit = (int)lrint((*settings)[17]);
    p.dissipation = (*settings)[18];
    p.dissipation_scale = (*settings)[19];
    // m contact nodes: contact's length / 4 (/ 6 on the cone; a scene without contact passes none,
    // and its table is not read).
    const long perNode = rows == 3 ? 6 : 4;
    const long n = chi->N(), nodes = p.heat->size(), dofs = p.stiffness->size(), m = contact->N() / perNode;
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
    if (contact->N() != perNode * m)
      throw std::invalid_argument(rows == 3 ? "contact must hold tangentFree, mu, t2.u of reference and r: 6 values per node"
                                            : "contact must hold tangentFree, mu and r: 4 values per node");
    if (stats->N() != 14 && stats->N() != 15 && stats->N() != 17)
      throw std::invalid_argument("stats must have 14, 15 or 17 entries");
    p.gap.resize(m);
    p.slip_reference.resize((rows - 1) * m);
    Eigen::VectorXd threshold(m);
    for (long i = 0; i < m; ++i) {
      p.gap[i] = (*table)(i, 3L);
      threshold[i] = (*table)(i, 4L);
      p.slip_reference[(rows - 1) * i] = (*table)(i, 5L);
      if (rows == 3) p.slip_reference[2 * i + 1] = (*contact)[2 * m + i];
    }
    SegmentInto(p.tangent_free, contact, 0, m, "contact");
    SegmentInto(p.mu, contact, m, m, "contact");
    const long rStart = (perNode - rows) * m;  // r after the per-node values
    Eigen::VectorXd r = Segment(contact, rStart, rows * m, "contact");
    if (!p.contact && m > 0) throw std::invalid_argument("the stiffness slot has no contact problem (SpdDelassus first)");
    Eigen::VectorXd x = Segment(chi, 0, n, "chi"), temperature(nodes), displacement(dofs);
    const sma::StepResult res = sma::solve_fraction_step(p, set, x, r, threshold, temperature, displacement);
    if (T->N() != nodes) T->resize(nodes);
    for (long i = 0; i < nodes; ++i) (*T)[i] = temperature[i];
    for (long i = 0; i < rows * m; ++i) (*contact)[rStart + i] = r[i];
    if (res.converged || res.at_floor || !keepStartUnconverged) {
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
    if (stats->N() >= 15) (*stats)[14] = res.trial_given_up ? 1.0 : 0.0;
    if (stats->N() == 17) {
      (*stats)[15] = res.at_floor ? (res.floor_is_noise ? 1.0 : 2.0) : 0.0;
      (*stats)[16] = res.residual_noise;
    }
    StepFailure() = res.failure;
    return (long)res.iterations;
  });
}

// StepSolveFractionBy(heatSolve, stiffnessSolve, [contactMotion,] settings, data, table, contact,
// chi, T, u, stats): StepSolveFraction with the heat and stiffness slots' solves the script's
// (SpdExternal slots; the distributed run's, edp/solvers/distributed.idp): each is a FreeFEM function
//   func real solve(real[int] & x)   x = A^-1 x in place (its value unused)
// called by the step solver at each of its solves, on every rank alike. With a contact problem
// whose columns the script keeps (SpdDelassusScriptColumns), contactMotion, of the same form, gives
// their product: x (dofs values) becomes C' x (one value a formed contact row). The functions are
// bound for the call only. Its expression is compiled as FreeFEM's optimisers' (plugin/seq/ffnewuoa.cpp):
// a block of local arrays, each function applied to its own.
class StepSolveFractionByOperator : public OneOperator {
 public:
  // One of the script's solves or products: x = f(b) through the function and its array.
  struct ScriptSolve {
    Stack stack;
    Expression call, array;
    void operator()(const Eigen::VectorXd& b, sma::span<double> x) const {
      KN<double>* a = GetAny<KN<double>*>((*array)(stack));
      a->resize(b.size());
      for (Eigen::Index i = 0; i < b.size(); ++i) (*a)[i] = b[i];
      (*call)(stack);
      WhereStackOfPtr2Free(stack)->clean();
      if (a->N() != (long)x.size())
        throw std::invalid_argument("a script's solve returned " + std::to_string(a->N()) + " values for " +
                                    std::to_string(x.size()) + " unknowns");
      for (std::size_t i = 0; i < x.size(); ++i) x[i] = (*a)[(long)i];
    }
  };

  class Call : public E_F0mps {
   public:
    static constexpr int kArrays = 8;
    bool withMotion;
    Expression arrays[kArrays];
    // The functions (heat, stiffness, the contact's product) and the local arrays they apply to.
    C_F0 open[3], array[3], close;
    Expression call[3];

    explicit Call(const basicAC_F0& args) : withMotion(args.size() == 11) {
      const int functions = withMotion ? 3 : 2;
      static const char* const names[3] = {"the heat solve's array", "the stiffness solve's array",
                                           "the contact product's array"};
      Block::open(currentblock);
      C_F0 size(args[functions], "n");
      for (int f = 0; f < functions; ++f) {
        open[f] = currentblock->NewVar<LocalVariable>(names[f], atype<KN<double>*>(), size);
        array[f] = currentblock->Find(names[f]);
        const Polymorphic* function = dynamic_cast<const Polymorphic*>(args[f].LeftValue());
        if (!function)
          CompileError("StepSolveFractionBy: its first " + std::to_string(functions) +
                       " arguments are functions, func real f(real[int] & x)");
        call[f] = to<double>(C_F0(function, "(", array[f]));
      }
      for (int k = 0; k < kArrays; ++k)
        arrays[k] = k == 2 ? to<KNM<double>*>(args[functions + k]) : to<KN<double>*>(args[functions + k]);
      close = C_F0((Expression)Block::snewclose(currentblock), atype<void>());
    }

    AnyType operator()(Stack stack) const {
      WhereStackOfPtr2Free(stack) = new StackOfPtr2Free(stack);
      for (int f = 0; f < (withMotion ? 3 : 2); ++f) open[f].eval(stack);
      KN<double>* a[kArrays];
      KNM<double>* table = nullptr;
      for (int k = 0; k < kArrays; ++k) {
        if (k == 2) table = GetAny<KNM<double>*>((*arrays[k])(stack));
        else a[k] = GetAny<KN<double>*>((*arrays[k])(stack));
      }
      long its = guarded("StepSolveFractionBy", [&] {
        if (a[0]->N() < 3) throw std::invalid_argument("settings must have 20 to 23 values");
        FactorSlot& heatSlot = SlotAt(lrint((*a[0])[1]));
        FactorSlot& mechSlot = SlotAt(lrint((*a[0])[2]));
        if (!heatSlot.external || !mechSlot.external)
          throw std::invalid_argument("the heat and stiffness slots must be external (SpdExternal)");
        const bool scriptColumns = mechSlot.contact && mechSlot.contact->caller_columns;
        if (scriptColumns != withMotion)
          throw std::invalid_argument(withMotion ? "a contact product given for a slot without the script's contact problem "
                                                   "(SpdDelassusScriptColumns)"
                                                 : "the contact problem's columns are the script's (SpdDelassusScriptColumns): "
                                                   "give their product as the third function");
        // unbound again however the step ends
        struct Unbind {
          FactorSlot &heat, &mech;
          ~Unbind() {
            heat.external->bind(nullptr);
            mech.external->bind(nullptr);
            if (mech.contact) mech.contact->motion = nullptr;
          }
        } unbind{heatSlot, mechSlot};
        heatSlot.external->bind(ScriptSolve{stack, call[0], array[0]});
        mechSlot.external->bind(ScriptSolve{stack, call[1], array[1]});
        if (withMotion) mechSlot.contact->motion = ScriptSolve{stack, call[2], array[2]};
        return StepSolveFraction(a[0], a[1], table, a[3], a[4], a[5], a[6], a[7]);
      });
      close.eval(stack);
      return SetAny<long>(its);
    }
    operator aType() const { return atype<long>(); }
  };

  E_F0* code(const basicAC_F0& args) const { return new Call(args); }
  // The 10-argument form, and the 11-argument one with contactMotion third (withMotion).
  explicit StepSolveFractionByOperator(bool withMotion) : OneOperator(atype<long>(), Signature(withMotion)) {}

 private:
  // The functions, then settings, data, table (a matrix), contact, chi, T, u, stats.
  static ArrayOfaType Signature(bool withMotion) {
    const aType f = atype<Polymorphic*>(), v = atype<KN<double>*>(), m = atype<KNM<double>*>();
    if (withMotion) return ArrayOfaType(f, f, f, v, v, m, v, v, v, v, v, false);
    return ArrayOfaType(f, f, v, v, m, v, v, v, v, v, false);
  }
};

// The reason the last StepSolveFraction stopped unconverged ("" after a converged step); the
// argument is unused (FreeFEM's string functions of no argument need a Stack-less form).
string* StepFailureMessage(Stack stack, long const&) { return NewString(stack, StepFailure()); }

}  // namespace

void AddStepFunctions() {
  typedef KN<double>* A;
  typedef string* S;
  Global.Add("StepOperatorsSet", "(",
             new OneOperator4_<long, long, Matrice_Creuse<double>*, Matrice_Creuse<double>*,
                               Matrice_Creuse<double>*>(StepOperatorsSet));
  Global.Add("StepSolveFraction", "(",
             new OneOperator8_<long, A, A, KNM<double>*, A, A, A, A, A>(StepSolveFraction));
  Global.Add("StepSolveFractionBy", "(", new StepSolveFractionByOperator(false));
  Global.Add("StepSolveFractionBy", "(", new StepSolveFractionByOperator(true));
  Global.Add("StepFailureMessage", "(", new OneOperator1s_<S, long>(StepFailureMessage));
}

}  // namespace sma_glue
