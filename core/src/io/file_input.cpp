#include "pagor/io/file_input.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "io/read_pieces.hpp"
#include "pagor/errors.hpp"

namespace pagor {
namespace {

std::string size_text(std::uint64_t bytes) {
  if (bytes >= (std::uint64_t{1} << 30) && bytes % (std::uint64_t{1} << 30) == 0)
    return std::to_string(bytes >> 30) + " GiB";
  if (bytes >= (std::uint64_t{1} << 20) && bytes % (std::uint64_t{1} << 20) == 0)
    return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

InputError too_large(const std::string& path, const std::string& what, const std::string& size,
                     std::uint64_t max_bytes) {
  return InputError(path + ": " + what + " is " + size + ", more than the " + size_text(max_bytes) +
                    " this reader takes");
}

// Closes the descriptor on every path out.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

namespace {

// Opens a regular file for reading, checked as read_file documents; its size in `size`.
int open_regular(const std::string& path, const std::string& what, std::uint64_t max_bytes,
                 std::uint64_t& size) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno == ENOENT || errno == ENOTDIR)
      throw InputError(path + ": " + what + " does not exist");
    throw InputError(path + ": cannot open " + what + " (" + std::strerror(errno) + ")");
  }
  if (!S_ISREG(st.st_mode))
    throw InputError(path + ": " + what + " is " + kind_of(st.st_mode) + ", expected a file");
  // O_NONBLOCK: should the path have become a FIFO since the check, opening it does not wait for
  // a writer; fstat below then refuses it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError(path + ": cannot open " + what + " (" + std::strerror(errno) + ")");
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw InputError(path + ": " + what + " is " + kind_of(st.st_mode) + ", expected a file");
  }
  size = static_cast<std::uint64_t>(st.st_size);
  if (size > max_bytes) {
    ::close(fd);
    throw too_large(path, what, std::to_string(size) + " bytes", max_bytes);
  }
  return fd;
}

// Reads up to `n` bytes at `into`; 0 at the end of the file. Throws InputError.
std::size_t read_some(int fd, char* into, std::size_t n, const std::string& path,
                      const std::string& what) {
  for (;;) {
    const ssize_t got = ::read(fd, into, n);
    if (got >= 0) return static_cast<std::size_t>(got);
    if (errno != EINTR)
      throw InputError(path + ": cannot read " + what + " (" + std::strerror(errno) + ")");
  }
}

}  // namespace

std::string read_file(const std::string& path, const std::string& what, std::uint64_t max_bytes) {
  std::uint64_t size = 0;
  Fd f;
  f.fd = open_regular(path, what, max_bytes, size);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t done = 0;
  for (;;) {  // to the end of the file, which may have grown or shrunk since it was opened
    if (done == bytes.size()) {
      // Full: the end is probed with a small read before the string grows (growing copies it).
      char more[4096];
      const std::size_t n = read_some(f.fd, more, sizeof(more), path, what);
      if (n == 0) break;
      if (bytes.size() > max_bytes) throw too_large(path, what, "growing", max_bytes);
      bytes.append(more, n);
      done += n;
      continue;
    }
    const std::size_t n = read_some(f.fd, &bytes[done], bytes.size() - done, path, what);
    if (n == 0) break;
    done += n;
  }
  if (done > max_bytes) throw too_large(path, what, std::to_string(done) + " bytes", max_bytes);
  bytes.resize(done);
  return bytes;
}

std::uint64_t read_file_pieces(const std::string& path, const std::string& what,
                               std::uint64_t max_bytes,
                               const std::function<void(std::uint64_t size)>& opened,
                               const std::function<void(const char*, std::size_t)>& consume) {
  std::uint64_t size = 0;
  Fd f;
  f.fd = open_regular(path, what, max_bytes, size);
  if (opened) opened(size);
  // On the stack: a buffer from the heap would be fresh pages for every file (a page fault each,
  // dear in a virtual machine).
  char buf[kFilePieceBytes];
  std::uint64_t total = 0;
  for (;;) {
    const std::size_t n = read_some(f.fd, buf, sizeof(buf), path, what);
    if (n == 0) break;
    total += n;
    if (total > max_bytes) throw too_large(path, what, "growing", max_bytes);
    consume(buf, n);
  }
  return total;
}

std::string file_fingerprint(const std::string& path, const std::string& what,
                             std::uint64_t max_bytes) {
  // FNV-1a over 8-byte words (the tail zero-padded): not cryptographic, but any change of a
  // byte changes it with near certainty. Words are counted from the file's start, whatever the
  // pieces the reads return.
  std::uint64_t h = 0xcbf29ce484222325ull;
  std::uint64_t word = 0;
  std::size_t filled = 0;  // bytes of `word` set
  const auto mix = [&] {
    h = (h ^ word) * 0x100000001b3ull;
    h ^= h >> 29;
    word = 0;
    filled = 0;
  };
  const std::uint64_t total =
      read_file_pieces(path, what, max_bytes, {}, [&](const char* data, std::size_t n) {
        for (std::size_t i = 0; i < n;) {
          const std::size_t take = std::min<std::size_t>(8 - filled, n - i);
          std::memcpy(reinterpret_cast<char*>(&word) + filled, data + i, take);
          filled += take;
          i += take;
          if (filled == 8) mix();
        }
      });
  if (filled > 0) mix();
  char out[48];
  std::snprintf(out, sizeof(out), "%llu:%016llx", static_cast<unsigned long long>(total),
                static_cast<unsigned long long>(h));
  return out;
}

}  // namespace pagor
