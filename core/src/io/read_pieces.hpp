#pragma once
/// \file read_pieces.hpp
/// Reading a file in pieces, with file_input.hpp's checks: for the binary readers, which turn the
/// bytes into their arrays as they come (no copy of the whole file). Internal to the core.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace pagor {

/// Largest piece read_file_pieces hands over [bytes].
constexpr std::size_t kFilePieceBytes = std::size_t{64} << 10;

/// Opens `path` as read_file does (the same checks and errors), calls `opened(size)` with its
/// size as opened (when given; the file may still grow or shrink), then `consume(bytes, n)` for
/// each piece of at most kFilePieceBytes, in order. Returns the bytes read. Throws InputError as
/// read_file does, also when the file grows beyond `max_bytes` while read.
std::uint64_t read_file_pieces(const std::string& path, const std::string& what,
                               std::uint64_t max_bytes,
                               const std::function<void(std::uint64_t size)>& opened,
                               const std::function<void(const char*, std::size_t)>& consume);

}  // namespace pagor
