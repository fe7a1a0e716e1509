// The two ways a run can fail, kept apart because users act on them differently:
// InputError  -> the case file or command line is wrong (exit code 2, nothing written);
// NumericalError -> the physics went wrong mid-run (stop, keep last good state, exit code 3);
// OutputError -> an output could not be written (disk full, quota, file size limit): stop, keep the last complete
//                checkpoint, exit code 5.
#pragma once
#include <stdexcept>
#include <string>

namespace suspend {
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr int exit_input_error = 2;
inline constexpr int exit_numerical_error = 3;
// An imposed-stress run whose shear rate stayed below its jammed threshold (RunCase::jammed_*): data, not a failure.
inline constexpr int exit_jammed = 4;
inline constexpr int exit_output_error = 5;
inline constexpr int exit_interrupted = 130;
}  // namespace suspend
