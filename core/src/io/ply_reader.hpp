#pragma once
/// \file ply_reader.hpp
/// The project's own PLY reader (ascii, binary_little_endian, binary_big_endian), for bytes that
/// come from users: element counts, list lengths and record sizes are checked against the bytes
/// actually there before anything is allocated or read.

#include <string>
#include <string_view>

#include "pagor/types.hpp"

namespace pagor {

/// Parses a whole PLY file held in `bytes`: the `vertex` element's scalar properties x, y, z
/// (required), intensity and label (optional); other properties (lists included) and the elements
/// after `vertex` are skipped, elements before it are stepped over with bounds checks. Labels must
/// be integers in [0, 2^32 - 1]. Coordinates of a kind wider than float32 (double, 32- and 64-bit
/// integers) are stored relative to the cloud's frame origin (cloud_frame.hpp), as in parse_pcd,
/// with the largest rounding error in `narrowing_loss` [m]; float32 ones as they are.
/// Throws InputError whose message starts with `name` and says what is wrong and where (header
/// line, element and record).
PointCloud parse_ply(std::string_view bytes, const std::string& name,
                     double* narrowing_loss = nullptr);

}  // namespace pagor
