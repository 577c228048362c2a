// The factorisations that the solvers' units share (solvers.cpp makes them, step.cpp's step
// solver uses them): glue state, as the step slots and VtuWrite's mesh text are (the core holds
// none). They live until the process ends.
#ifndef SMA_GLUE_SLOTS_HPP
#define SMA_GLUE_SLOTS_HPP

#include <cstdint>
#include <memory>

#include "glue/glue.hpp"
#include "core/contact_step.hpp"
#include "core/sparse_spd.hpp"

namespace sma_glue {

// A value no earlier call returned (the versions of the factor slots and the step operators).
std::uint64_t NewVersion();

// The factorisations of SpdFactorize, by slot, each with the contact problem SpdDelassus formed
// on it.
struct FactorSlot {
  sma::SpdFactor factor;
  // SpdExternal's: a solve the script gives at each StepSolveFractionBy (the distributed run's),
  // which then stands for the factor (solver()); its contact problem SpdDelassusScriptColumns's.
  std::unique_ptr<sma::ExternalSolver> external;
  std::unique_ptr<sma::DelassusFactor> contact;
  const sma::LinearSolver* solver() const {
    if (external) return external.get();
    return &factor;
  }
  // Renewed at every change of the factor or its contact operator, unique over all slots: the
  // step solver's contact memo (StepProblem::mechanics_version) holds for one version only.
  std::uint64_t version = 0;
  void changed() { version = NewVersion(); }
};
// The slot `handle`, or an error naming it.
FactorSlot& SlotAt(long handle);

// A FreeFEM sparse matrix as an Eigen one (its triplets; the FreeFEM matrix is not modified: sorting
// it in place (HashMatrix::CSR) spoilt the factorisation FreeFEM keeps of it for K^-1, measured).
sma::SparseMatrix ToEigen(Matrice_Creuse<double>* M);

}  // namespace sma_glue

#endif
