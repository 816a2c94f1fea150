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
#include "scratch.hpp"
#include "state/app_state.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  static const std::string path =
      (pagor::fuzz::make_scratch_directory("session") / "session.json").string();
  pagor::fuzz::write_bytes(path, reinterpret_cast<const char*>(bytes), size);
  pagor::studio::AppState state;
  try {
    pagor::studio::load_session(path, state);
  } catch (const pagor::Error&) {
  }
  return 0;
}
