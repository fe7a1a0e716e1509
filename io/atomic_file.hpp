// Files that are either complete or absent: write to a temporary name in the same directory, then rename.
#pragma once
#include <functional>
#include <string>

namespace suspend::io {

// Calls write(temporary_path), fsyncs it and renames it onto path. On exception the temporary is removed.
void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write);
void write_text_atomically(const std::string& path, const std::string& text);
// Removes the temporaries (NAME.tmp.PID) in `dir` that a killed writer left: those whose process is gone.
void remove_stale_temporaries(const std::string& dir);

}  // namespace suspend::io
