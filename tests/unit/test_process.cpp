// run_shell (plugin/core/process.hpp): exit statuses, a death by a signal, and the caller's
// SIGINT left as it was while the child runs (system() ignores it: an INT to a scene was lost).
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "core/process.hpp"

namespace {

TEST(RunShell, ExitStatusAndSignal) {
  EXPECT_EQ(sma::process::run_shell("true"), 0);
  EXPECT_EQ(sma::process::run_shell("exit 3"), 3);
  EXPECT_EQ(sma::process::run_shell("kill -TERM $$"), 128 + SIGTERM);
  EXPECT_EQ(sma::process::run_shell("exec /nonexistent/program 2> /dev/null"), 127);
}

// The child reads its parent's ignored-signal mask (/proc/<ppid>/status, SigIgn, hexadecimal):
// SIGINT (bit 2 - 1) must not be in it while the child runs; with std::system it is.
unsigned long long ParentIgnoredWhileChildRuns(bool viaSystem) {
  char name[] = "/tmp/sma-process-XXXXXX";
  const int fd = mkstemp(name);
  close(fd);
  const std::string command = std::string("awk '/^SigIgn/ {print $2}' /proc/$PPID/status > ") + name;
  if (viaSystem) {
    EXPECT_EQ(std::system(command.c_str()), 0);
  } else {
    EXPECT_EQ(sma::process::run_shell(command), 0);
  }
  std::ifstream in(name);
  std::string hex;
  in >> hex;
  std::remove(name);
  return std::stoull(hex, nullptr, 16);
}

TEST(RunShell, CallerKeepsItsInterrupt) {
  const unsigned long long intBit = 1ULL << (SIGINT - 1);
  ASSERT_EQ(std::signal(SIGINT, SIG_DFL), SIG_DFL);
  EXPECT_EQ(ParentIgnoredWhileChildRuns(false) & intBit, 0ULL);
  // (the check can fail: system() ignores SIGINT in the caller meanwhile)
  EXPECT_NE(ParentIgnoredWhileChildRuns(true) & intBit, 0ULL);
}

TEST(TemporaryDirectory, NewEmptyAndOwn) {
  const std::string a = sma::process::temporary_directory("sma-test-"), b = sma::process::temporary_directory("sma-test-");
  ASSERT_FALSE(a.empty());
  EXPECT_NE(a, b);
  EXPECT_EQ(a.rfind(sma::process::temporary_root() + "/sma-test-", 0), 0U);
  struct stat st {};
  ASSERT_EQ(stat(a.c_str(), &st), 0);
  EXPECT_TRUE(S_ISDIR(st.st_mode));
  EXPECT_EQ(st.st_mode & 0777, 0700U);  // (mkdtemp: the owner's alone)
  EXPECT_EQ(rmdir(a.c_str()), 0);       // (empty)
  EXPECT_EQ(rmdir(b.c_str()), 0);
  EXPECT_EQ(sma::process::temporary_directory("a/b"), "");
}

// $TMPDIR when it names an existing directory by an absolute path (trailing slashes dropped), else
// /tmp: a relative, missing or empty TMPDIR is not taken.
TEST(TemporaryDirectory, InTmpdir) {
  const char* before = std::getenv("TMPDIR");
  const std::string saved = before ? before : "";
  char pattern[] = "/tmp/sma-tmpdir-XXXXXX";
  ASSERT_NE(mkdtemp(pattern), nullptr);
  const std::string root(pattern);
  setenv("TMPDIR", (root + "//").c_str(), 1);
  EXPECT_EQ(sma::process::temporary_root(), root);
  const std::string inside = sma::process::temporary_directory("sma-test-");
  EXPECT_EQ(inside.rfind(root + "/sma-test-", 0), 0U);
  EXPECT_EQ(rmdir(inside.c_str()), 0);
  for (const char* bad : {"relative/dir", "/tmp/sma-no-such-folder-here", ""}) {
    setenv("TMPDIR", bad, 1);
    EXPECT_EQ(sma::process::temporary_root(), "/tmp") << bad;
  }
  EXPECT_EQ(rmdir(root.c_str()), 0);
  if (before) setenv("TMPDIR", saved.c_str(), 1);
  else unsetenv("TMPDIR");
}

}  // namespace
