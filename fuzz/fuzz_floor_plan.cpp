// libFuzzer target: the floor-plan readers (SVG and JSON) on arbitrary bytes.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "pagor/errors.hpp"
#include "pagor/indoor/floor_plan.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    pagor::parse_floor_plan_svg(text, "fuzz.svg");
  } catch (const pagor::InputError&) {
  }
  try {
    pagor::parse_floor_plan_json(text, "fuzz.json");
  } catch (const pagor::InputError&) {
  }
  return 0;
}
