/* Out of memory ends the run with one line, preloaded by tools/ff (LD_PRELOAD) into FreeFem++.
 *
 * Why: FreeFEM 4.11 (Debian's build) replaces the global operator new and new[] with a bare
 * malloc (its CheckPtr counters): a failed `new` anywhere in the process, FreeFEM's lexer, its
 * arrays, the plugin's std::vector, returns a null pointer instead of throwing std::bad_alloc, and
 * the caller writes through it: a segmentation fault (ulimit -v 94000-96000 kB: a memcpy in
 * mylex::readin, set_init_init of a KN<String>). OpenBLAS 0.3.21 retries a failed buffer
 * allocation forever (blas_memory_alloc): with one BLAS thread (tools/ff), the first UMFPACK solve
 * of beam or free-ring under ulimit -v 96000-230000 kB spun without end. libgfortran exits 1
 * without an `error:` line ("Memory allocation failed").
 *
 * What changes: malloc and its relatives forward to glibc's own (__libc_malloc, ...); when one
 * fails for a size above zero, the process prints
 *   error: out of memory: an allocation of N bytes failed under the address-space limit
 *          (ulimit -v K kB): raise it, or use a coarser mesh
 * (or names the data-segment limit, or the machine's memory) and exits 12 (ENOMEM), running its
 * exit handlers (the results folder's lock is released) when the main thread failed. A caller
 * that would have coped with a null pointer (UMFPACK retrying a smaller workspace) cannot: at the
 * edge of memory such a run ends cleanly instead. What no malloc sees, the loader failing to map a
 * library (exit 127) or the plugin (FreeFEM's Load error, exit 2), tools/ff names under a limit.
 * Successful allocations are unchanged: every output of sleeve-circular, sleeve-radial,
 * sleeve-elliptic, beam, free-ring and ring-lame is byte-identical with and without it. */
#define _GNU_SOURCE
#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

extern void* __libc_malloc(size_t size);
extern void* __libc_calloc(size_t count, size_t size);
extern void* __libc_realloc(void* old, size_t size);
extern void* __libc_memalign(size_t alignment, size_t size);
extern void* __libc_valloc(size_t size);
extern void* __libc_pvalloc(size_t size);

enum { EXIT_OUT_OF_MEMORY = 12 };

static int failing;

/* Appends text to buf (no allocation: this runs where malloc has just failed). */
static size_t put(char* buf, size_t at, size_t cap, const char* text) {
  while (*text && at + 1 < cap) buf[at++] = *text++;
  buf[at] = 0;
  return at;
}

static size_t put_number(char* buf, size_t at, size_t cap, unsigned long long value) {
  char digits[24];
  int n = 0;
  do {
    digits[n++] = (char)('0' + value % 10);
    value /= 10;
  } while (value);
  char text[24];
  for (int i = 0; i < n; ++i) text[i] = digits[n - 1 - i];
  text[n] = 0;
  return put(buf, at, cap, text);
}

static void out_of_memory(size_t bytes) __attribute__((noreturn));
static void out_of_memory(size_t bytes) {
  /* A second failure (in an exit handler, or another thread) ends the process at once. */
  if (__atomic_exchange_n(&failing, 1, __ATOMIC_SEQ_CST)) _exit(EXIT_OUT_OF_MEMORY);
  char line[400];
  size_t at = put(line, 0, sizeof line, "error: out of memory: an allocation of ");
  at = put_number(line, at, sizeof line, bytes);
  at = put(line, at, sizeof line, " bytes failed ");
  struct rlimit as, data;
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    at = put(line, at, sizeof line, "under the address-space limit (ulimit -v ");
    at = put_number(line, at, sizeof line, (unsigned long long)as.rlim_cur / 1024);
    at = put(line, at, sizeof line, " kB): raise it, or use a coarser mesh\n");
  } else if (getrlimit(RLIMIT_DATA, &data) == 0 && data.rlim_cur != RLIM_INFINITY) {
    at = put(line, at, sizeof line, "under the data-segment limit (ulimit -d ");
    at = put_number(line, at, sizeof line, (unsigned long long)data.rlim_cur / 1024);
    at = put(line, at, sizeof line, " kB): raise it, or use a coarser mesh\n");
  } else {
    at = put(line, at, sizeof line,
             "(the machine's memory, or what its overcommit policy allows, is used up): "
             "free some, or use a coarser mesh\n");
  }
  ssize_t ignored = write(STDERR_FILENO, line, at);
  (void)ignored;
  if (getpid() == (pid_t)syscall(SYS_gettid)) exit(EXIT_OUT_OF_MEMORY);
  _exit(EXIT_OUT_OF_MEMORY);
}

void* malloc(size_t size) {
  void* p = __libc_malloc(size);
  if (!p && size) out_of_memory(size);
  return p;
}

void* calloc(size_t count, size_t size) {
  void* p = __libc_calloc(count, size);
  if (!p && count && size) out_of_memory(count > SIZE_MAX / size ? SIZE_MAX : count * size);
  return p;
}

void* realloc(void* old, size_t size) {
  void* p = __libc_realloc(old, size);
  if (!p && size) out_of_memory(size);
  return p;
}

void* reallocarray(void* old, size_t count, size_t size) {
  if (size && count > SIZE_MAX / size) {
    errno = ENOMEM; /* an overflow, not a lack of memory: the caller's to handle */
    return NULL;
  }
  return realloc(old, count * size);
}

void* memalign(size_t alignment, size_t size) {
  void* p = __libc_memalign(alignment, size);
  if (!p && size) out_of_memory(size);
  return p;
}

void* aligned_alloc(size_t alignment, size_t size) { return memalign(alignment, size); }

int posix_memalign(void** result, size_t alignment, size_t size) {
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0 || alignment == 0) return EINVAL;
  void* p = __libc_memalign(alignment, size);
  if (!p && size) out_of_memory(size);
  *result = p;
  return 0;
}

void* valloc(size_t size) {
  void* p = __libc_valloc(size);
  if (!p && size) out_of_memory(size);
  return p;
}

void* pvalloc(size_t size) {
  void* p = __libc_pvalloc(size);
  if (!p && size) out_of_memory(size);
  return p;
}
