// Which folder a command may write its results into (docs/output.md, "Overwriting"): never one that holds another
// kind of result. A run folder holds run.h5 or checkpoint.h5, a campaign folder sweep.json, a cross-validation
// folder crossval.json; `suspend phim` writes beside a campaign's table (its default), never into a run or a
// cross-validation.
#pragma once
#include <filesystem>
#include <string>

namespace suspend::io {

enum class FolderKind { run, campaign, phim, crossval };

// Throws InputError naming `option` and what the folder holds when `dir` holds a result `kind` may not join.
void refuse_foreign_folder(const std::filesystem::path& dir, FolderKind kind, const std::string& option = "--out");

}  // namespace suspend::io
