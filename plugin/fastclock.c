/* clock() without a system call, preloaded by tools/ff (LD_PRELOAD) into FreeFem++.
 *
 * Why: FreeFEM 4.11 reads the process CPU time twice per statement of every { } block it
 * evaluates (ListOfInst::operator() in fflib/AFunction.cpp: CPUtime() before and after each
 * statement, for a per-statement display that is off unless FreeFEM is run with -cpu). glibc's
 * clock() is clock_gettime(CLOCK_PROCESS_CPUTIME_ID), a real system call (about 1.5 us here): it
 * was 40 % of the default sleeve run (perf; docs/benchmarks.md, "Where the time goes").
 *
 * What changes: clock() returns the wall time since the process started (CLOCK_MONOTONIC, read
 * through the vDSO without entering the kernel), in CLOCKS_PER_SEC units. For a single-threaded
 * FreeFEM run this is its CPU time plus the time it waited (I/O, exec'd commands); a script's
 * clock() therefore measures elapsed time under tools/ff. Nothing a scene computes depends on it:
 * the outputs are byte-identical with and without it (tests/fastclock_test.py). SMA_FASTCLOCK=0
 * turns it off. */
#define _GNU_SOURCE
#include <time.h>

static struct timespec process_start;

__attribute__((constructor)) static void fastclock_start(void) {
  clock_gettime(CLOCK_MONOTONIC, &process_start);
}

clock_t clock(void) {
  struct timespec now;
  if (clock_gettime(CLOCK_MONOTONIC, &now) != 0) return (clock_t)-1;
  long long us = (long long)(now.tv_sec - process_start.tv_sec) * 1000000LL
                 + (now.tv_nsec - process_start.tv_nsec) / 1000;
  return (clock_t)(us * (CLOCKS_PER_SEC / 1000000));
}
