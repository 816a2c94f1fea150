// libFuzzer target: the PCD reader on arbitrary bytes. Any outcome but a clean cloud or an
// InputError (a crash, a sanitizer report, a hang, a huge allocation) is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "pagor/errors.hpp"
#include "io/pcd_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    pagor::parse_pcd(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.pcd");
  } catch (const pagor::InputError&) {
  }
  return 0;
}
