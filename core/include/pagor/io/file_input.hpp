#pragma once
/// \file file_input.hpp
/// Reading the files users name, bounded: only regular files (a FIFO, a device such as
/// /dev/zero or a socket could block or never end), and no more bytes than a limit that suits
/// the kind of file. Every failure is an InputError naming the file.

#include <cstdint>
#include <string>

namespace pagor {

/// Largest point-cloud or label file the readers take: 4 GiB (2.7·10^8 KITTI points) [bytes].
constexpr std::uint64_t kMaxCloudFileBytes = std::uint64_t{4} << 30;
/// Largest text file the readers take (configurations, manifests, pairs, poses and calibration
/// files, transforms, floor plans, sessions): 64 MiB [bytes].
constexpr std::uint64_t kMaxTextFileBytes = std::uint64_t{64} << 20;
/// Largest results file of `pagor bench --out` the readers take: 1 GiB [bytes].
constexpr std::uint64_t kMaxResultsFileBytes = std::uint64_t{1} << 30;

/// The whole of the regular file `path`. `what` names the kind of file in messages ("config
/// file"). Throws InputError "<path>: ..." when the file does not exist, is a directory or not a
/// regular file, cannot be read, or holds more than `max_bytes` (the limit is named).
std::string read_file(const std::string& path, const std::string& what, std::uint64_t max_bytes);

/// A fingerprint of the content of the regular file `path`: its size and a 64-bit hash of its
/// bytes, as text ("2048:0123456789abcdef"), read in pieces (memory stays small). Equal contents
/// give equal fingerprints wherever the files are. Throws InputError as read_file does.
std::string file_fingerprint(const std::string& path, const std::string& what,
                             std::uint64_t max_bytes);

}  // namespace pagor
