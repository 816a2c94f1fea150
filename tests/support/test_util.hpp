#pragma once
// Helpers shared by the tests.

#include <filesystem>
#include <random>
#include <string>

#include "pagor/errors.hpp"

namespace pagor::test {

/// Whether this build runs under AddressSanitizer: tests whose brute-force references are
/// exponential run fewer random cases there (same code paths, a fraction of the time).
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#elif defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

/// The message of the InputError that `f()` throws, or "no error".
template <class F>
std::string input_error_of(const F& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// A fresh directory under the system temp dir, removed when it goes out of scope.
class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() / ("pagor_test_" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

/// The shared KITTI data used by the tests on real scans.
inline std::string kitti_root() {
  return PAGOR_KITTI_DIR;
}

}  // namespace pagor::test
