// Running the `suspend` program from a test as a user would: spawn it, wait for its exit code, read what it said.
#pragma once
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/scratch_dir.hpp"

extern char** environ;

namespace suspend::test {

namespace fs = std::filesystem;
inline const std::string suspend_bin = SUSPEND_BINARY_DIR "/bin/suspend";

// Per-process scratch space, removed when the program ends: several builds (Release, sanitizers) may run this
// test at the same time.
inline std::string scratch() { return suspend::testing_support::scratch_dir(); }
inline pid_t spawn(std::vector<std::string> args, const std::string& err_file, bool own_group = false,
                   const std::string& out_file = "/dev/null", const std::string& program = suspend_bin) {
  args.insert(args.begin(), program);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  if (own_group) {  // so that a test can kill the program and every process it started at once
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attr, 0);
  }
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, program.c_str(), &fa, &attr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  return pid;
}
inline int wait_exit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
struct Result {
  int code;
  std::string err;
  std::string out;
};
inline std::string read_text(const std::string& path);
inline Result run(const std::vector<std::string>& args) {
  const std::string err_file = scratch() + "/stderr.txt", out_file = scratch() + "/stdout.txt";
  const int code = wait_exit(spawn(args, err_file, false, out_file));
  return {code, read_text(err_file), read_text(out_file)};
}
inline std::string fresh_dir(const std::string& name) {
  const std::string d = scratch() + "/" + name;
  fs::remove_all(d);
  return d;
}
inline std::string write_case(const std::string& name, const std::string& text) {
  const std::string p = scratch() + "/" + name;
  std::ofstream(p) << text;
  return p;
}
inline void expect_input_error(const std::vector<std::string>& args, const std::string& fragment, const std::string& out) {
  const Result r = run(args);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "") << "nothing may be printed on bad input";
  if (!out.empty()) {
    EXPECT_FALSE(fs::exists(out)) << "nothing may be written to --out on bad input";
  }
}
inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace suspend::test
