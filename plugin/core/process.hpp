// A child process run from a script, the caller keeping its own signal dispositions.
//
// FreeFEM's exec() is the C library's system(), which ignores SIGINT and SIGQUIT in the caller
// while the child runs: an INT sent to the scene's process alone (as a user stops a FreeFEM run)
// was discarded, the child finished and the scene went on to publish its results. run_shell waits
// for the child without touching the caller's signals: an INT or TERM stops the caller as it would
// anywhere else (a child that must not outlive it asks for its parent's death signal itself:
// setpriv --pdeathsig TERM).
#pragma once

#include <spawn.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>

#include <signal.h>
#include <stdlib.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

extern char** environ;

namespace sma::process {

// Runs `command` with /bin/sh -c and waits for it: its exit status, 128 + the signal that ended it,
// or -1 when it could not be started.
inline int run_shell(const std::string& command) {
  pid_t pid = 0;
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  if (posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

// Ends the process by the signal `sig` (its default action, whatever handler it had), after the
// standard streams are flushed: a process whose child was stopped by a signal stops as it did, so
// that its own parent sees a stop, not a failure (an MPI rank: mpiexec stops the other ranks, where
// an exit would wait in MPI_Finalize while they wait in their next collective call, for ever).
// Returns only if the signal did not end it (then the caller exits).
inline void stop_by_signal(int sig) {
  std::fflush(nullptr);
  std::signal(sig, SIG_DFL);
  sigset_t unblocked;
  sigemptyset(&unblocked);
  sigaddset(&unblocked, sig);
  sigprocmask(SIG_UNBLOCK, &unblocked, nullptr);
  raise(sig);
}

// Where temporary folders go: $TMPDIR when it names an existing directory by an absolute path (the
// POSIX convention; tools/ff-mpi gives its ranks a folder of the run's, which it removes even when
// MPI_Abort skipped their exit handlers), else /tmp.
inline std::string temporary_root() {
  const char* dir = std::getenv("TMPDIR");
  struct stat st {};
  if (dir == nullptr || dir[0] != '/' || stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) return "/tmp";
  std::string root(dir);
  while (root.size() > 1 && root.back() == '/') root.pop_back();
  return root;
}

// A new, empty directory <temporary_root()>/<prefix>XXXXXX of this process's own (mkdtemp), for a
// scene's scratch runs; "" when it cannot be made (or the prefix holds a slash).
inline std::string temporary_directory(const std::string& prefix) {
  if (prefix.find('/') != std::string::npos) return {};
  const std::string root = temporary_root();
  std::string pattern = root + (root == "/" ? "" : "/") + prefix + "XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  if (mkdtemp(name.data()) == nullptr) return {};
  return std::string(name.data());
}

}  // namespace sma::process
