#include "pagor/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "pagor/errors.hpp"

namespace pagor {
namespace {

std::string reason() {
  return std::strerror(errno);
}

// Writes all of `bytes` to `fd`, retrying short writes; false (errno set) on failure.
bool write_all(int fd, std::string_view bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// Permissions for a new file: those of the file it replaces, else 0666 less the umask.
mode_t new_file_mode(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) return st.st_mode & 07777;
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

// Longest file name (not path) the file systems in use take [bytes].
constexpr std::size_t kMaxNameBytes = 255;

}  // namespace

std::string sibling_path(const std::string& path, const std::string& suffix) {
  const std::filesystem::path p(path);
  const std::string name = p.filename().string();
  if (name.size() + suffix.size() <= kMaxNameBytes) return path + suffix;
  const std::string hash = "~" + fingerprint(name);
  const std::size_t keep = kMaxNameBytes - suffix.size() - hash.size();
  return (p.parent_path() / (name.substr(0, keep) + hash + suffix)).string();
}

void write_file_atomic(const std::string& path, std::string_view bytes) {
  const std::filesystem::path target(path);
  const std::filesystem::path dir =
      target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  // ".NAME.tmp-XXXXXX", shortened (sibling_path) when NAME is near the 255-byte limit.
  std::string tmp =
      sibling_path((dir / ("." + target.filename().string())).string(), ".tmp-XXXXXX");
  std::vector<char> name(tmp.begin(), tmp.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0)
    throw InputError(path + ": cannot create a temporary file beside it (" + reason() +
                     "); nothing was written");
  tmp = name.data();
  const auto give_up = [&](const std::string& what) {
    const std::string why = reason();
    ::close(fd);
    ::unlink(tmp.c_str());
    throw InputError(path + ": " + what + " (" + why +
                     "); the previous file, if any, is unchanged");
  };
  if (::fchmod(fd, new_file_mode(path)) != 0) give_up("cannot set permissions");
  if (!write_all(fd, bytes)) give_up("write failed");
  if (::fsync(fd) != 0) give_up("cannot flush to disk");
  if (::close(fd) != 0) {
    const std::string why = reason();
    ::unlink(tmp.c_str());
    throw InputError(path + ": write failed (" + why +
                     "); the previous file, if any, is unchanged");
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = reason();
    ::unlink(tmp.c_str());
    throw InputError(path + ": cannot rename the new file into place (" + why +
                     "); the previous file, if any, is unchanged");
  }
  // Make the rename itself durable (best effort: not every file system supports it).
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

LineAppender::LineAppender(const std::string& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC, 0666);
  if (fd_ < 0) throw InputError(path + ": cannot open for appending (" + reason() + ")");
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd_);
    throw InputError(path + ": not a regular file");
  }
  // Find the end of the last complete line by reading backwards.
  std::uint64_t end = static_cast<std::uint64_t>(st.st_size);
  char buf[4096];
  while (end > 0) {
    const std::uint64_t chunk = std::min<std::uint64_t>(end, sizeof(buf));
    const ssize_t n = ::pread(fd_, buf, chunk, static_cast<off_t>(end - chunk));
    if (n != static_cast<ssize_t>(chunk)) {
      ::close(fd_);
      throw InputError(path + ": cannot read (" + reason() + ")");
    }
    std::uint64_t k = chunk;
    while (k > 0 && buf[k - 1] != '\n') --k;
    if (k > 0) {
      end = end - chunk + k;
      break;
    }
    end -= chunk;
  }
  if (end != static_cast<std::uint64_t>(st.st_size) &&
      ::ftruncate(fd_, static_cast<off_t>(end)) != 0) {
    ::close(fd_);
    throw InputError(path + ": cannot cut off its incomplete last line (" + reason() + ")");
  }
  size_ = end;
}

LineAppender::~LineAppender() {
  if (fd_ >= 0) ::close(fd_);
}

void LineAppender::append(std::string_view line) {
  std::string text(line);
  text += '\n';
  if (!write_all(fd_, text) || ::fsync(fd_) != 0) {
    const std::string why = reason();
    const bool restored = ::ftruncate(fd_, static_cast<off_t>(size_)) == 0;
    throw InputError(
        path_ + ": cannot append a line (" + why + ")" +
        (restored ? "; the lines written before are intact" : "; the last line may be incomplete"));
  }
  size_ += text.size();
}

std::string fingerprint(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  char out[17];
  std::snprintf(out, sizeof(out), "%016llx", static_cast<unsigned long long>(h));
  return out;
}

}  // namespace pagor
