#pragma once
// For fuzz targets whose readers take paths: a per-process scratch directory, and the fuzzer's
// bytes written to a file in it.
#include <unistd.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>

namespace pagor::fuzz {

/// `<tmp>/pagor_fuzz_<name>_<pid>`, created.
inline std::filesystem::path make_scratch_directory(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() /
                 ("pagor_fuzz_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d;
}

/// Replaces `p` with `size` bytes of `data`.
inline void write_bytes(const std::filesystem::path& p, const char* data, std::size_t size) {
  std::ofstream(p, std::ios::binary | std::ios::trunc)
      .write(data, static_cast<std::streamsize>(size));
}

}  // namespace pagor::fuzz
