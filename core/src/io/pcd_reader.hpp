#pragma once
/// \file pcd_reader.hpp
/// The project's own PCD reader (DATA ascii, binary and binary_compressed), for bytes that come
/// from users: every count, size and offset is checked against the bytes actually there before
/// anything is allocated or read.

#include <string>
#include <string_view>

#include "pagor/types.hpp"

namespace pagor {

/// Parses a whole PCD file held in `bytes`. Reads fields x, y, z (required), intensity and label
/// (optional) of types I/U (1, 2, 4, 8 bytes) or F (4, 8 bytes); other fields are skipped, and a
/// field with COUNT > 1 contributes its first element. Labels must be integers in [0, 2^32 - 1].
/// Non-finite coordinates are kept (load_cloud drops them). Coordinates are read as doubles and
/// stored as float32 relative to the cloud's frame origin (cloud_frame.hpp: zero unless the cloud
/// lies far from the origin); `narrowing_loss`, when given, receives the largest rounding error
/// of a coordinate that this cost [m] (0 for float32 data near its origin).
/// Throws InputError whose message starts with `name` and says what is wrong and where (header
/// line, body line for ASCII, point index or byte counts for binary bodies).
PointCloud parse_pcd(std::string_view bytes, const std::string& name,
                     double* narrowing_loss = nullptr);

}  // namespace pagor
