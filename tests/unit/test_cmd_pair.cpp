// `suspend pair`: the JSON it prints is the library's model functions, and bad input exits with code 2.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "dem/hydro/resistance_functions.hpp"

namespace {

struct Result {
  int exit_code;
  std::string out;
};

Result run(const std::string& args) {
  const std::string cmd = std::string(SUSPEND_BINARY_DIR "/bin/suspend pair ") + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

double value(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return -1e300;
  return std::stod(json.substr(at + key.size() + 4));
}

}  // namespace

TEST(PairCommand, JsonHoldsEveryFunctionOfTheModel) {
  const Result r = run("--a1 1 --a2 3 --gap 0.002 --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const suspend::hydro::ResistanceScalars s = suspend::hydro::two_sphere_resistance(1.0, 3.0, 0.002);
  EXPECT_NEAR(value(r.out, "xi"), 0.001, 1e-12);
  EXPECT_NEAR(value(r.out, "X11A"), s.x11a, 1e-9 * s.x11a);
  EXPECT_NEAR(value(r.out, "Y12B"), s.y12b, 1e-9 * s.y12b);
  EXPECT_NEAR(value(r.out, "Y12H"), s.y12h, 1e-9 * s.y12h);
  for (const char* key : {"X12A", "Y11A", "Y12A", "Y11B", "X11C", "Y11C", "Y12C", "X11G", "X12G", "Y11G", "Y12G", "Y11H"})
    EXPECT_NE(value(r.out, key), -1e300) << key;
}

TEST(PairCommand, OuterCutoffLeavesStokesDrag) {
  const Result r = run("--a1 1 --a2 1 --gap 0.5 --outer-cutoff 0.25 --json");
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_EQ(value(r.out, "X11A"), 1.0);
  EXPECT_EQ(value(r.out, "X12A"), 0.0);
}

TEST(PairCommand, BadInputIsOneLineAndExitCode2) {
  for (const char* args : {"--a1 -1 --a2 1 --gap 0.1", "--a1 1 --a2 1 --gap -0.1", "--a1 1 --a2 1 --gap 0",
                           "--a1 1e-300 --a2 1 --gap 0.1", "--a1 1 --a2 1 --gap 0.1 --outer-cutoff 0",
                           "--a1 1 --a2 1 --gap 0.1 --outer-cutoff -2", "--a1 1 --a2 1 --gap 0.1 --outer-cutoff nan",
                           "--a1 nan --a2 1 --gap 0.1"}) {
    const Result r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  }
}
