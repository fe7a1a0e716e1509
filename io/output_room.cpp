#include "io/output_room.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace suspend::io {

namespace fs = std::filesystem;

std::uintmax_t room_for(const std::string& path) {
  std::error_code ec;
  const fs::path folder = fs::path(path).has_parent_path() ? fs::path(path).parent_path() : fs::path(".");
  const fs::space_info space = fs::space(folder, ec);
  std::uintmax_t room = ec ? UINTMAX_MAX : space.available;
  rlimit limit{};
  if (getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const std::uintmax_t size = fs::exists(path, ec) ? fs::file_size(path, ec) : 0;
    room = std::min<std::uintmax_t>(room, limit.rlim_cur > size ? limit.rlim_cur - size : 0);
  }
  return room;
}

std::optional<std::string> OutputRoom::after_checkpoint(const std::string& run_path,
                                                        const std::string& checkpoint_path) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(run_path, ec);
  if (ec) return std::nullopt;
  const std::uintmax_t checkpoint = fs::file_size(checkpoint_path, ec);
  if (ec) return std::nullopt;
  if (measured_) largest_growth_ = std::max(largest_growth_, size > last_run_size_ ? size - last_run_size_ : 0);
  last_run_size_ = size;
  const bool first = !measured_;
  measured_ = true;
  if (first) return std::nullopt;
  const std::uintmax_t need = 2 * largest_growth_ + 2 * checkpoint;
  const std::uintmax_t room = room_for(run_path);
  if (room >= need) return std::nullopt;
  std::ostringstream s;
  s << "the disk is nearly full: room for " << room / 1024 << " kB more next to " << run_path
    << ", the next checkpoint interval needs about " << need / 1024 << " kB";
  return s.str();
}

}  // namespace suspend::io
