// Result files without a shell (plugin/core/files.hpp): names with shell syntax stay names,
// removal stays inside the folder, a foreign folder is refused, a live run's lock is respected
// and a dead run's lock is taken.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

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
  // New, empty, or marked by an earlier run: taken.
  EXPECT_EQ(files::claim_results(t / "new", "beam", getpid()), "");
  EXPECT_TRUE(fs::exists(t / "new/.sma-results"));
  files::release_results(t / "new", getpid());
  EXPECT_FALSE(fs::exists(t / "new/.sma-lock"));
  EXPECT_EQ(files::claim_results(t / "new", "beam", getpid()), "");
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
  EXPECT_EQ(files::claim_results(d, "beam", getpid()), "");
  EXPECT_EQ(files::lock_owner(fs::path(d) / files::results_lock), (long)getpid());
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
