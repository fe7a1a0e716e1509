// A process's exclusive hold on a folder: flock(2) on a lock file in it, released by the kernel when the process
// ends in any way (SIGKILL included), inherited by a child that keeps the descriptor. The file holds who took it
// (process, host, command, time), so that a refusal can name the holder.
//
// Assumption (docs/output.md): the file system honours flock across the processes that share the folder. Local
// file systems and Linux NFS clients do (NFS maps flock onto byte-range locks, which the server arbitrates across
// clients); Lustre needs its `flock` mount option. HDF5's own file locking is not relied on: clusters often switch it
// off (HDF5_USE_FILE_LOCKING=FALSE).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <utility>

namespace suspend::io {

class FolderLock {
 public:
  FolderLock() = default;
  // Tries once, never waits; `purpose` goes into the file (e.g. "suspend run").
  FolderLock(const std::filesystem::path& file, const std::string& purpose);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  FolderLock(FolderLock&& o) noexcept : fd_(std::exchange(o.fd_, -1)), holder_(std::move(o.holder_)) {}
  FolderLock& operator=(FolderLock&& o) noexcept {
    std::swap(fd_, o.fd_);
    std::swap(holder_, o.holder_);
    return *this;
  }
  // Who holds the lock of `file` now, without taking it or writing anything; nullopt when nobody does.
  static std::optional<std::string> holder_of(const std::filesystem::path& file);

  bool held() const { return fd_ >= 0; }
  int fd() const { return fd_; }
  // When not held: who holds it, as its file says ("process 123 on node7 (suspend run), since 2026-12-06 03:30:00").
  const std::string& holder() const { return holder_; }

 private:
  int fd_ = -1;
  std::string holder_;
};

}  // namespace suspend::io
