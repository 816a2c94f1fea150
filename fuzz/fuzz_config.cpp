// libFuzzer target: configuration JSON (depth-limited parse, checked numbers, validation).
#include <cstddef>
#include <cstdint>
#include <string>

#include "pagor/config.hpp"
#include "pagor/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const pagor::Config c =
        pagor::parse_config(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
    pagor::config_to_json(c);
  } catch (const pagor::Error&) {
  }
  return 0;
}
