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
 * turns it off.
 *
 * FreeFEM's own timers, the statement loop (ListOfInst::operator(), which calls clock() inline,
 * about 570 000 times in the default run) and its sparse product (HashMatrix<int, double>::
 * addMatMul), read the coarse clock instead (CLOCK_MONOTONIC_COARSE: the kernel's last tick, a
 * few milliseconds' resolution, without reading the time-stamp counter): even through the vDSO
 * the fine clock was 6 % of the default run's time (perf). They are told by the caller's address,
 * within those functions' symbols in the FreeFem++ executable (looked up once; a FreeFEM without
 * them keeps the fine clock everywhere; SMA_FASTCLOCK_REPORT=1 says how many were found). A
 * script's clock() comes through CPUtime(), a function of its own: it keeps the fine clock. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <link.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static struct timespec process_start, process_start_coarse;

/* The address ranges of FreeFEM's timers. */
enum { kMaxSites = 2 };
static const char* timer_begin[kMaxSites];
static const char* timer_end[kMaxSites];
static int timers;

static void add_timer(const char* symbol) {
  void* address = dlsym(RTLD_DEFAULT, symbol);
  Dl_info info;
  const ElfW(Sym)* entry = 0;
  if (!address || !dladdr1(address, &info, (void**)&entry, RTLD_DL_SYMENT) || !entry || entry->st_size == 0)
    return;
  timer_begin[timers] = (const char*)address;
  timer_end[timers] = (const char*)address + entry->st_size;
  ++timers;
}

__attribute__((constructor)) static void fastclock_start(void) {
  clock_gettime(CLOCK_MONOTONIC, &process_start);
  clock_gettime(CLOCK_MONOTONIC_COARSE, &process_start_coarse);
  add_timer("_ZNK10ListOfInstclEPv");                 /* ListOfInst::operator()(void*) const */
  add_timer("_ZNK10HashMatrixIidE9addMatMulEPdS1_bii"); /* HashMatrix<int, double>::addMatMul */
  /* (tests/fastclock_test.py: how many of FreeFEM's timers were found) */
  if (getenv("SMA_FASTCLOCK_REPORT")) fprintf(stderr, "fastclock: %d coarse timers\n", timers);
}

static clock_t since(const struct timespec* start, const struct timespec* now) {
  long long us = (long long)(now->tv_sec - start->tv_sec) * 1000000LL + (now->tv_nsec - start->tv_nsec) / 1000;
  return (clock_t)(us * (CLOCKS_PER_SEC / 1000000));
}

clock_t clock(void) {
  const char* caller = (const char*)__builtin_return_address(0);
  struct timespec now;
  for (int k = 0; k < timers; ++k)
    if (caller >= timer_begin[k] && caller < timer_end[k]) {
      if (clock_gettime(CLOCK_MONOTONIC_COARSE, &now) != 0) return (clock_t)-1;
      return since(&process_start_coarse, &now);
    }
  if (clock_gettime(CLOCK_MONOTONIC, &now) != 0) return (clock_t)-1;
  return since(&process_start, &now);
}
