#pragma once
/// \file clouds.hpp
/// Point-cloud I/O: KITTI `.bin` scans with SemanticKITTI `.label` files, PCD and PLY.

#include <string>
#include <vector>

#include "pagor/types.hpp"

namespace pagor {

/// A cloud read from disk, with what was dropped on the way.
struct LoadedCloud {
  PointCloud cloud;                   ///< finite points only
  std::size_t dropped_nonfinite = 0;  ///< points removed because a coordinate was NaN or Inf
  std::vector<std::string> warnings;  ///< things worth telling the user; the cloud is usable
};

/// Reads a cloud by its extension: `.bin` (KITTI float32 x, y, z, reflectance), `.pcd` or `.ply`
/// (fields x, y, z, optional intensity, optional label). `labels_path`, when not empty, names a
/// SemanticKITTI `.label` file (one uint32 per point, same order) that supplies or replaces the
/// labels. Points with a non-finite coordinate are dropped and counted.
/// Throws InputError naming the file when it is missing, unreadable, malformed, empty, or when the
/// label count differs from the point count.
LoadedCloud load_cloud(const std::string& path, const std::string& labels_path = {});

/// Reads a KITTI `.bin` scan as stored (non-finite points included). Throws InputError.
PointCloud read_kitti_bin(const std::string& path);

/// Reads a SemanticKITTI `.label` file. Throws InputError.
std::vector<std::uint32_t> read_kitti_labels(const std::string& path);

/// Writes a KITTI `.bin` scan (reflectance 0 where the cloud has none). Throws InputError.
void write_kitti_bin(const PointCloud& cloud, const std::string& path);

/// Writes a SemanticKITTI `.label` file. Throws InputError.
void write_kitti_labels(const std::vector<std::uint32_t>& labels, const std::string& path);

/// Writes a cloud by extension: `.bin` (labels, if any, go to the same path with `.label`),
/// `.pcd` or `.ply` (binary, with intensity and label fields when present). Throws InputError.
void save_cloud(const PointCloud& cloud, const std::string& path);

/// Lower-case extension of a path including the dot, e.g. ".pcd"; empty if none.
std::string file_extension(const std::string& path);

}  // namespace pagor
