// Result files without a shell: directories, renames, removal by name pattern, and the claim of a
// results folder (refuse a folder this suite did not write, lock it against a concurrent run).
// Paths are passed to the system as they are: a quote, a space, a semicolon or any UTF-8 in a
// path is a character of the path, never shell syntax. Each function returns an empty string on
// success, else one sentence naming the path and the reason (the scripts turn it into `error:`).
#pragma once
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fnmatch.h>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <sys/types.h>
#include <unistd.h>
#include <vector>

namespace sma::files {

namespace fs = std::filesystem;

// The marker a run leaves in its results folder: a later run may clear the folder's earlier
// results only when it finds the marker there (or a summary.json of a run older than markers).
inline const char* results_marker = ".sma-results";
inline const char* results_lock = ".sma-lock";

inline std::string reason(const std::error_code& ec) { return ec.message(); }

// Creates `path` and its parents; fails when it exists as something other than a directory.
inline std::string make_directory(const std::string& path) {
  if (path.empty()) return "the empty string is not a directory name";
  std::error_code ec;
  fs::create_directories(path, ec);
  if (ec) return "cannot create the directory " + path + ": " + reason(ec);
  if (!fs::is_directory(path, ec)) return "cannot create the directory " + path + ": a file of that name exists";
  return {};
}

// Renames `from` to `to` (atomically within one file system), replacing `to`.
inline std::string rename_file(const std::string& from, const std::string& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) return "cannot write " + to + " (renaming " + from + "): " + reason(ec);
  return {};
}

// `path` made absolute against the current directory (for messages: where a file was looked for).
inline std::string absolute(const std::string& path) {
  std::error_code ec;
  const auto full = fs::absolute(path, ec);
  return ec ? path : full.lexically_normal().string();
}

// 0: nothing there, 1: a regular file (or a link to one), 2: a directory, 3: something else.
inline int kind(const std::string& path) {
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (ec || st.type() == fs::file_type::not_found) return 0;
  if (st.type() == fs::file_type::regular) return 1;
  if (st.type() == fs::file_type::directory) return 2;
  return 3;
}

// The words of a space-separated list.
inline std::vector<std::string> words(const std::string& list) {
  std::vector<std::string> out;
  std::istringstream in(list);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// Removes the entries of `dir` (not below it) whose names match one of the space-separated shell
// patterns of `patterns` (fnmatch: `fields-*.csv`; a match that is a directory goes whole).
// A pattern with a slash or equal to `.`/`..` is refused: it could reach outside `dir`.
inline std::string remove_matching(const std::string& dir, const std::string& patterns) {
  const auto list = words(patterns);
  for (const auto& p : list)
    if (p.find('/') != std::string::npos || p == "." || p == "..")
      return "refusing to remove '" + p + "' in " + dir + ": a removal pattern names entries of the folder only";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return "cannot remove the earlier results in " + dir + ": not a directory";
  std::vector<fs::path> doomed;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    for (const auto& p : list)
      if (fnmatch(p.c_str(), name.c_str(), FNM_PERIOD) == 0) {
        doomed.push_back(it->path());
        break;
      }
  }
  if (ec) return "cannot list " + dir + ": " + reason(ec);
  for (const auto& path : doomed) {
    fs::remove_all(path, ec);
    if (ec) return "cannot remove " + path.string() + ": " + reason(ec);
  }
  return {};
}

// Whether the process `pid` is alive on this machine (a lock of a dead process is stale). A killed
// process whose parent died too stays a zombie until someone reaps it (in a container, maybe
// never): kill(pid, 0) still succeeds, so /proc's state Z counts as dead.
inline bool process_alive(long pid) {
  if (pid <= 0 || !(kill((pid_t)pid, 0) == 0 || errno == EPERM)) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  const auto close = text.rfind(')');  // the command name, in parentheses, may hold spaces
  return close == std::string::npos || close + 2 >= text.size() || text[close + 2] != 'Z';
}

// The process id written in a lock file, or 0.
inline long lock_owner(const fs::path& lock) {
  std::ifstream in(lock);
  long pid = 0;
  in >> pid;
  return in ? pid : 0;
}

// Claims the results folder `dir` for a run of `scene` by the process `pid`:
//  - a folder that holds entries but neither this suite's marker nor a summary.json is someone
//    else's: refused, nothing in it is touched;
//  - a live run's lock in it: refused (two runs would mix their files);
//  - else the lock is taken (a dead process's lock is replaced) and the marker written.
// The caller removes the lock with release_results when the run ends, however it ends.
inline std::string claim_results(const std::string& dir, const std::string& scene, long pid) {
  if (auto e = make_directory(dir); !e.empty()) return e;
  const fs::path d(dir);
  std::error_code ec;
  bool ours = fs::exists(d / results_marker, ec) || fs::exists(d / "summary.json", ec);
  if (!ours) {
    for (fs::directory_iterator it(d, ec), end; !ec && it != end; it.increment(ec))
      if (it->path().filename() != results_lock)
        return "the output folder " + dir + " holds files this suite did not write (" +
               it->path().filename().string() + "): choose a new or empty folder with -out";
    if (ec) return "cannot list the output folder " + dir + ": " + reason(ec);
  }
  const fs::path lock = d / results_lock;
  for (int attempt = 0; attempt < 2; ++attempt) {
    const int fd = open(lock.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd >= 0) {
      const std::string text = std::to_string(pid) + "\n";
      const bool written = write(fd, text.data(), text.size()) == (ssize_t)text.size();
      close(fd);
      if (!written) return "cannot write the lock " + lock.string() + " (disk full?)";
      std::ofstream marker(d / results_marker);
      marker << scene << "\n";
      marker.flush();
      if (!marker) return "cannot write " + (d / results_marker).string() + " (disk full?)";
      return {};
    }
    if (errno != EEXIST) return "cannot create the lock " + lock.string() + ": " + std::strerror(errno);
    const long owner = lock_owner(lock);
    if (owner == pid) return {};
    if (process_alive(owner))
      return "the output folder " + dir + " is in use by another run (process " + std::to_string(owner) +
             ", lock " + lock.string() + "): wait for it or choose another -out";
    // A dead run's lock: move it aside under a name of our own, so that of two runs that find
    // the same stale lock only one takes the folder (the O_EXCL create above decides).
    const fs::path aside = d / (std::string(results_lock) + ".stale-" + std::to_string(pid));
    fs::rename(lock, aside, ec);
    fs::remove(aside, ec);
  }
  return "cannot take the lock " + lock.string() + " (another run keeps taking it)";
}

// Removes the lock of `dir` if `pid` holds it.
inline void release_results(const std::string& dir, long pid) {
  const fs::path lock = fs::path(dir) / results_lock;
  if (lock_owner(lock) == pid) {
    std::error_code ec;
    fs::remove(lock, ec);
  }
}

// Whether the file `path` ends with `tail` (after trailing white space): a complete VTU file ends
// with </VTKFile>, one cut short by a full disk does not.
inline bool ends_with(const std::string& path, const std::string& tail) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return false;
  const std::streamoff size = in.tellg();
  const std::streamoff n = std::min<std::streamoff>(size, (std::streamoff)tail.size() + 64);
  std::string end((size_t)n, '\0');
  in.seekg(size - n);
  in.read(&end[0], n);
  if (!in) return false;
  while (!end.empty() && (end.back() == '\n' || end.back() == '\r' || end.back() == ' ' || end.back() == '\t'))
    end.pop_back();
  return end.size() >= tail.size() && end.compare(end.size() - tail.size(), tail.size(), tail) == 0;
}

// Cuts the file `path` to its first `length` bytes: a resumed run (edp/problems/sleeve/
// checkpoint.idp) drops the rows written after its last checkpoint. A file shorter than `length`
// is refused: the rows the checkpoint counts on are gone, it cannot be continued.
inline std::string truncate_file(const std::string& path, long long length) {
  if (length < 0) return "cannot cut " + path + " to " + std::to_string(length) + " bytes: a length is >= 0";
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return "cannot cut " + path + ": no such file";
  const auto size = fs::file_size(path, ec);
  if (ec) return "cannot cut " + path + ": " + reason(ec);
  if (size < (std::uintmax_t)length)
    return "cannot cut " + path + " to " + std::to_string(length) + " bytes: it holds only " + std::to_string(size);
  fs::resize_file(path, (std::uintmax_t)length, ec);
  if (ec) return "cannot cut " + path + " to " + std::to_string(length) + " bytes: " + reason(ec);
  return {};
}

// `text` quoted for a POSIX shell: one word whatever it holds ('it'\''s').
inline std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

}  // namespace sma::files
