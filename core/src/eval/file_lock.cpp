#include "pagor/eval/file_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"

namespace pagor {
namespace {

// The holder's note in the lock file ("pid 1234: pagor bench --out"), for the message.
std::string holder(int fd) {
  char buf[256] = {};
  const ssize_t n = ::pread(fd, buf, sizeof(buf) - 1, 0);
  std::string text(buf, n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\0')) text.pop_back();
  return text.empty() ? "another process" : text;
}

}  // namespace

FileLock::FileLock(const std::string& path, const std::string& purpose)
    : lock_path_(sibling_path(path, ".lock")) {
  // A lock file removed by its last holder between our open and our flock is not the lock any
  // more: try again on the file now at the path.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0)
      throw InputError(path + ": cannot create its lock file " + lock_path_ + " (" +
                       std::strerror(errno) + ")");
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      const std::string who = holder(fd);
      ::close(fd);
      if (err == EWOULDBLOCK)
        throw InputError(path + ": is being written by " + who + " (lock " + lock_path_ +
                         "); wait until it has finished, or write to another file");
      throw InputError(path + ": cannot lock " + lock_path_ + " (" + std::strerror(err) + ")");
    }
    struct stat held {
    }, now{};
    if (::fstat(fd, &held) == 0 && ::stat(lock_path_.c_str(), &now) == 0 &&
        held.st_dev == now.st_dev && held.st_ino == now.st_ino) {
      const std::string note = "pid " + std::to_string(::getpid()) + ": " + purpose + "\n";
      const bool noted = ::ftruncate(fd, 0) == 0 &&
                         ::pwrite(fd, note.data(), note.size(), 0) == ssize_t(note.size());
      (void)noted;  // the note only serves messages
      fd_ = fd;
      return;
    }
    ::close(fd);
  }
  throw InputError(path + ": cannot lock " + lock_path_ + " (it keeps being replaced)");
}

FileLock::~FileLock() {
  if (fd_ < 0) return;
  ::unlink(lock_path_.c_str());  // while still held, so nobody locks the file being removed
  ::close(fd_);
}

}  // namespace pagor
