#pragma once
/// \file lzf.hpp
/// LZF decompression (the format of PCD `binary_compressed` bodies), written from the format
/// description: a stream of runs, each starting with a control byte `c`:
/// - `c < 32`: a literal run of `c + 1` bytes that follow;
/// - otherwise a back-reference: length `(c >> 5) + 2` (when `c >> 5 == 7`, a further byte is added
///   to the length), offset `((c & 31) << 8) + next byte + 1` bytes back into the output.

#include <cstddef>
#include <cstdint>

namespace pagor {

/// Decompresses `in` into `out`. Returns true iff the stream is well formed — every run and every
/// back-reference stays inside the input and the output — and it decodes to exactly `out_size`
/// bytes. Never reads or writes outside the two buffers.
bool lzf_decompress(const std::uint8_t* in, std::size_t in_size, std::uint8_t* out,
                    std::size_t out_size);

}  // namespace pagor
