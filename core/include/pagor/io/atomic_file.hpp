#pragma once
/// \file atomic_file.hpp
/// Writing files so that nothing is lost: a file is replaced only by a complete new version, and
/// an append adds complete lines or nothing. A failed or interrupted write leaves the previous
/// contents intact.

#include <cstdint>
#include <string>
#include <string_view>

namespace pagor {

/// Writes `bytes` to `path` atomically: into a temporary file in the same directory, flushed to
/// disk (fsync), then renamed over `path`. On any failure (no space, a file-size limit, no
/// permission) the temporary file is removed, `path` keeps its previous contents (or stays
/// absent), and InputError says so, naming `path`. Callers should ignore SIGXFSZ so that a
/// file-size limit is an error rather than a signal.
void write_file_atomic(const std::string& path, std::string_view bytes);

/// A file that grows by whole lines only (results written as they come, e.g. one JSON line per
/// pair). Each append is written and flushed to disk; if it cannot be written completely the
/// file is cut back to its previous size and InputError says so.
class LineAppender {
 public:
  /// Opens (creating if needed) `path` for appending. A last line without its newline — left by a
  /// process killed mid-write before this class existed — is cut off first. Throws InputError.
  explicit LineAppender(const std::string& path);
  ~LineAppender();
  LineAppender(const LineAppender&) = delete;
  LineAppender& operator=(const LineAppender&) = delete;

  /// Appends `line` and a newline (`line` must not contain one). Throws InputError.
  void append(std::string_view line);

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

/// A file beside `path` whose name is `path`'s name with `suffix` added (".partial", ".lock"),
/// kept within the 255 bytes a file name may have: when the name would be longer, its start is
/// kept and the rest replaced by a hash of the whole name, so the same `path` always gives the
/// same sibling and different paths different ones.
std::string sibling_path(const std::string& path, const std::string& suffix);

/// FNV-1a 64-bit hash of `bytes` as 16 hex digits: a stable fingerprint (e.g. of a configuration).
std::string fingerprint(std::string_view bytes);

}  // namespace pagor
