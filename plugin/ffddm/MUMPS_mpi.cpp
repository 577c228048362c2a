// A stand-in for FreeFEM's MUMPS_mpi plugin, which Debian's FreeFEM 4.11 does not ship: ffddm.idp's
// first lines `load "MUMPS_mpi"`, and without it no ffddm script starts. MUMPS_seq cannot stand
// in: its MPI stubs clash with OpenMPI's ("mpi_init: invoked multiple times", measured).
//
// It registers one solver under the name "MUMPS", the name ffddm's GenEO coarse space asks for
// (ffddm_geneoCS.idp: set(E, solver = "MUMPS", commworld = commCS, master = -1)): UMFPACK, the
// sequential direct solver FreeFEM already uses, on a matrix held by a single rank. That is exact
// for ffddm's default, the coarse problem gathered on one rank (-ffddm_master_p 1), and for any
// factorisation on one rank's own communicator. A matrix whose communicator spans several ranks
// (-ffddm_master_p > 1: each rank holds some rows) is refused by name: UMFPACK on one rank's rows
// would be a wrong answer, not a slow one. The local factorisations keep FreeFEM's default
// sparse solver (UMFPACK): "MUMPS" is not made the default. It also gives the scripts
// MpiAbortAll(code), to stop every rank after an error one rank caught (try/catch): FreeFEM's own
// error path leaves the other ranks waiting for ever.
// Built by the Makefile into plugin/build/ffddm/ (docs/benchmarks/ffddm-sleeve-3d.md).
#include "ff++.hpp"
#include "SparseLinearSolver.hpp"
#include <dlfcn.h>

namespace {

// The ranks of the solver's communicator (the pointer to an MPI_Comm FreeFEM passes, or none for
// MPI_COMM_WORLD); 1 in a FreeFEM without MPI. No mpi.h on this machine (Debian's FreeFEM needs
// none): OpenMPI's MPI_Comm is a pointer, and its functions are found in the running process.
int CommunicatorRanks(const Data_Sparse_Solver& ds) {
  using CommSize = int (*)(void*, int*);
  using Initialized = int (*)(int*);
  void* sizeSymbol = dlsym(RTLD_DEFAULT, "MPI_Comm_size");
  void* initializedSymbol = dlsym(RTLD_DEFAULT, "MPI_Initialized");
  if (!sizeSymbol || !initializedSymbol) return 1;
  int initialized = 0;
  reinterpret_cast<Initialized>(initializedSymbol)(&initialized);
  if (!initialized) return 1;
  void* comm = ds.commworld ? *static_cast<void**>(ds.commworld) : dlsym(RTLD_DEFAULT, "ompi_mpi_comm_world");
  if (!comm) ExecError("MUMPS stand-in (plugin/ffddm/MUMPS_mpi.cpp): no communicator to check (not OpenMPI?)");
  int ranks = 0;
  reinterpret_cast<CommSize>(sizeSymbol)(comm, &ranks);
  return ranks;
}

// MPI_Abort on MPI_COMM_WORLD with `code` (no MPI in the process: exit). Every rank stops: a rank
// that failed alone would wait in MPI_Finalize and the others in their next collective call.
void AbortAllRanks(int code) {
  using Abort = int (*)(void*, int);
  void* abortSymbol = dlsym(RTLD_DEFAULT, "MPI_Abort");
  void* world = dlsym(RTLD_DEFAULT, "ompi_mpi_comm_world");
  std::cout.flush();
  std::cerr.flush();
  if (abortSymbol && world) reinterpret_cast<Abort>(abortSymbol)(world, code);
  std::exit(code);
}

class MumpsStandIn : public VirtualSolverUMFPACK<int, double> {
 public:
  MumpsStandIn(HashMatrix<int, double>& A, const Data_Sparse_Solver& ds, Stack stack)
      : VirtualSolverUMFPACK<int, double>(A, ds, stack) {
    const int ranks = CommunicatorRanks(ds);
    if (ranks != 1) {
      std::string what = "MUMPS stand-in (plugin/ffddm/MUMPS_mpi.cpp): the matrix is distributed over " +
                         std::to_string(ranks) +
                         " ranks, which needs the real MUMPS_mpi (Debian's FreeFEM lacks it); keep ffddm's coarse "
                         "problem on one rank (-ffddm_master_p 1, the default)";
      // MPI_Abort, not FreeFEM's ExecError: the refusing ranks would stop while the others wait
      // in the next collective call for ever (measured: -ffddm_master_p 2 on 4 ranks hung).
      std::cerr << "error: " << what << std::endl;
      AbortAllRanks(1);
    }
  }
};

// MpiAbortAll(code), for the scripts: after a FreeFEM error caught on one rank (try/catch), stop
// them all rather than leave the others waiting.
long MpiAbortAll(long const& code) {
  AbortAllRanks((int)code);
  return code;
}

}  // namespace

static void Init() {
  addsolver<MumpsStandIn>("MUMPS", 1);
  Global.Add("MpiAbortAll", "(", new OneOperator1_<long, long>(MpiAbortAll));
}
LOADFUNC(Init)
