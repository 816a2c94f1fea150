// libFuzzer target: the PLY reader on arbitrary bytes.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "pagor/errors.hpp"
#include "io/ply_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    pagor::parse_ply(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.ply");
  } catch (const pagor::InputError&) {
  }
  return 0;
}
