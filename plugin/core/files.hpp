// Result files without a shell: directories, renames, removal by name pattern, and the claim of a
// results folder (refuse a folder this suite did not write, lock it against a concurrent run).
// Paths are passed to the system as they are: a quote, a space, a semicolon or any UTF-8 in a
// path is a character of the path, never shell syntax. Each function returns an empty string on
// success, else one sentence naming the path and the reason (the scripts turn it into `error:`).
#pragma once
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fnmatch.h>
#include <fstream>
#include <istream>
#include <iterator>
#include <sstream>
#include <string>
#include <sys/types.h>
#include <unistd.h>
#include <unordered_set>
#include <vector>

namespace sma::files {

namespace fs = std::filesystem;

// The manifest a run leaves in its results folder: the marker that the folder is this suite's
// and the list of every entry the suite wrote there. A later run replaces or removes only listed
// entries, and refuses a folder that holds anything unlisted, touching nothing (issue 26: names
// alone decided ownership, and a user's file named like an output was deleted). Its text:
//   sma-results manifest 1
//   scene <the scene that wrote the folder>
//   <a path relative to the folder>        one line per entry written (a file, frames/x.vtu)
//   <a folder name>/                       a results folder of its own inside (a sweep's run)
inline const char* results_marker = ".sma-results";
inline const char* manifest_header = "sma-results manifest 1";
inline const char* results_lock = ".sma-lock";
// A run's results replace the earlier run's only when it completes (publishes its record): a
// fresh claim moves a complete run's entries into previous-run/ (a results folder of its own, with
// the earlier manifest), and the run's completion (complete_results) removes it. A run that fails
// or is stopped therefore leaves its own partial files beside the last complete run's, whole
// (a re-run stopped by ^C, or refused late by its own physics, removed an hour's results).
// The mark of a complete run, and the staging name of a claim moving a run aside (+ its pid).
inline const char* results_complete = ".sma-complete";
inline const char* previous_run = "previous-run";
inline const char* previous_staging = ".sma-previous-";

inline std::string reason(const std::error_code& ec) { return ec.message(); }

// Creates `path` and its parents; fails when it exists as something other than a directory.
inline std::string make_directory(const std::string& path) {
  if (path.empty()) return "the empty string is not a directory name";
  std::error_code ec;
  fs::create_directories(path, ec);
  if (ec) {
    // A symbolic link to a missing target on the way says "File exists", a loop of links "Too many
    // levels of symbolic links": name the link instead.
    for (fs::path p = fs::path(path); !p.empty() && p != p.parent_path(); p = p.parent_path()) {
      std::error_code lec, sec;
      if (!fs::is_symlink(fs::symlink_status(p, lec))) continue;
      const std::string link = p.string() + " is a symbolic link to " + fs::read_symlink(p, lec).string();
      const fs::file_status target = fs::status(p, sec);
      if (sec == std::errc::too_many_symbolic_link_levels)
        return "cannot create the directory " + path + ": " + link + ", a loop of links that leads back to itself";
      if (target.type() == fs::file_type::not_found) return "cannot create the directory " + path + ": " + link + ", which does not exist";
    }
    return "cannot create the directory " + path + ": " + reason(ec);
  }
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
// The entries of `dir` (not below it) whose names match one of the space-separated shell patterns
// of `patterns` into `found`; "" or the reason. A pattern with a slash or equal to `.`/`..` is
// refused: it could reach outside `dir`.
inline std::string matching_entries(const std::string& dir, const std::string& patterns, std::vector<fs::path>& found) {
  const auto list = words(patterns);
  for (const auto& p : list)
    if (p.find('/') != std::string::npos || p == "." || p == "..")
      return "refusing to remove '" + p + "' in " + dir + ": a removal pattern names entries of the folder only";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return "cannot remove the earlier results in " + dir + ": not a directory";
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (std::any_of(list.begin(), list.end(),
                    [&](const std::string& p) { return fnmatch(p.c_str(), name.c_str(), FNM_PERIOD) == 0; }))
      found.push_back(it->path());
  }
  if (ec) return "cannot list " + dir + ": " + reason(ec);
  return {};
}

// Removes each of `doomed` (a directory whole).
inline std::string remove_entries(const std::vector<fs::path>& doomed) {
  std::error_code ec;
  for (const auto& path : doomed) {
    fs::remove_all(path, ec);
    if (ec) return "cannot remove " + path.string() + ": " + reason(ec);
  }
  return {};
}

// Removes the entries of `dir` (not below it) whose names match one of the space-separated shell
// patterns of `patterns` (fnmatch: `fields-*.csv`; a match that is a directory goes whole).
inline std::string remove_matching(const std::string& dir, const std::string& patterns) {
  std::vector<fs::path> doomed;
  if (auto e = matching_entries(dir, patterns, doomed); !e.empty()) return e;
  return remove_entries(doomed);
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
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(lock, ec))) return 0;  // a FIFO would block the read
  std::ifstream in(lock);
  long pid = 0;
  in >> pid;
  return in ? pid : 0;
}

struct Manifest {
  bool present = false;  // a marker exists
  bool legacy = false;   // a marker of a version before manifests (a scene name only)
  std::string scene;
  std::vector<std::string> entries;  // in the order written; repeats allowed
};

// Reads the manifest of the results folder `dir` into `m`; "" or the reason it cannot be read.
inline std::string read_manifest(const fs::path& dir, Manifest& m) {
  m = Manifest{};
  const fs::path file = dir / results_marker;
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(file, ec))) return {};
  m.present = true;
  if (!fs::is_regular_file(fs::symlink_status(file, ec)))
    return file.string() + " is not a file (a results folder's manifest is a text file)";
  std::ifstream in(file);
  std::string line;
  auto next = [&](std::string& text) {  // a line, without the \r of a file saved with CRLF
    if (!std::getline(in, text)) return false;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    return true;
  };
  if (!next(line)) {  // empty: an older marker, which lists nothing
    m.legacy = true;
    return {};
  }
  if (line != manifest_header) {
    m.legacy = true;
    m.scene = line;
    return {};
  }
  if (!next(line) || line.compare(0, 6, "scene ") != 0)
    return file.string() + " is damaged: its second line is not 'scene <name>'";
  m.scene = line.substr(6);
  for (int number = 3; next(line); ++number) {
    const fs::path entry(line);
    bool bad = line.empty() || entry.is_absolute();
    for (const auto& part : entry) bad = bad || part == ".." || part == ".";
    if (bad) return file.string() + " is damaged: line " + std::to_string(number) + " ('" + line +
                    "') is not a path inside the folder";
    m.entries.push_back(line);
  }
  return {};
}

// Whether `name` is `prefix` followed by a process id (a temporary name of one run's own).
inline bool with_pid(const std::string& name, const std::string& prefix) {
  return name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
         name.find_first_not_of("0123456789", prefix.size()) == std::string::npos;
}

// Whether `name` is the manifest, the lock, or one of their temporary names (the suite's own files;
// anything else of a similar name is a user's, and makes the folder refused like any other).
inline bool bookkeeping(const std::string& name) {
  return name == results_marker || name == results_lock || name == results_complete ||
         with_pid(name, std::string(results_lock) + ".stale-") || with_pid(name, std::string(results_lock) + ".new-") ||
         with_pid(name, std::string(results_marker) + ".partial-") || with_pid(name, previous_staging);
}

// Whether `dir` holds the suite's previous-run/: a folder (not a link) with a manifest. A user's
// folder of that name has none, and is refused as any unlisted entry.
inline bool holds_previous_run(const fs::path& dir) {
  std::error_code ec;
  const fs::path kept = dir / previous_run;
  return fs::is_directory(fs::symlink_status(kept, ec)) && fs::exists(fs::symlink_status(kept / results_marker, ec));
}

// Whether the file `rel` is listed, or is a listed file's unfinished copy (x.csv.partial,
// x.partial.vtu, x.partial.png: a run stopped while writing it).
inline bool covered(const std::vector<std::string>& listed, const std::string& rel) {
  auto has = [&](const std::string& name) { return std::find(listed.begin(), listed.end(), name) != listed.end(); };
  if (has(rel)) return true;
  const std::string partial = ".partial";
  if (rel.size() > partial.size() && rel.compare(rel.size() - partial.size(), partial.size(), partial) == 0)
    return has(rel.substr(0, rel.size() - partial.size()));
  const auto at = rel.rfind(partial + ".");
  if (at != std::string::npos && rel.find('/', at) == std::string::npos)
    return has(rel.substr(0, at) + rel.substr(at + partial.size()));
  return false;
}

// What a run of a version before manifests wrote in its folder (the names those versions' scenes
// and plot tools write; a match that is a folder counts whole): a folder whose marker is such a
// version's, of the same scene, is taken once if it holds nothing else, then gets a manifest.
inline const char* legacy_outputs =
    "summary.json history.csv points.csv contact-final.csv fields.pvd frames fields-* checkpoint.txt "
    "dc-convergence.csv ring-final.vtu beam-*.vtu pressure-*.csv phase-*.csv pointwise-check.csv "
    "force-temperature.png force-time.png displacement.png iterations.png temperature.png histogram.png "
    "phase-*.png dc-convergence.png *.partial *.partial.vtu *.partial.png seeds.csv failed.txt seed-* kernels.json";

inline bool legacy_output(const std::string& name) {
  std::istringstream patterns(legacy_outputs);
  for (std::string p; patterns >> p;)
    if (fnmatch(p.c_str(), name.c_str(), FNM_PERIOD) == 0) return true;
  return false;
}

inline std::string unlisted_in(const fs::path& root, const Manifest& m, const std::string& prefix, int depth);

// "" when every entry of the results folder `dir` is its manifest's (nested results folders
// checked by their own), else the reason naming the first entry that is not.
inline std::string foreign_entry(const fs::path& dir, int depth = 0) {
  if (depth > 16) return "results folders nested too deep at " + dir.string();
  Manifest m;
  if (auto e = read_manifest(dir, m); !e.empty()) return e;
  return unlisted_in(dir, m, "", depth);
}

inline std::string unlisted_in(const fs::path& root, const Manifest& m, const std::string& prefix, int depth) {
  std::error_code ec;
  const fs::path here = prefix.empty() ? root : root / prefix;
  auto why = [&](const std::string& rel) {
    if (!m.present)
      return "the output folder " + root.string() + " holds files this suite did not write (" + rel +
             "; it has no manifest " + results_marker + "): choose a new or empty folder with -out";
    if (m.legacy)
      return "the output folder " + root.string() + " was written by a version of this suite before " +
             "manifests and holds " + rel + ", which no run of it wrote: move it away or choose another -out; " +
             "nothing was touched";
    return "the output folder " + root.string() + " holds " + rel + ", which this suite did not write " +
           "there (it is not in the folder's manifest " + results_marker + "): move it away or choose " +
           "another -out; nothing was touched";
  };
  for (fs::directory_iterator it(here, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (prefix.empty() && bookkeeping(name)) continue;
    if (prefix.empty() && name == previous_run && holds_previous_run(root)) {
      if (auto e = foreign_entry(it->path(), depth + 1); !e.empty()) return e;
      continue;
    }
    const std::string rel = prefix + name;
    const auto type = it->symlink_status(ec).type();
    // The suite writes no link: one here would make a write or a cut land outside the folder.
    if (type == fs::file_type::symlink) return why(rel + " (a symbolic link)");
    if (m.legacy) {
      if (!legacy_output(name)) return why(rel);
      continue;
    }
    if (type == fs::file_type::directory) {
      // A listed folder (`name/`), or one that listed files lie in (frames/x.vtu): a results
      // folder of its own inside is checked against its own manifest, any other by the listing.
      const bool listed = std::any_of(m.entries.begin(), m.entries.end(), [&](const std::string& e) {
        return e.compare(0, rel.size() + 1, rel + "/") == 0;
      });
      if (!listed) return why(rel + "/");
      if (fs::exists(it->path() / results_marker, ec)) {
        if (auto e = foreign_entry(it->path(), depth + 1); !e.empty()) return e;
      } else if (auto e = unlisted_in(root, m, rel + "/", depth); !e.empty()) {
        return e;
      }
      continue;
    }
    if (!covered(m.entries, rel)) return why(rel);
  }
  if (ec) return "cannot list " + here.string() + ": " + reason(ec);
  return {};
}

// Writes a fresh manifest (header and scene) for `scene` in `dir`, under a temporary name.
inline std::string write_manifest(const fs::path& dir, const std::string& scene, long pid) {
  const fs::path file = dir / results_marker,
                 partial = dir / (std::string(results_marker) + ".partial-" + std::to_string(pid));
  {
    std::ofstream out(partial, std::ios::trunc);
    out << manifest_header << "\n" << "scene " << scene << "\n";
    out.flush();
    if (!out) return "cannot write " + file.string() + " (disk full?)";
  }
  std::error_code ec;
  fs::rename(partial, file, ec);
  if (ec) return "cannot write " + file.string() + ": " + reason(ec);
  return {};
}

// Adds the line `entry` to the manifest of `dir` (one write with O_APPEND: lines appended by
// several processes at once do not mix).
inline std::string append_manifest(const fs::path& dir, const std::string& entry) {
  const fs::path file = dir / results_marker;
  if (entry.find_first_of("\n\r") != std::string::npos)
    return "cannot list '" + entry + "' in " + file.string() + ": a name with a line break (the manifest has a "
           "name per line): choose a name without one";
  const int fd = open(file.c_str(), O_WRONLY | O_APPEND);
  if (fd < 0) return "cannot add " + entry + " to " + file.string() + ": " + std::strerror(errno);
  const std::string line = entry + "\n";
  const bool written = write(fd, line.data(), line.size()) == (ssize_t)line.size();
  close(fd);
  if (!written) return "cannot add " + entry + " to " + file.string() + " (disk full?)";
  return {};
}

// The nearest folder holding a manifest among those of `path` (its own folder, then each parent),
// and the path relative to it; false when none does.
inline bool manifest_of(const std::string& path, fs::path& dir, std::string& rel) {
  std::error_code ec;
  fs::path full = fs::absolute(fs::path(path), ec).lexically_normal();
  if (ec) return false;
  fs::path rest = full.filename();
  for (fs::path d = full.parent_path(); !d.empty(); d = d.parent_path()) {
    if (fs::exists(d / results_marker, ec)) {
      dir = d;
      rel = rest.string();
      return true;
    }
    if (d == d.parent_path()) break;
    rest = d.filename() / rest;
  }
  return false;
}

// What one process has recorded: the manifest entries it has read or written (as "dir/entry")
// and the folders whose manifest it has read. A manifest is read once per process, so recording
// a run's thousandth frame costs what its first did (reading it at every new name, a path parsed
// per line, grew as the square of the frames).
struct RecordedResults {
  std::unordered_set<std::string> entries, folders_read;
  void clear() { entries.clear(), folders_read.clear(); }
};

// "" when the file `path` can be written where it is: its folder exists and takes new files; else
// why not, naming both. A folder removed or made read-only while a run writes into it made
// FreeFEM's own open fail, "Exec error : Error opening file", exit 8, which names no cause.
inline std::string unwritable_folder(const std::string& path) {
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  const auto kind = fs::status(dir, ec).type();
  if (kind == fs::file_type::not_found)
    return "cannot write " + path + ": its folder " + dir.string() + " is missing (removed while the run wrote "
           "into it?)";
  if (!ec && kind != fs::file_type::directory) return "cannot write " + path + ": " + dir.string() + " is not a folder";
  if (access(dir.c_str(), W_OK | X_OK) != 0)
    return "cannot write " + path + ": its folder " + dir.string() + " takes no new file (" + std::strerror(errno) +
           ": made read-only while the run wrote into it?)";
  return {};
}

// Records that the suite writes `path`: its name goes into the manifest of the nearest results
// folder above it (nothing when there is none: a verification record, a documentation figure).
// Another process's additions since this one read the manifest may be listed a second time,
// which a reader ignores (repeats are allowed). A file whose folder cannot take it is refused
// (unwritable_folder): the caller is about to write it.
inline std::string record_result(const std::string& path, RecordedResults& known) {
  std::string file = path;
  bool folder = false;  // a path ending in '/' is a folder, listed as `name/`
  while (file.size() > 1 && file.back() == '/') {
    file.pop_back();
    folder = true;
  }
  if (!folder)
    if (auto e = unwritable_folder(file); !e.empty()) return e;
  fs::path dir;
  std::string rel;
  if (!manifest_of(file, dir, rel)) return {};
  if (folder) rel += "/";
  const std::string key = (dir / rel).string();
  if (known.entries.count(key)) return {};
  if (!known.folders_read.count(dir.string())) {
    Manifest m;
    if (auto e = read_manifest(dir, m); !e.empty()) return e;
    if (m.legacy) return {};  // an older marker: the next claim refuses the folder anyway
    for (const std::string& entry : m.entries) known.entries.insert((dir / entry).string());
    known.folders_read.insert(dir.string());
    if (known.entries.count(key)) return {};
  }
  if (auto e = append_manifest(dir, rel); !e.empty()) return e;
  known.entries.insert(key);
  return {};
}

// "" unless `path` is, or holds, a results folder that a live run other than `pid` is writing
// (a sweep's run still going): then the reason, naming it.
inline std::string busy_inside(const fs::path& path, long pid, int depth = 0) {
  std::error_code ec;
  if (depth > 16 || !fs::is_directory(fs::symlink_status(path, ec))) return {};
  const long owner = lock_owner(path / results_lock);
  if (owner != 0 && owner != pid && process_alive(owner))
    return "the results folder " + path.string() + " is in use by another run (process " + std::to_string(owner) +
           "): wait for it or choose another -out";
  for (fs::directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec))
    if (auto e = busy_inside(it->path(), pid, depth + 1); !e.empty()) return e;
  return {};
}

// Claims the results folder `dir` for a run of `scene` by the process `pid`:
//  - a folder that holds anything its manifest does not list (or any entry and no manifest) is
//    someone else's: refused, nothing in it touched;
//  - a live run's lock in it: refused (two runs would mix their files);
//  - else the lock is taken (a dead process's lock is replaced). A fresh run (resume false) then
//    removes every entry the manifest lists, whichever scene wrote them, and starts a manifest of
//    its own, but for the runs of their own inside it, kept and listed again unless it owns them
//    (owns_nested_runs: a sweep, an ensemble); a resumed run must find its own scene's manifest
//    and removes only the listed entries matching the shell patterns of `patterns` (what its
//    remaining steps rewrite);
//  - a folder inside another results folder is listed in that one's manifest as `name/`.
// The caller removes the lock with release_results when the run ends, however it ends.
inline std::string claim_locked(const fs::path& d, const std::string& dir, const std::string& scene, long pid,
                                bool resume, const std::string& patterns);
inline void release_results(const std::string& dir, long pid);

inline std::string claim_results(const std::string& dir, const std::string& scene, long pid, bool resume = false,
                                 const std::string& patterns = "") {
  std::error_code ec;
  // "a/sub/.." goes down into sub and back: the scripts write through the name as given, so sub
  // would have to exist; the folder is asked for as itself (a leading ../ is fine).
  bool down = false;
  for (const auto& part : fs::path(dir)) {
    if (part == "..") {
      if (down) return "-out " + dir + " goes into a folder and back out ('..' after a name): give the folder "
                       "itself, " + fs::path(dir).lexically_normal().string();
    } else if (part != "." && !part.empty()) {
      down = true;
    }
  }
  const fs::path d = fs::path(dir).lexically_normal();
  if (d.empty()) return "the empty string is not a directory name";
  // Listed in the manifest of a results folder around this one (a sweep's run, an ensemble's
  // seed) before it is made: a claim refused below leaves nothing unlisted in the outer folder.
  if (!resume) {
    const fs::path full = fs::absolute(d, ec).lexically_normal();
    const fs::path self = full.filename().empty() ? full.parent_path() : full;
    Manifest outer;
    if (!ec && !self.filename().empty() && read_manifest(self.parent_path(), outer).empty() && outer.present &&
        !outer.legacy && std::find(outer.entries.begin(), outer.entries.end(), self.filename().string() + "/") ==
                             outer.entries.end())
      if (auto e = append_manifest(self.parent_path(), self.filename().string() + "/"); !e.empty()) return e;
  }
  if (auto e = make_directory(d.string()); !e.empty()) return e;
  Manifest m;
  if (auto e = read_manifest(d, m); !e.empty()) return e;
  if (m.legacy && m.scene != scene)
    return "the output folder " + dir + " holds a marker " + results_marker + " of a version before manifests " +
           (m.scene.empty() ? std::string("that names no scene") : "of another scene (" + m.scene + ")") +
           ": it cannot tell this suite's files from yours there; choose another -out, or remove the folder "
           "yourself if it holds nothing of yours";
  if (auto e = foreign_entry(d); !e.empty()) return e;
  if (resume && (!m.present || m.legacy || m.scene != scene))
    return "cannot resume " + scene + " in " + dir + ": the folder holds " +
           (m.present && !m.legacy ? "a run of " + m.scene : std::string("no run of this version of the suite"));
  const fs::path lock = d / results_lock;
  bool taken = false;
  // The lock appears whole, its process id in it: written under a name of our own, then linked to
  // the lock's name (link fails if the name exists: the O_EXCL of a file with its content). Created
  // empty and then written, a second run that read it in between saw no owner, judged it stale,
  // moved it aside and took the folder too (6 of 20 pairs started together: one failed renaming a
  // file the other had moved, the other on a FreeFEM assertion).
  const fs::path mine = d / (std::string(results_lock) + ".new-" + std::to_string(pid));
  {
    const int fd = open(mine.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) return "cannot create the lock " + mine.string() + ": " + std::strerror(errno);
    const std::string text = std::to_string(pid) + "\n";
    const bool written = write(fd, text.data(), text.size()) == (ssize_t)text.size();
    close(fd);
    if (!written) {
      fs::remove(mine, ec);
      return "cannot write the lock " + mine.string() + " (disk full?)";
    }
  }
  // (the loop in a function of its own: whatever it returns, the name of our own goes once after)
  const std::string refused = [&]() -> std::string {
    for (int attempt = 0; attempt < 2 && !taken; ++attempt) {
      if (link(mine.c_str(), lock.c_str()) == 0) {
        taken = true;
        break;
      }
      if (errno != EEXIST) return "cannot create the lock " + lock.string() + ": " + std::strerror(errno);
      if (!fs::is_regular_file(fs::symlink_status(lock, ec)))
        return "the lock " + lock.string() + " is not a file (the suite writes a file there): remove it";
      const long owner = lock_owner(lock);
      if (owner == pid) {
        taken = true;
        break;
      }
      if (process_alive(owner))
        return "the output folder " + dir + " is in use by another run (process " + std::to_string(owner) +
               ", lock " + lock.string() + "): wait for it or choose another -out (if no run of this suite is "
               "going on, the lock is stale: remove it)";
      // A dead run's lock: move it aside under a name of our own, so that of two runs that find
      // the same stale lock only one takes the folder (the link above decides).
      const fs::path aside = d / (std::string(results_lock) + ".stale-" + std::to_string(pid));
      fs::rename(lock, aside, ec);
      // (between the read and the move another run may have taken the folder: its lock is put back)
      const long moved = ec ? 0 : lock_owner(aside);
      if (moved != 0 && moved != owner && process_alive(moved)) {
        const bool back = link(aside.c_str(), lock.c_str()) == 0;
        fs::remove(aside, ec);
        return "the output folder " + dir + " is in use by another run (process " + std::to_string(moved) + ", lock " +
               lock.string() + (back ? "" : ", which a third run took meanwhile") + "): wait for it or choose another -out";
      }
      fs::remove(aside, ec);
    }
    return "";
  }();
  fs::remove(mine, ec);
  if (!refused.empty()) return refused;
  if (!taken) return "cannot take the lock " + lock.string() + " (another run keeps taking it)";
  // A claim that fails from here gives the folder back as it found it: its lock and its unfinished
  // manifest go (a disk full while writing it left both, and every later run was refused).
  std::string error = claim_locked(d, dir, scene, pid, resume, patterns);
  if (!error.empty()) {
    fs::remove(d / (std::string(results_marker) + ".partial-" + std::to_string(pid)), ec);
    release_results(d.string(), pid);
  }
  return error;
}

// Whether a run of `scene` makes the results folders inside its own (a sweep's runs, "sweep
// <scene>"; an ensemble's seeds, "<name>-ensemble"): its fresh claim removes them with its other
// entries. Any other run's folder may hold a run of its own that someone put there (-out
// results/x/sub): the folder's next run keeps it, listed again (it removed a finished run).
inline bool owns_nested_runs(const std::string& scene) {
  const std::string ensemble = "-ensemble";
  return scene.compare(0, 6, "sweep ") == 0 ||
         (scene.size() > ensemble.size() && scene.compare(scene.size() - ensemble.size(), ensemble.size(), ensemble) == 0);
}

// A fresh claim's treatment of the earlier run's entries `doomed` (under the lock): a complete
// run's (its mark present) go into previous-run/ with a copy of its manifest, replacing an older
// previous-run/; an incomplete run's are removed, and previous-run/, the last complete run's,
// stays. The move goes through a staging folder of this process's: a claim killed while moving
// leaves one, which the next claim takes over and completes (the earlier run's mark is removed
// only after the move, so the next claim still sees a complete run).
inline std::string set_aside_earlier_run(const fs::path& d, long pid, const std::vector<fs::path>& doomed) {
  std::error_code ec;
  const fs::path staging = d / (std::string(previous_staging) + std::to_string(pid));
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(d, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (with_pid(name, previous_staging) && it->path() != staging &&
        !process_alive(std::atol(name.c_str() + std::strlen(previous_staging))))
      stale.push_back(it->path());
  }
  if (ec) return "cannot list " + d.string() + ": " + reason(ec);
  bool adopted = false;
  for (const auto& path : stale) {
    if (adopted || fs::exists(staging, ec)) {  // (two killed claims: the first one's is kept)
      fs::remove_all(path, ec);
    } else {
      fs::rename(path, staging, ec);
      adopted = !ec;
    }
    if (ec) return "cannot take over " + path.string() + " (a killed run's earlier results): " + reason(ec);
  }
  const bool complete = adopted || fs::exists(d / results_complete, ec);
  if (!complete) return remove_entries(doomed);
  if (doomed.empty() && !adopted) return {};  // nothing to keep: an older previous-run/ stays
  if (!fs::exists(staging, ec)) {
    fs::create_directory(staging, ec);
    if (ec) return "cannot create " + staging.string() + ": " + reason(ec);
  }
  if (!fs::exists(staging / results_marker, ec)) {
    fs::copy_file(d / results_marker, staging / results_marker, ec);
    if (ec) return "cannot copy the manifest into " + staging.string() + ": " + reason(ec);
  }
  for (const auto& path : doomed) {
    fs::rename(path, staging / path.filename(), ec);
    if (ec) return "cannot move " + path.string() + " into " + staging.string() + ": " + reason(ec);
  }
  fs::remove_all(d / previous_run, ec);
  if (!ec) fs::rename(staging, d / previous_run, ec);
  if (ec) return "cannot keep the earlier run in " + (d / previous_run).string() + ": " + reason(ec);
  return {};
}

// The part of claim_results done under the folder's lock.
inline std::string claim_locked(const fs::path& d, const std::string& dir, const std::string& scene, long pid,
                                bool resume, const std::string& patterns) {
  std::error_code ec;
  Manifest m;
  // Under the lock: the folder as it is now (a run that held it may have added entries).
  if (auto e = foreign_entry(d); !e.empty()) return e;
  if (auto e = read_manifest(d, m); !e.empty()) return e;
  // The existing entries, all the manifest's (listed, or a listed file's unfinished copy:
  // foreign_entry found no other): every one for a fresh run, those matching `patterns` for a
  // resumed one.
  std::vector<fs::path> doomed;
  std::vector<std::string> kept_runs;  // results folders inside, runs of their own (owns_nested_runs)
  if (resume) {
    if (auto e = matching_entries(d.string(), patterns, doomed); !e.empty()) return e;
  } else {
    for (fs::directory_iterator it(d, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (bookkeeping(name) || (name == previous_run && holds_previous_run(d))) continue;
      std::error_code nested;
      if (!owns_nested_runs(scene) && fs::is_directory(fs::symlink_status(it->path(), nested)) &&
          fs::exists(it->path() / results_marker, nested))
        kept_runs.push_back(name + "/");
      else
        doomed.push_back(it->path());
    }
    if (ec) return "cannot list " + dir + ": " + reason(ec);
  }
  for (const auto& path : doomed)
    if (auto e = busy_inside(path, pid); !e.empty()) return e;
  if (auto e = resume ? remove_entries(doomed) : set_aside_earlier_run(d, pid, doomed); !e.empty()) return e;
  // The folder is being written again: not complete until this run says so.
  fs::remove(d / results_complete, ec);
  if (ec) return "cannot remove " + (d / results_complete).string() + ": " + reason(ec);
  // The suite's own temporaries that a killed run left (its unfinished manifest, the stale lock it
  // was moving aside), fresh or resumed alike: their process no longer runs.
  for (const std::string& prefix : {std::string(results_marker) + ".partial-", std::string(results_lock) + ".stale-",
                                    std::string(results_lock) + ".new-"})
    for (fs::directory_iterator it(d, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (with_pid(name, prefix)) {
        const long owner = std::atol(name.c_str() + prefix.size());
        if (owner != pid && !process_alive(owner)) fs::remove(it->path(), ec);
      }
    }
  if (!resume) {
    if (auto e = write_manifest(d, scene, pid); !e.empty()) return e;
    for (const std::string& run : kept_runs)
      if (auto e = append_manifest(d, run); !e.empty()) return e;
  }
  return {};
}

// Marks the run of `pid` in `dir` complete (it published its record): the mark is written, then
// the earlier complete run kept in previous-run/ is removed. "" or the reason.
inline std::string complete_results(const std::string& dir, long pid) {
  const fs::path d(dir);
  if (lock_owner(d / results_lock) != pid)
    return "cannot mark the run in " + dir + " complete: this process does not hold the folder";
  const fs::path mark = d / results_complete;
  const int fd = open(mark.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return "cannot write " + mark.string() + ": " + std::strerror(errno);
  close(fd);
  std::error_code ec;
  if (holds_previous_run(d)) fs::remove_all(d / previous_run, ec);
  if (ec) return "cannot remove the earlier run " + (d / previous_run).string() + ": " + reason(ec);
  return {};
}

// Whether `path` is the record (summary.json) of the results folder `dir`: publishing it
// completes the run (complete_results).
inline bool is_record_of(const std::string& path, const std::string& dir) {
  if (fs::path(path).filename() != "summary.json") return false;  // (every published file asks: no paths made)
  std::error_code ec;
  const fs::path file = fs::absolute(path, ec).lexically_normal();
  fs::path folder = fs::absolute(dir, ec).lexically_normal();
  if (folder.filename().empty()) folder = folder.parent_path();  // "out/"
  return !ec && file.filename() == "summary.json" && file.parent_path() == folder;
}

// The line a run that did not complete leaves at its exit when previous-run/ keeps the earlier
// complete run ("" otherwise: the run completed, or there was none to keep).
inline std::string incomplete_run_note(const std::string& dir, long pid) {
  std::error_code ec;
  const fs::path d(dir);
  if (lock_owner(d / results_lock) != pid || fs::exists(d / results_complete, ec) || !holds_previous_run(d))
    return {};
  return "note: this run did not complete: " + dir + " holds its partial results, and the last complete run's "
         "are kept whole in " + (d / previous_run).string() + " (removed when a run of the folder completes)";
}

// Removes the lock of `dir` if `pid` holds it.
inline void release_results(const std::string& dir, long pid) {
  const fs::path lock = fs::path(dir) / results_lock;
  if (lock_owner(lock) == pid) {
    std::error_code ec;
    fs::remove(lock, ec);
  }
}

// Removes pid's lock of `dir` (release_results) and returns the line an incomplete run then
// leaves (incomplete_run_note, read before the lock goes): the one way a run ends, whether the
// scene's process exits (the plugin's exit handler) or sma-results releases it for a launcher.
inline std::string release_results_noted(const std::string& dir, long pid) {
  std::string note = incomplete_run_note(dir, pid);
  release_results(dir, pid);
  return note;
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
  if (fs::is_symlink(path, ec)) return "cannot cut " + path + ": it is a symbolic link (the suite writes none)";
  // A file with another name elsewhere (a hard link) would be cut and continued there too.
  if (fs::hard_link_count(path, ec) > 1)
    return "cannot cut " + path + ": it has another name (a hard link): the suite's files have one; copy it instead";
  if (!fs::is_regular_file(path, ec)) return "cannot cut " + path + ": no such file";
  const auto size = fs::file_size(path, ec);
  if (ec) return "cannot cut " + path + ": " + reason(ec);
  if (size < (std::uintmax_t)length)
    return "cannot cut " + path + " to " + std::to_string(length) + " bytes: it holds only " + std::to_string(size);
  fs::resize_file(path, (std::uintmax_t)length, ec);
  if (ec) return "cannot cut " + path + " to " + std::to_string(length) + " bytes: " + reason(ec);
  return {};
}

// The FNV-1a 64-bit hash of the first `length` bytes of the file `path` (all of it when length < 0),
// as 16 hex digits; "" when the file cannot be read or is shorter. Not a cryptographic seal: it
// names an accidental or careless change (an edited number, a file cut or continued), which is
// what a checkpoint's reader must not take for the run's state.
struct Fnv1a {
  std::uint64_t h = 14695981039346656037ULL;
  void add(const char* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      h ^= (unsigned char)data[i];
      h *= 1099511628211ULL;
    }
  }
  std::string hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", (unsigned long long)h);
    return text;
  }
};

inline std::string checksum(const std::string& path, long long length = -1) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  Fnv1a sum;
  char buffer[1 << 16];
  long long left = length;
  while (length < 0 || left > 0) {
    const std::streamsize want = length < 0 ? (std::streamsize)sizeof buffer
                                            : (std::streamsize)std::min<long long>(left, sizeof buffer);
    in.read(buffer, want);
    const std::streamsize got = in.gcount();
    sum.add(buffer, (std::size_t)got);
    left -= got;
    if (got < want) break;
  }
  if (length >= 0 && left > 0) return {};
  return sum.hex();
}

inline const char* seal_word = "checksum ";

// Appends the line "checksum <hex>" of the file's content so far (a checkpoint, once written).
inline std::string seal(const std::string& path) {
  const std::string sum = checksum(path);
  if (sum.empty()) return "cannot read " + path + " to seal it";
  std::ofstream out(path, std::ios::binary | std::ios::app);
  out << seal_word << sum << "\n";
  out.flush();
  if (!out) return "cannot write " + path + " (disk full?)";
  return {};
}

// "" when the file's last line is "checksum <hex>" of everything before it, else the reason: the
// file was changed, cut or continued after it was sealed.
inline std::string seal_error(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot be read";
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.empty() || text.back() != '\n') return "has no checksum line at its end (cut short, or written by another version)";
  const auto start = text.rfind('\n', text.size() - 2);
  const std::size_t line = start == std::string::npos ? 0 : start + 1;
  const std::string last = text.substr(line, text.size() - 1 - line);
  if (last.compare(0, std::strlen(seal_word), seal_word) != 0)
    return "has no checksum line at its end (cut short, or written by another version)";
  Fnv1a content;
  content.add(text.data(), line);
  const std::string sum = content.hex();
  if (last.substr(std::strlen(seal_word)) != sum)
    return "was changed after it was written (its content's checksum is " + sum + ", its last line says " +
           last.substr(std::strlen(seal_word)) + ")";
  return {};
}

// Whether `word` is a whole decimal number, [+-]digits[.digits][(e|E)[+-]digits] with a digit
// before the exponent, or [+-]digits when `integer` (edp/lib/errors.idp IsNumberWord, the same
// rule): strtod alone would read "abc" as 0, "5x" as 5, and accept "nan", "inf", hex.
inline bool number_word(const std::string& word, bool integer) {
  std::size_t i = 0, digits = 0;
  const std::size_t n = word.size();
  auto digit = [&](std::size_t k) { return k < n && word[k] >= '0' && word[k] <= '9'; };
  if (i < n && (word[i] == '+' || word[i] == '-')) ++i;
  for (; digit(i); ++i) ++digits;
  if (!integer && i < n && word[i] == '.')
    for (++i; digit(i); ++i) ++digits;
  if (digits == 0) return false;
  if (!integer && i < n && (word[i] == 'e' || word[i] == 'E')) {
    ++i;
    if (i < n && (word[i] == '+' || word[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    for (; digit(i); ++i) ++exponent_digits;
    if (exponent_digits == 0) return false;
  }
  return i == n;
}

// Reads the `n` values of the array `name` of a checkpoint (edp/problems/sleeve/checkpoint.idp:
// one white-space separated word each) from `in` into `values`: each a whole number word
// (number_word; an integer one when `integer`) and finite. "" or the reason naming the first bad
// value: "name[i] is 'word', not a number", "name[i] 'word' overflows a double", "it ends at name[i]".
// A loop over the words in the script cost about 70 us a value (2.6 s for the 39 000 values of
// an 18-layer sleeve's checkpoint); here it is the stream's own word reads and strtod.
inline std::string read_numbers(std::istream& in, double* values, std::size_t n, bool integer,
                                const std::string& name) {
  std::string word;
  for (std::size_t i = 0; i < n; ++i) {
    auto what = [&] { return name + "[" + std::to_string(i) + "]"; };  // (built for a message only)
    if (!(in >> word)) return "it ends at " + what();
    if (!number_word(word, integer))
      return what() + " is '" + word + "', not " + (integer ? "an integer" : "a number");
    const double value = std::strtod(word.c_str(), nullptr);
    if (!(std::fabs(value) <= 1.7976931348623157e308)) return what() + " '" + word + "' overflows a double";
    values[i] = value;
  }
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
