// Result files without a shell (plugin/core/files.hpp): names with shell syntax stay names,
// removal stays inside the folder, a foreign folder is refused, a live run's lock is respected
// and a dead run's lock is taken.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "core/files.hpp"

namespace fs = std::filesystem;
namespace files = sma::files;

namespace {

struct Scratch {
  fs::path dir;
  Scratch() {
    char name[] = "/tmp/sma-files-XXXXXX";
    dir = mkdtemp(name);
  }
  ~Scratch() { fs::remove_all(dir); }
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
};

void touch(const std::string& path, const std::string& text = "x") { std::ofstream(path) << text; }

}  // namespace

TEST(Files, NamesWithShellSyntaxAreJustNames) {
  Scratch t;
  const std::string dir = t / "it's a \"dir\"; touch pwned $(id) r\xc3\xa9sultats";
  ASSERT_EQ(files::make_directory(dir + "/frames"), "");
  EXPECT_EQ(files::kind(dir), 2);
  touch(dir + "/a.partial");
  ASSERT_EQ(files::rename_file(dir + "/a.partial", dir + "/a"), "");
  EXPECT_EQ(files::kind(dir + "/a"), 1);
  EXPECT_EQ(files::kind(dir + "/a.partial"), 0);
  EXPECT_FALSE(fs::exists(t / "pwned"));
  EXPECT_FALSE(fs::exists("pwned"));
}

TEST(Files, ErrorsNameThePath) {
  Scratch t;
  touch(t / "file");
  const std::string error = files::make_directory(t / "file");
  EXPECT_NE(error.find(t / "file"), std::string::npos) << error;
  EXPECT_NE(files::rename_file(t / "missing", t / "x").find(t / "x"), std::string::npos);
  // A link to a missing target, as the folder or on its way: the link and its target are named
  // (the system's message was "File exists").
  fs::create_symlink(t / "gone", t / "dangling");
  for (const std::string& dir : {t / "dangling", t / "dangling" + "/sub"}) {
    const std::string e = files::make_directory(dir);
    EXPECT_NE(e.find(t / "dangling" + " is a symbolic link to " + t / "gone" + ", which does not exist"),
              std::string::npos) << e;
  }
  EXPECT_FALSE(fs::exists(t / "gone"));
  // A loop of links is named as one (it was called a link to a missing target).
  fs::create_symlink(t / "loop-b", t / "loop-a");
  fs::create_symlink(t / "loop-a", t / "loop-b");
  for (const std::string& dir : {t / "loop-a", t / "loop-a" + "/sub"}) {
    const std::string e = files::make_directory(dir);
    EXPECT_NE(e.find(t / "loop-a" + " is a symbolic link to " + t / "loop-b" + ", a loop of links"), std::string::npos) << e;
  }
}

TEST(Files, RemoveMatchingStaysInsideTheFolder) {
  Scratch t;
  const std::string d = t / "out";
  fs::create_directories(d + "/frames");
  touch(d + "/frames/step-1.vtu");
  touch(d + "/fields-1.csv");
  touch(d + "/fields-2.csv");
  touch(d + "/keep.txt");
  touch(d + "/.hidden.csv");
  touch(t / "sibling.csv");
  ASSERT_EQ(files::remove_matching(d, "frames fields-*.csv *.partial"), "");
  EXPECT_FALSE(fs::exists(d + "/frames"));
  EXPECT_FALSE(fs::exists(d + "/fields-1.csv"));
  EXPECT_TRUE(fs::exists(d + "/keep.txt"));
  EXPECT_TRUE(fs::exists(d + "/.hidden.csv"));  // a pattern's * does not match a leading dot
  EXPECT_NE(files::remove_matching(d, "../sibling.csv"), "");
  EXPECT_NE(files::remove_matching(d, ".."), "");
  EXPECT_TRUE(fs::exists(t / "sibling.csv"));
}

TEST(Files, ClaimRefusesAFolderThisSuiteDidNotWrite) {
  Scratch t;
  const std::string d = t / "papers";
  fs::create_directories(d + "/frames");
  touch(d + "/frames/my-own.vtu");
  const std::string error = files::claim_results(d, "beam", getpid());
  EXPECT_NE(error.find("did not write"), std::string::npos) << error;
  EXPECT_TRUE(fs::exists(d + "/frames/my-own.vtu"));
  EXPECT_FALSE(fs::exists(d + "/" + files::results_lock));
  // Output names without a manifest are not ours either (a summary.json made the folder ours).
  fs::create_directories(t / "named");
  touch(t / "named/summary.json", "mine");
  EXPECT_NE(files::claim_results(t / "named", "beam", getpid()), "");
  EXPECT_TRUE(fs::exists(t / "named/summary.json"));
  // New, empty, or listed by an earlier run: taken.
  EXPECT_EQ(files::claim_results(t / "new", "beam", getpid()), "");
  EXPECT_TRUE(fs::exists(t / "new/.sma-results"));
  files::release_results(t / "new", getpid());
  EXPECT_FALSE(fs::exists(t / "new/.sma-lock"));
  EXPECT_EQ(files::claim_results(t / "new", "beam", getpid()), "");
}

// The manifest decides: a listed file (or its unfinished copy) is replaced, an unlisted one makes
// the whole folder refused untouched, another scene's listed files go as a whole.
TEST(Files, OnlyTheManifestsEntriesAreReplaced) {
  Scratch t;
  const std::string d = t / "out";
  files::RecordedResults known;
  ASSERT_EQ(files::claim_results(d, "sleeve-circular", getpid()), "");
  fs::create_directories(d + "/frames");
  for (const std::string name : {"summary.json", "fields-1.csv", "frames/step-1.vtu", "frames/"})
    ASSERT_EQ(files::record_result(d + "/" + name, known), "");
  touch(d + "/summary.json");
  touch(d + "/fields-1.csv");
  touch(d + "/frames/step-1.vtu");
  touch(d + "/fields-1.csv.partial");       // a listed file's unfinished copies
  touch(d + "/frames/step-1.partial.vtu");
  files::release_results(d, getpid());
  // A user's file named like an output: refused, nothing touched.
  touch(d + "/fields-2.csv", "mine");
  std::string error = files::claim_results(d, "sleeve-circular", getpid());
  EXPECT_NE(error.find("fields-2.csv"), std::string::npos) << error;
  EXPECT_TRUE(fs::exists(d + "/summary.json"));
  EXPECT_FALSE(fs::exists(d + "/.sma-lock"));
  fs::remove(d + "/fields-2.csv");
  // A user's file in a listed folder: refused too.
  touch(d + "/frames/notes.txt", "mine");
  error = files::claim_results(d, "sleeve-circular", getpid());
  EXPECT_NE(error.find("frames/notes.txt"), std::string::npos) << error;
  fs::remove(d + "/frames/notes.txt");
  // A resumed run of another scene: refused.
  EXPECT_NE(files::claim_results(d, "sleeve-radial", getpid(), true, "summary.json"), "");
  files::release_results(d, getpid());
  // Resumed, its own scene: only the listed entries matching the patterns go.
  ASSERT_EQ(files::claim_results(d, "sleeve-circular", getpid(), true, "summary.json *.partial"), "");
  EXPECT_FALSE(fs::exists(d + "/summary.json"));
  EXPECT_FALSE(fs::exists(d + "/fields-1.csv.partial"));
  EXPECT_TRUE(fs::exists(d + "/fields-1.csv"));
  files::release_results(d, getpid());
  // Another scene, fresh: every listed entry goes, the manifest starts again.
  ASSERT_EQ(files::claim_results(d, "sleeve-radial", getpid()), "");
  EXPECT_FALSE(fs::exists(d + "/fields-1.csv"));
  EXPECT_FALSE(fs::exists(d + "/frames"));
  files::Manifest m;
  ASSERT_EQ(files::read_manifest(d, m), "");
  EXPECT_EQ(m.scene, "sleeve-radial");
  EXPECT_TRUE(m.entries.empty());
  files::release_results(d, getpid());
}

// A folder of a version before manifests (its marker a scene name): taken once when it holds only
// what such versions wrote, refused untouched when it holds anything else.
TEST(Files, AFolderOfAnOlderVersionIsTakenOnlyWithItsOwnOutputs) {
  Scratch t;
  const std::string d = t / "old";
  fs::create_directories(d + "/frames");
  touch(d + "/.sma-results", "sleeve-circular\n");
  touch(d + "/summary.json");
  touch(d + "/frames/step-000050.vtu");
  touch(d + "/notes.txt", "mine");
  EXPECT_NE(files::claim_results(d, "sleeve-circular", getpid()).find("notes.txt"), std::string::npos);
  EXPECT_TRUE(fs::exists(d + "/summary.json"));
  EXPECT_NE(files::claim_results(d, "sleeve-circular", getpid(), true, "summary.json"), "");  // no resume
  fs::remove(d + "/notes.txt");
  ASSERT_EQ(files::claim_results(d, "sleeve-circular", getpid()), "");
  EXPECT_FALSE(fs::exists(d + "/summary.json"));
  EXPECT_FALSE(fs::exists(d + "/frames"));
  files::Manifest m;
  ASSERT_EQ(files::read_manifest(d, m), "");
  EXPECT_FALSE(m.legacy);
  files::release_results(d, getpid());
}

// A run put inside another scene's folder (-out results/x/sub) is a run of its own: the folder's
// next run keeps it and lists it again (it removed it with its own files); a sweep's or an
// ensemble's next run removes the runs it made.
TEST(Files, ARunInsideAScenesFolderOutlivesTheFoldersNextRun) {
  Scratch t;
  const std::string scene = t / "radial", inner = t / "radial/sub";
  files::RecordedResults known;
  ASSERT_EQ(files::claim_results(scene, "sleeve-radial", getpid()), "");
  ASSERT_EQ(files::record_result(scene + "/summary.json", known), "");
  touch(scene + "/summary.json");
  ASSERT_EQ(files::claim_results(inner, "sleeve-radial", getpid()), "");
  files::RecordedResults known_inner;
  ASSERT_EQ(files::record_result(inner + "/summary.json", known_inner), "");
  touch(inner + "/summary.json");
  files::release_results(inner, getpid());
  files::release_results(scene, getpid());
  ASSERT_EQ(files::claim_results(scene, "sleeve-radial", getpid()), "");
  EXPECT_FALSE(fs::exists(scene + "/summary.json"));
  EXPECT_TRUE(fs::exists(inner + "/summary.json"));
  files::Manifest m;
  ASSERT_EQ(files::read_manifest(scene, m), "");
  EXPECT_EQ(m.entries, std::vector<std::string>{"sub/"});
  files::release_results(scene, getpid());
  // Listed again, it is not foreign at the claim after: the same again.
  ASSERT_EQ(files::claim_results(scene, "sleeve-radial", getpid()), "");
  EXPECT_TRUE(fs::exists(inner + "/summary.json"));
  files::release_results(scene, getpid());
  EXPECT_TRUE(files::owns_nested_runs("sweep beam"));
  EXPECT_TRUE(files::owns_nested_runs("sleeve-random-ensemble"));
  EXPECT_FALSE(files::owns_nested_runs("sleeve-radial"));
}

// A results folder inside another (a sweep's runs) is listed in the outer manifest as `name/` and
// checked against its own: a user's file inside it keeps the outer folder refused.
TEST(Files, NestedResultsFoldersAreCheckedByTheirOwnManifest) {
  Scratch t;
  const std::string sweep = t / "sweep", run = t / "sweep/g=400";
  files::RecordedResults known;
  ASSERT_EQ(files::claim_results(sweep, "sweep beam", getpid()), "");
  ASSERT_EQ(files::claim_results(run, "beam", getpid()), "");
  ASSERT_EQ(files::record_result(run + "/summary.json", known), "");
  touch(run + "/summary.json");
  files::Manifest outer;
  ASSERT_EQ(files::read_manifest(sweep, outer), "");
  EXPECT_EQ(outer.entries, std::vector<std::string>{"g=400/"});
  files::release_results(run, getpid());
  files::release_results(sweep, getpid());
  touch(run + "/mine.txt");
  EXPECT_NE(files::claim_results(sweep, "sweep beam", getpid()).find("mine.txt"), std::string::npos);
  EXPECT_TRUE(fs::exists(run + "/summary.json"));
  fs::remove(run + "/mine.txt");
  // A run inside that is still going (its lock's process alive): refused, not removed under it.
  std::ofstream(run + "/.sma-lock") << getppid() << "\n";
  EXPECT_NE(files::claim_results(sweep, "sweep beam", getpid()).find("in use"), std::string::npos);
  EXPECT_TRUE(fs::exists(run + "/summary.json"));
  fs::remove(run + "/.sma-lock");
  ASSERT_EQ(files::claim_results(sweep, "sweep beam", getpid()), "");
  EXPECT_FALSE(fs::exists(run));
  files::release_results(sweep, getpid());
  // A manifest line that leaves the folder is damage, named.
  std::ofstream(sweep + "/.sma-results", std::ios::app) << "../victim\n";
  EXPECT_NE(files::claim_results(sweep, "sweep beam", getpid()).find("damaged"), std::string::npos);
}

TEST(Files, ALiveRunsLockIsRespectedADeadRunsIsTaken) {
  Scratch t;
  const std::string d = t / "out";
  // A live process (a child that waits on a pipe) holds the lock.
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t child = fork();
  if (child == 0) {
    char c;
    close(fds[1]);
    (void)!read(fds[0], &c, 1);
    _exit(0);
  }
  close(fds[0]);
  ASSERT_EQ(files::claim_results(d, "beam", child), "");
  const std::string error = files::claim_results(d, "beam", getpid());
  EXPECT_NE(error.find("in use by another run (process " + std::to_string(child)), std::string::npos) << error;
  // The child ends: its lock is stale and the next run takes it.
  close(fds[1]);
  waitpid(child, nullptr, 0);
  // Killed while claiming, it had left its unfinished manifest and a lock it was moving aside:
  // the next claim removes a dead process's temporaries.
  const std::string manifest_left = d + "/" + files::results_marker + ".partial-" + std::to_string(child),
                    lock_left = d + "/" + files::results_lock + ".stale-" + std::to_string(child);
  touch(manifest_left);
  touch(lock_left);
  EXPECT_EQ(files::claim_results(d, "beam", getpid()), "");
  EXPECT_EQ(files::lock_owner(fs::path(d) / files::results_lock), (long)getpid());
  EXPECT_FALSE(fs::exists(manifest_left));
  EXPECT_FALSE(fs::exists(lock_left));
}

// A run's results replace the earlier run's only when it completes: a fresh claim moves a complete
// run into previous-run/, a run that does not complete leaves it there whole (and its own partial
// files beside it), the next complete run removes it.
TEST(Files, ARunThatDoesNotCompleteLeavesTheLastCompleteRunWhole) {
  Scratch t;
  const std::string d = t / "out";
  const long pid = getpid();
  auto write = [&](const std::string& name, const std::string& text) {
    files::RecordedResults known;
    ASSERT_EQ(files::record_result(d + "/" + name, known), "");
    touch(d + "/" + name, text);
  };
  // Run 1 completes: its record published, the mark written.
  ASSERT_EQ(files::claim_results(d, "sleeve-radial", pid), "");
  fs::create_directories(d + "/frames");
  write("frames/step-1.vtu", "frame 1");
  write("summary.json", "run 1");
  EXPECT_TRUE(files::is_record_of(d + "/summary.json", d));
  EXPECT_TRUE(files::is_record_of(d + "/./summary.json", d + "/"));
  EXPECT_FALSE(files::is_record_of(d + "/frames/summary.json", d));
  EXPECT_FALSE(files::is_record_of(d + "/history.csv", d));
  ASSERT_EQ(files::complete_results(d, pid), "");
  EXPECT_EQ(files::incomplete_run_note(d, pid), "");
  files::release_results(d, pid);
  // Another process cannot mark a folder it does not hold.
  EXPECT_NE(files::complete_results(d, pid), "");
  // Run 2 (another scene) is stopped before its record: run 1 is whole in previous-run/.
  ASSERT_EQ(files::claim_results(d, "sleeve-circular", pid), "");
  EXPECT_FALSE(fs::exists(d + "/summary.json"));
  EXPECT_FALSE(fs::exists(d + "/" + files::results_complete));
  std::ifstream kept(d + "/previous-run/summary.json");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), "run 1");
  EXPECT_TRUE(fs::exists(d + "/previous-run/frames/step-1.vtu"));
  files::Manifest previous;
  ASSERT_EQ(files::read_manifest(d + "/previous-run", previous), "");
  EXPECT_EQ(previous.scene, "sleeve-radial");
  write("history.csv", "run 2, cut short");
  const std::string note = files::incomplete_run_note(d, pid);
  EXPECT_NE(note.find(d + "/previous-run"), std::string::npos) << note;
  EXPECT_EQ(files::release_results_noted(d, pid), note);  // the same line, and the lock gone
  EXPECT_FALSE(fs::exists(fs::path(d) / files::results_lock));
  EXPECT_EQ(files::incomplete_run_note(d, pid), "");
  // Run 3 is stopped too: run 2's partial files go, run 1 stays kept (not replaced by run 2's).
  ASSERT_EQ(files::claim_results(d, "sleeve-radial", pid), "");
  EXPECT_FALSE(fs::exists(d + "/history.csv"));
  EXPECT_TRUE(fs::exists(d + "/previous-run/summary.json"));
  EXPECT_FALSE(fs::exists(d + "/previous-run/history.csv"));
  files::release_results(d, pid);
  // A user's file in previous-run/ is refused as any unlisted file, nothing touched.
  touch(d + "/previous-run/notes.txt", "mine");
  const std::string refused = files::claim_results(d, "sleeve-radial", pid);
  EXPECT_NE(refused.find("notes.txt"), std::string::npos) << refused;
  fs::remove(d + "/previous-run/notes.txt");
  // Run 4 completes: previous-run/ goes.
  ASSERT_EQ(files::claim_results(d, "sleeve-radial", pid), "");
  write("summary.json", "run 4");
  ASSERT_EQ(files::complete_results(d, pid), "");
  EXPECT_FALSE(fs::exists(d + "/previous-run"));
  files::release_results(d, pid);
  // A claim killed while moving run 4 aside (its staging folder holds the manifest's copy and part
  // of the entries): the next claim takes the move over, and run 4 is whole in previous-run/.
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);
  const std::string staging = d + "/" + files::previous_staging + std::to_string(child);
  fs::create_directories(staging);
  fs::copy_file(d + "/" + files::results_marker, staging + "/" + files::results_marker);
  fs::rename(d + "/summary.json", staging + "/summary.json");
  fs::create_directories(d + "/frames");
  write("frames/step-1.vtu", "frame 4");
  ASSERT_EQ(files::claim_results(d, "sleeve-radial", pid), "");
  EXPECT_FALSE(fs::exists(staging));
  EXPECT_TRUE(fs::exists(d + "/previous-run/summary.json"));
  EXPECT_TRUE(fs::exists(d + "/previous-run/frames/step-1.vtu"));
  EXPECT_FALSE(fs::exists(d + "/frames"));
  files::release_results(d, pid);
  // A user's folder named previous-run (no manifest) is the user's: refused, untouched.
  const std::string other = t / "other";
  ASSERT_EQ(files::claim_results(other, "beam", pid), "");
  files::release_results(other, pid);
  fs::create_directories(other + "/previous-run");
  touch(other + "/previous-run/mine.txt", "mine");
  EXPECT_NE(files::claim_results(other, "beam", pid).find("previous-run/"), std::string::npos);
  EXPECT_TRUE(fs::exists(other + "/previous-run/mine.txt"));
}

// A result file whose folder is gone (or is a file) is refused naming it, before FreeFEM's open
// fails with an "Exec error" that names no cause.
TEST(Files, RecordingAFileInAMissingFolderNamesTheFolder) {
  Scratch t;
  const std::string d = t / "out";
  files::RecordedResults known;
  ASSERT_EQ(files::claim_results(d, "sleeve-radial", getpid()), "");
  ASSERT_EQ(files::record_result(d + "/history.csv", known), "");
  std::string error = files::record_result(d + "/frames/step-1.vtu", known);
  EXPECT_NE(error.find("its folder " + d + "/frames is missing"), std::string::npos) << error;
  touch(d + "/notes");
  error = files::record_result(d + "/notes/x.csv", known);
  EXPECT_NE(error.find(d + "/notes is not a folder"), std::string::npos) << error;
  files::release_results(d, getpid());
  fs::remove_all(d);
  // (an entry recorded before is refused too: the folder went after it)
  error = files::record_result(d + "/history.csv", known);
  EXPECT_NE(error.find("its folder " + d + " is missing"), std::string::npos) << error;
  EXPECT_EQ(files::unwritable_folder("relative-name.csv"), "");  // (the current folder)
}

TEST(Files, EndsWithTellsACompleteVtuFromACutOne) {
  Scratch t;
  touch(t / "whole.vtu", "<VTKFile>\n</VTKFile>\n");
  touch(t / "cut.vtu", "<VTKFile>\n<Piece");
  EXPECT_TRUE(files::ends_with(t / "whole.vtu", "</VTKFile>"));
  EXPECT_FALSE(files::ends_with(t / "cut.vtu", "</VTKFile>"));
  EXPECT_FALSE(files::ends_with(t / "missing.vtu", "</VTKFile>"));
}

TEST(Files, TruncateKeepsTheFirstBytesAndRefusesToGrow) {
  Scratch t;
  touch(t / "history.csv", "step\n1\n2\n3\n");
  ASSERT_EQ(files::truncate_file(t / "history.csv", 7), "");
  std::ifstream in(t / "history.csv");
  const std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(kept, "step\n1\n");
  const std::string longer = files::truncate_file(t / "history.csv", 8);
  EXPECT_NE(longer.find("holds only 7"), std::string::npos) << longer;
  EXPECT_EQ(fs::file_size(t / "history.csv"), 7u);  // a refused cut leaves the file as it was
  EXPECT_NE(files::truncate_file(t / "missing.csv", 0).find(t / "missing.csv"), std::string::npos);
  EXPECT_NE(files::truncate_file(t / "history.csv", -1), "");
  ASSERT_EQ(files::truncate_file(t / "history.csv", 0), "");
  EXPECT_EQ(fs::file_size(t / "history.csv"), 0u);
}

TEST(Files, ShellQuoteMakesOneWordOfAnything) {
  Scratch t;
  for (const std::string& s : {std::string("plain"), std::string("it's"), std::string("a b; touch pwned"),
                               std::string("$(id) `id` \"q\" \\ r\xc3\xa9sultats"), std::string("")}) {
    // The shell echoes the word back unchanged, and runs nothing.
    const std::string command = "printf %s " + files::shell_quote(s) + " > " + files::shell_quote(t / "echo");
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream in(t / "echo");
    std::string back((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(back, s);
  }
  EXPECT_FALSE(fs::exists("pwned"));
}

// FNV-1a 64 against its published test vectors; a sealed file verifies, and any change to it (an
// edited byte, a cut, a line added) is named.
TEST(Files, ChecksumAndSealNameAChangedFile) {
  Scratch t;
  const std::string f = t / "f";
  touch(f, "");
  EXPECT_EQ(files::checksum(f), "cbf29ce484222325");
  touch(f, "a");
  EXPECT_EQ(files::checksum(f), "af63dc4c8601ec8c");
  touch(f, "foobar");
  EXPECT_EQ(files::checksum(f), "85944171f73967e8");
  touch(t / "g", "foo");
  EXPECT_EQ(files::checksum(f, 3), files::checksum(t / "g"));  // a prefix
  EXPECT_EQ(files::checksum(f, 7), "");                  // longer than the file
  EXPECT_EQ(files::checksum(t / "none"), "");
  const std::string ck = t / "checkpoint.txt";
  touch(ck, "sma-sleeve-checkpoint 2\nstep 20\nend\n");
  ASSERT_EQ(files::seal(ck), "");
  EXPECT_EQ(files::seal_error(ck), "");
  std::string text;
  {
    std::ifstream in(ck);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::string edited = text;
  edited.replace(edited.find("20"), 2, "21");
  touch(ck, edited);
  EXPECT_NE(files::seal_error(ck).find("changed after it was written"), std::string::npos);
  touch(ck, text.substr(0, text.size() - 5));
  EXPECT_NE(files::seal_error(ck).find("no checksum line"), std::string::npos);
  touch(ck, text + "step 22\n");
  EXPECT_NE(files::seal_error(ck).find("no checksum line"), std::string::npos);
}

// The hostile cases of issue 26's second round: a link in a results folder, a user's file named
// like the suite's temporary files, an empty or foreign older marker, a line break in a name, a
// path through a folder that does not exist: refused, nothing touched or left behind.
TEST(Files, LinksLookalikesAndOddNamesAreRefusedUntouched) {
  Scratch t;
  const std::string d = t / "out";
  files::RecordedResults known;
  ASSERT_EQ(files::claim_results(d, "sleeve-radial", getpid()), "");
  ASSERT_EQ(files::record_result(d + "/history.csv.partial", known), "");
  touch(t / "users.csv", "mine");
  fs::create_symlink(t / "users.csv", d + "/history.csv.partial");  // listed name, but a link
  files::release_results(d, getpid());
  EXPECT_NE(files::claim_results(d, "sleeve-radial", getpid()).find("symbolic link"), std::string::npos);
  EXPECT_NE(files::truncate_file(d + "/history.csv.partial", 1).find("symbolic link"), std::string::npos);
  std::string users;
  {
    std::ifstream in(t / "users.csv");
    in >> users;
  }
  EXPECT_EQ(users, "mine");
  fs::remove(d + "/history.csv.partial");
  // A user's file that looks like the manifest's temporary name is not the suite's.
  touch(d + "/.sma-results.partial", "mine");
  EXPECT_NE(files::claim_results(d, "sleeve-radial", getpid()).find(".sma-results.partial"), std::string::npos);
  EXPECT_TRUE(fs::exists(d + "/.sma-results.partial"));
  fs::remove(d + "/.sma-results.partial");
  // An empty marker (or another scene's old one) among a user's files: refused, files kept.
  const std::string mine = t / "mine";
  fs::create_directories(mine);
  touch(mine + "/.sma-results", "");
  touch(mine + "/my-measurements.csv", "mine");
  EXPECT_NE(files::claim_results(mine, "sleeve-radial", getpid()).find("names no scene"), std::string::npos);
  touch(mine + "/.sma-results", "beam\n");
  EXPECT_NE(files::claim_results(mine, "sleeve-radial", getpid()).find("another scene (beam)"), std::string::npos);
  EXPECT_TRUE(fs::exists(mine + "/my-measurements.csv"));
  // A name with a line break cannot be listed (it would add a forged line).
  EXPECT_NE(files::claim_results(d + "/sub\nsummary.json", "beam", getpid()).find("line break"), std::string::npos);
  EXPECT_FALSE(fs::exists(d + "/sub\nsummary.json"));
  // out/sub/.. goes into sub and back: refused (the scripts would write through sub), none made.
  EXPECT_NE(files::claim_results(d + "/sub/..", "sleeve-radial", getpid()).find("and back out"), std::string::npos);
  EXPECT_FALSE(fs::exists(d + "/sub"));
  // A lock that is a FIFO is named at once (reading it blocked for ever).
  ASSERT_EQ(mkfifo((d + "/.sma-lock").c_str(), 0644), 0);
  EXPECT_NE(files::claim_results(d, "sleeve-radial", getpid()).find("is not a file"), std::string::npos);
  fs::remove(d + "/.sma-lock");
  // A file with a second name elsewhere (a hard link) is not cut (nor continued) in place.
  touch(d + "/history.csv.partial", "step\n1\n2\n");
  fs::create_hard_link(d + "/history.csv.partial", t / "users-copy.csv");
  EXPECT_NE(files::truncate_file(d + "/history.csv.partial", 5).find("hard link"), std::string::npos);
  EXPECT_EQ(fs::file_size(t / "users-copy.csv"), 9u);  // untouched
  // A manifest saved with CRLF line ends reads as the same manifest.
  const std::string crlf = t / "crlf";
  fs::create_directories(crlf);
  touch(crlf + "/.sma-results", "sma-results manifest 1\r\nscene beam\r\nsummary.json\r\n");
  touch(crlf + "/summary.json");
  files::Manifest m;
  ASSERT_EQ(files::read_manifest(crlf, m), "");
  EXPECT_FALSE(m.legacy);
  EXPECT_EQ(m.scene, "beam");
  EXPECT_EQ(m.entries, std::vector<std::string>{"summary.json"});
}

// The checkpoint's number words (edp/problems/sleeve/checkpoint.idp through StreamReadNumbers):
// the words the suite writes read back as the same doubles, anything else refused naming the value.
TEST(Files, NumberWordIsAWholeDecimalNumber) {
  for (const char* w : {"0", "-1", "+7", "3.", ".5", "-1.2345678901234567e-05", "1E+300", "6.0883720704432680e1"})
    EXPECT_TRUE(files::number_word(w, false)) << w;
  for (const char* w : {"", "-", ".", "e5", "1e", "1e+", "5x", "1.2.3", "nan", "inf", "-inf", "0x10", "1 ", " 1", "1,5"})
    EXPECT_FALSE(files::number_word(w, false)) << "'" << w << "'";
  for (const char* w : {"0", "30", "-2", "+4"}) EXPECT_TRUE(files::number_word(w, true)) << w;
  for (const char* w : {"2.5", "1e3", "3.", "", "+", "7x"}) EXPECT_FALSE(files::number_word(w, true)) << w;
}

TEST(Files, ReadNumbersReadsBackWhatWasWrittenAndNamesTheBadValue) {
  // 17 significant digits (the checkpoint's precision): each value back bit for bit, and the
  // stream left at the word after the array (the script reads the next array's name there).
  std::vector<double> written = {0.0, -1.0 / 3.0, 6.02214076e23, 4.9e-324, -1.7976931348623157e308, 293.15};
  std::stringstream text;
  text.precision(17);
  for (double v : written) text << v << "\n";
  text << "next 2\n";
  std::vector<double> read(written.size(), -99.0);
  EXPECT_EQ(files::read_numbers(text, read.data(), read.size(), false, "T"), "");
  EXPECT_EQ(read, written);
  std::string following;
  text >> following;
  EXPECT_EQ(following, "next");

  auto error = [](const std::string& words, std::size_t n, bool integer) {
    std::istringstream in(words);
    std::vector<double> values(n);
    return files::read_numbers(in, values.data(), n, integer, "u");
  };
  EXPECT_EQ(error("1 2 3", 3, true), "");
  EXPECT_EQ(error("1 2 abc", 3, false), "u[2] is 'abc', not a number");
  EXPECT_EQ(error("1 2.5", 2, true), "u[1] is '2.5', not an integer");
  EXPECT_EQ(error("1 1e400", 2, false), "u[1] '1e400' overflows a double");
  EXPECT_EQ(error("1 2", 3, false), "it ends at u[2]");
  EXPECT_EQ(error("", 0, false), "");
}
