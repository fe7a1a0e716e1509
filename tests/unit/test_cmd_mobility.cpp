// The `suspend mobility` command end to end: JSON drag ratio against the exact periodic-Gaussian drag
// 1 - 2.837297 (a/L) + 4 (a/L)^3 (docs/references.md, "Force Coupling Method
// facts"), and exit code 2 with one line on bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {
struct CommandRun {
  int code;
  std::string out;
};
CommandRun run_mobility(const std::string& args) {
  // One output file per process: ctest runs the tests of this file in parallel.
  const std::string out_file = std::string(SUSPEND_BINARY_DIR) + "/test_cmd_mobility." + std::to_string(getpid()) + ".out";
  const std::string cmd = std::string(SUSPEND_BINARY_DIR) + "/bin/suspend mobility " + args + " > " + out_file + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(out_file);
  std::stringstream s;
  s << in.rdbuf();
  return {WEXITSTATUS(status), s.str()};
}
}  // namespace

TEST(CmdMobility, JsonDragRatioOfOneSphere) {
  const CommandRun r = run_mobility("--box 10 --grid 20 --radius 1 --force 0,0,2 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto k = r.out.find("\"drag_ratio\": ");
  ASSERT_NE(k, std::string::npos) << r.out;
  const double drag = std::stod(r.out.substr(k + 14));
  const double x = 0.1;
  EXPECT_NEAR(drag, 1.0 - 2.837297 * x + 4.0 * x * x * x, 2e-3);
}

TEST(CmdMobility, BadInputGivesOneLineAndExitCodeTwo) {
  for (const char* args : {"--force 1,2", "--box -3", "--positions /no/such/file", "--box 4 --grid 8",
                           "--force nan,0,0", "--radius 1e-6", "--grid 100000", "--shear-rate inf"}) {
    const CommandRun r = run_mobility(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  }
}
