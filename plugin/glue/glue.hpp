// What the glue units (plugin/glue/*.cpp) share: FreeFEM's headers, array views for the core's
// functions, the guard that turns the core's exceptions into FreeFEM errors, and each unit's
// registration function, called by load.cpp. The units are compiled separately and in parallel:
// only step.cpp includes the step solver (plugin/core/step_newton.hpp, about 30 s of template
// instantiation alone), so an edit elsewhere recompiles in seconds.
#ifndef SMA_GLUE_HPP
#define SMA_GLUE_HPP

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

#include "core/span.hpp"

namespace sma_glue {

using namespace Fem2D;

inline sma::span<double> view(KN<double>* a) { return {a->N() ? &(*a)[0] : nullptr, (std::size_t)a->N()}; }
inline sma::span<const double> cview(KN<double>* a) {
  return {a->N() ? &(*a)[0] : nullptr, (std::size_t)a->N()};
}

// Eigen throws std::bad_alloc when malloc fails (FreeFEM's own operator new returns null
// instead). Under tools/ff plugin/oomguard.c ends the run before either; run without it, a failed
// allocation in the plugin still ends in one line and exit 12, not in FreeFEM's Exec error.
[[noreturn]] inline void OutOfMemory(const char* name) {
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
inline auto guarded(const char* name, F f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    OutOfMemory(name);
  } catch (const std::exception& e) {
    ExecError((std::string(name) + ": " + e.what()).c_str());
  }
  return {};
}

inline string* NewString(Stack stack, const std::string& text) { return Add2StackOfPtr2Free(stack, new string(text)); }

// The row of each of A's entries in their storage order, in A's index base: its triplets' rows, or
// its row pointers expanded into `expanded`. Throws when A holds neither.
inline const int* EntryRows(const HashMatrix<int, double>& A, std::vector<int>& expanded) {
  if (A.i) return A.i;
  if (!A.p) throw std::invalid_argument("the matrix has neither triplets nor row pointers");
  const int shift = A.fortran ? 1 : 0;
  expanded.resize(A.nnz);
  for (int r = 0; r < A.n; ++r)
    for (int k = A.p[r] - shift; k < A.p[r + 1] - shift; ++k) expanded[k] = r + shift;
  return expanded.data();
}

// The language functions of each unit, added to FreeFEM's by load.cpp.
void AddLawFunctions();      // law.cpp: phases, fractions, obstacle, condensed PSOR, contact records
void AddSolverFunctions();   // solvers.cpp: factorisations, contact steps, full PSOR, heat
void AddStepFunctions();     // step.cpp: the fraction model's step solver
void AddOutputFunctions();   // output.cpp: files, results folders, CSV, VTU, JSON, clocks

}  // namespace sma_glue

#endif
