#pragma once
/// \file file_lock.hpp
/// One writer per output file: an exclusive lock, held for as long as the object lives, on a
/// file beside the output (`FILE.lock`). A second writer is refused at once with a message naming
/// the file and the process that holds it. A lock left by a killed process is free again (the
/// kernel releases it with the process); the lock file is removed when the lock is released.

#include <string>

namespace pagor {

class FileLock {
 public:
  /// Locks `path` for `purpose` (e.g. "pagor bench --out"). Throws InputError naming `path` when
  /// another process holds the lock, or the lock file cannot be made.
  FileLock(const std::string& path, const std::string& purpose);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

  /// The lock file.
  const std::string& lock_path() const { return lock_path_; }

 private:
  std::string lock_path_;
  int fd_ = -1;
};

}  // namespace pagor
