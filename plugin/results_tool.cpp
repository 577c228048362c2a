// sma-results: the results folder's claim and manifest (plugin/core/files.hpp) for the suite's
// Python tools, so that a sweep takes its folder and a plot tool lists its figures by the same
// rules as a scene (one implementation: the manifest, the lock, what an earlier run listed kept
// in previous-run/ or removed). Paths are arguments, never shell text.
//   sma-results claim DIR SCENE PID    refuse DIR or lock it for PID, clear what its manifest lists
//   sma-results resume DIR SCENE PATTERNS PID   lock DIR, which must hold SCENE's manifest, for
//                                      PID's resumed run: remove only its listed entries matching
//                                      the shell patterns of PATTERNS (what the run writes again)
//   sma-results complete DIR PID       PID's run of DIR is complete: remove DIR/previous-run
//   sma-results release DIR PID        remove PID's lock of DIR (and say so if the run did not
//                                      complete and previous-run/ keeps the last complete run)
//   sma-results record PATH            list PATH in the manifest of the results folder above it
// Exit 0 on success; else 1 and one line "error: <reason naming the path>" on stderr; 2 on a bad
// command line.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/files.hpp"

int main(int argc, char** argv) {
  const std::string verb = argc > 1 ? argv[1] : "";
  char* end = nullptr;
  const long pid = argc > 1 ? std::strtol(argv[argc - 1], &end, 10) : 0;
  const bool pid_ok = end && *end == '\0' && pid > 0;
  if (verb == "claim" && argc == 5 && pid_ok) {
    const std::string error = sma::files::claim_results(argv[2], argv[3], pid);
    if (error.empty()) return 0;
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return 1;
  }
  if (verb == "resume" && argc == 6 && pid_ok) {
    const std::string error = sma::files::claim_results(argv[2], argv[3], pid, true, argv[4]);
    if (error.empty()) return 0;
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return 1;
  }
  if (verb == "record" && argc == 3) {
    sma::files::RecordedResults known;
    const std::string error = sma::files::record_result(argv[2], known);
    if (error.empty()) return 0;
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return 1;
  }
  if (verb == "complete" && argc == 4 && pid_ok) {
    const std::string error = sma::files::complete_results(argv[2], pid);
    if (error.empty()) return 0;
    std::fprintf(stderr, "error: %s\n", error.c_str());
    return 1;
  }
  if (verb == "release" && argc == 4 && pid_ok) {
    const std::string note = sma::files::release_results_noted(argv[2], pid);
    if (!note.empty()) std::fprintf(stderr, "%s\n", note.c_str());
    return 0;
  }
  std::fprintf(stderr, "usage: sma-results claim DIR SCENE PID | resume DIR SCENE PATTERNS PID | complete DIR PID | release DIR PID | record PATH\n");
  return 2;
}
