// A scratch folder for one test program: <gtest TempDir>/suspend_test_<pid>, made on first use and removed when the
// program's tests have run (a global gtest environment), so test runs leave nothing behind in the temp folder. The
// pid keeps programs that run at the same time (ctest -j, several builds) apart.
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace suspend::testing_support {

inline std::string scratch_path() { return ::testing::TempDir() + "/suspend_test_" + std::to_string(getpid()); }

inline std::string scratch_dir() {
  const std::string d = scratch_path();
  std::filesystem::create_directories(d);
  return d;
}

class ScratchCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(scratch_path(), ignored);
  }
};

// Registered before main runs the tests (gtest owns the environment).
inline ::testing::Environment* const scratch_cleanup = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

}  // namespace suspend::testing_support
