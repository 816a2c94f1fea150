// libFuzzer target: LZF decompression. The first two bytes give the expected output size (up to
// 64 KiB); the rest is the compressed stream.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/lzf.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::size_t out_size = static_cast<std::size_t>(data[0]) | (std::size_t{data[1]} << 8);
  std::vector<std::uint8_t> out(out_size);
  pagor::lzf_decompress(data + 2, size - 2, out.data(), out.size());
  return 0;
}
