#include "io/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

namespace suspend::io {

namespace {
// Who a lock file says holds it. The holder writes that right after it takes the lock: give it a moment when the
// file is still empty.
std::string read_holder(const std::filesystem::path& file) {
  std::string holder;
  for (int tries = 0; tries < 20 && holder.empty(); ++tries) {
    if (tries) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::ifstream in(file);
    std::getline(in, holder);
  }
  return holder.empty() ? "another process" : holder;
}
}  // namespace

FolderLock::FolderLock(const std::filesystem::path& file, const std::string& purpose) {
  fd_ = ::open(file.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    holder_ = "nobody: the lock file " + file.string() + " cannot be opened";
    return;
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    holder_ = read_holder(file);
    return;
  }
  char host[256] = "unknown host";
  ::gethostname(host, sizeof host - 1);
  const std::time_t now = std::time(nullptr);
  char when[32];
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
  std::ostringstream s;
  s << "process " << ::getpid() << " on " << host << " (" << purpose << "), since " << when << "\n";
  const std::string text = s.str();
  // Should the description not be written, the lock still holds; a refusal then names "another process".
  [[maybe_unused]] const bool described =
      ::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, text.data(), text.size(), 0) == static_cast<ssize_t>(text.size());
}

std::optional<std::string> FolderLock::holder_of(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  const bool free = ::flock(fd, LOCK_SH | LOCK_NB) == 0;
  ::close(fd);
  if (free) return std::nullopt;
  return read_holder(file);
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the flock
}

}  // namespace suspend::io
