// libFuzzer target: the studio's session file (strict reader: types, ranges, unknown keys, the
// embedded configuration, relative paths). The reader takes a path, so the bytes go to a
// per-process scratch file.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "pagor/errors.hpp"
#include "state/app_state.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  static const std::string path = (std::filesystem::temp_directory_path() /
                                   ("pagor_fuzz_session_" + std::to_string(::getpid()) + ".json"))
                                      .string();
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(bytes), static_cast<std::streamsize>(size));
  pagor::studio::AppState state;
  try {
    pagor::studio::load_session(path, state);
  } catch (const pagor::Error&) {
  }
  return 0;
}
