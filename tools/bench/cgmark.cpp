// A FreeFEM plugin for tools/bench/statement_costs.py (not part of the suite): CgMark("label")
// dumps callgrind's counters at that point of a script (CALLGRIND_DUMP_STATS_AT), so that each
// dump holds the instructions since the previous mark. Outside valgrind it does nothing.
//   ff-c++ tools/bench/cgmark.cpp   (statement_costs.py builds it into the clone's plugin/build)
#include <valgrind/callgrind.h>

#include "ff++.hpp"

static long CgMark(string* const& label) {
  CALLGRIND_DUMP_STATS_AT(label->c_str());
  return 0;
}

static void Load_Init() { Global.Add("CgMark", "(", new OneOperator1_<long, string*>(CgMark)); }
LOADFUNC(Load_Init)
