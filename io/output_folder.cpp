#include "io/output_folder.hpp"

#include <initializer_list>
#include <utility>

#include "core/error.hpp"

namespace suspend::io {

namespace fs = std::filesystem;

void refuse_foreign_folder(const fs::path& dir, FolderKind kind, const std::string& option) {
  struct Marker {
    const char* file;
    FolderKind holds;
    const char* what;
  };
  static constexpr Marker markers[] = {{"run.h5", FolderKind::run, "a run"},
                                       {"checkpoint.h5", FolderKind::run, "a run"},
                                       {"sweep.json", FolderKind::campaign, "a campaign"},
                                       {"crossval.json", FolderKind::crossval, "a cross-validation"}};
  // What each kind may share a folder with besides its own kind: a fit sits beside its campaign's table.
  auto allowed = [&](FolderKind other) { return other == kind || (kind == FolderKind::phim && other == FolderKind::campaign); };
  for (const Marker& m : markers) {
    std::error_code ec;
    if (!fs::exists(dir / m.file, ec) || allowed(m.holds)) continue;
    throw InputError(option + ": " + dir.string() + " holds " + m.what + " (" + m.file +
                     "); results of another kind are never written into it: give another directory");
  }
}

}  // namespace suspend::io
