#include "io/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <ctime>
#include <fstream>
#include <sstream>

namespace suspend::io {

FolderLock::FolderLock(const std::filesystem::path& file, const std::string& purpose) {
  fd_ = ::open(file.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    holder_ = "nobody: the lock file " + file.string() + " cannot be opened";
    return;
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    std::ifstream in(file);
    std::getline(in, holder_);
    if (holder_.empty()) holder_ = "another process";
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

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the flock
}

}  // namespace suspend::io
