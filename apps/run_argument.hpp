// The RUN_DIR argument of the commands that read a finished run (analyze, export): a run directory or its run.h5.
#pragma once
#include <filesystem>
#include <string>

#include "core/error.hpp"

namespace suspend::app {

// DIR/run.h5 (or the file given); InputError naming the command when there is none.
inline std::string run_file_argument(const std::string& given, const std::string& command) {
  std::filesystem::path file(given);
  if (std::filesystem::is_directory(file)) file /= "run.h5";
  if (!std::filesystem::is_regular_file(file))
    throw InputError(command + ": '" + file.string() + "' not found; give a run directory (suspend run --out DIR)");
  return file.string();
}

}  // namespace suspend::app
