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
  std::size_t dropped_far = 0;  ///< points removed lying more than 10^6 m from the cloud's centre
  std::vector<std::string> warnings;  ///< things worth telling the user; the cloud is usable
};

/// Reads a cloud by its extension: `.bin` (KITTI float32 x, y, z, reflectance), `.pcd` or `.ply`
/// (fields x, y, z, optional intensity, optional label). `labels_path`, when not empty, names a
/// SemanticKITTI `.label` file (one uint32 per point, same order) that supplies or replaces the
/// labels. Points with a non-finite coordinate, or one more than 10^6 m from the cloud's frame
/// origin (a corrupt point such as 1e30), are dropped and counted, with a warning naming the file.
/// A cloud whose median point lies more than 1 km from the file's origin (georeferenced data) is
/// kept relative to a frame origin near its points (`cloud.origin`, types.hpp), chosen before
/// the coordinates are narrowed to float32 (PCD and PLY doubles keep their precision; a warning
/// says how much was lost when a coordinate rounds by more than 1 mm).
/// Throws InputError naming the file when it is missing, not a regular file, larger than
/// kMaxCloudFileBytes (file_input.hpp), unreadable, malformed, empty, or when the label count
/// differs from the point count.
LoadedCloud load_cloud(const std::string& path, const std::string& labels_path = {});

/// `T_target_source` between the clouds' own frames (their `origin`s: types.hpp) from one between
/// the frames of their files: the transform the pipeline works with. Unchanged when both origins
/// are zero.
Transform to_cloud_frames(const Transform& T_files, const Eigen::Vector3d& source_origin,
                          const Eigen::Vector3d& target_origin);

/// The inverse of to_cloud_frames: a transform between the files' frames, as results report it.
Transform to_file_frames(const Transform& T_clouds, const Eigen::Vector3d& source_origin,
                         const Eigen::Vector3d& target_origin);

/// Reads a KITTI `.bin` scan as stored (non-finite points included). Throws InputError.
PointCloud read_kitti_bin(const std::string& path);

/// Reads a SemanticKITTI `.label` file. Throws InputError.
std::vector<std::uint32_t> read_kitti_labels(const std::string& path);

/// Writes a KITTI `.bin` scan (reflectance 0 where the cloud has none). Throws InputError.
void write_kitti_bin(const PointCloud& cloud, const std::string& path);

/// Writes a SemanticKITTI `.label` file. Throws InputError.
void write_kitti_labels(const std::vector<std::uint32_t>& labels, const std::string& path);

/// Writes a cloud by extension: `.bin` (labels, if any, go to the same path with `.label`),
/// `.pcd` or `.ply` (binary, with intensity and label fields when present), each file whole or
/// not at all (atomic_file.hpp). Points are written in the cloud's frame (its `origin` is not
/// added). Throws InputError.
void save_cloud(const PointCloud& cloud, const std::string& path);

/// Lower-case extension of a path including the dot, e.g. ".pcd"; empty if none.
std::string file_extension(const std::string& path);

}  // namespace pagor
