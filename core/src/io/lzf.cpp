#include "io/lzf.hpp"

namespace pagor {

bool lzf_decompress(const std::uint8_t* in, std::size_t in_size, std::uint8_t* out,
                    std::size_t out_size) {
  std::size_t ip = 0, op = 0;
  while (ip < in_size) {
    const unsigned ctrl = in[ip++];
    if (ctrl < 32) {  // literal run
      const std::size_t len = ctrl + 1;
      if (len > in_size - ip || len > out_size - op) return false;
      for (std::size_t k = 0; k < len; ++k) out[op++] = in[ip++];
      continue;
    }
    std::size_t len = ctrl >> 5;
    if (len == 7) {
      if (ip >= in_size) return false;
      len += in[ip++];
    }
    len += 2;
    if (ip >= in_size) return false;
    const std::size_t back = ((ctrl & 31u) << 8) + in[ip++] + 1;
    if (back > op || len > out_size - op) return false;
    // Byte by byte: a reference may overlap the bytes it produces (run-length repeats).
    for (std::size_t k = 0; k < len; ++k, ++op) out[op] = out[op - back];
  }
  return op == out_size;
}

}  // namespace pagor
