// A stand-in for FreeFEM's MUMPS_mpi plugin, which Debian's FreeFEM 4.11 does not ship: ffddm.idp's
// first lines `load "MUMPS_mpi"`, and without it no ffddm script starts. It registers nothing, so
// ffddm's local factorisations (each on one rank's communicator) use FreeFEM's default sparse
// solver (UMFPACK), and what names the solver "MUMPS" itself (ffddm's GenEO coarse space) fails
// with FreeFEM's own error instead of running on a solver it does not have. MUMPS_seq cannot stand
// in: its MPI stubs clash with OpenMPI's ("mpi_init: invoked multiple times", measured).
// Built by the Makefile into plugin/build/ffddm/ (docs/benchmarks/ffddm-sleeve-3d.md).
#include "ff++.hpp"

static void Init() {}
LOADFUNC(Init)
