#pragma once
/// \file kitti.hpp
/// Reader for KITTI / SemanticKITTI sequences laid out as
/// `<root>/sequences/<seq>/{velodyne,labels,poses.txt,calib.txt}`.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "pagor/io/clouds.hpp"
#include "pagor/types.hpp"

namespace pagor {

/// One sequence: its ground-truth poses (left camera frame) and the LiDAR-to-camera calibration.
class KittiSequence {
 public:
  /// Opens `<root>/sequences/<sequence>`, reading `poses.txt` and `calib.txt`.
  /// Throws InputError naming the file and line when either is missing or malformed.
  KittiSequence(const std::string& root, const std::string& sequence);

  const std::string& root() const { return root_; }
  const std::string& sequence() const { return sequence_; }
  const std::string& directory() const { return dir_; }
  std::size_t pose_count() const { return poses_->size(); }

  /// `<dir>/velodyne/NNNNNN.bin`.
  std::string scan_path(int frame) const;
  /// `<dir>/labels/NNNNNN.label`.
  std::string label_path(int frame) const;
  /// Whether the frame has a label file.
  bool has_labels(int frame) const;

  /// Loads a frame's scan with its labels when the label file exists. Throws InputError.
  LoadedCloud load_frame(int frame) const;

  /// Pose of cam0 at `frame` in the cam0 frame of frame 0 (line `frame` of poses.txt).
  const Transform& camera_pose(int frame) const;
  /// Velodyne-to-cam0 transform `Tr` from calib.txt.
  const Transform& T_cam_velo() const { return T_cam_velo_; }

  /// Ground truth mapping source-scan points into the target scan's LiDAR frame:
  /// inv(Tr) * inv(P_target) * P_source * Tr. Throws InputError for a frame without a pose.
  Transform ground_truth(int source_frame, int target_frame) const;

 private:
  std::string root_, sequence_, dir_;
  std::shared_ptr<const std::vector<Transform>> poses_;  // shared by the sequence's openings
  Transform T_cam_velo_ = Transform::Identity();
};

/// Reads a pairs file: one `source target` pair of frame numbers per line; `#` starts a comment
/// to the end of its line, and blank lines are skipped. Throws InputError naming the file and line.
std::vector<std::pair<int, int>> read_pairs_file(const std::string& path);

/// Parses 12 numbers (a 3x4 row-major matrix) into a 4x4 transform.
Transform transform_from_3x4(const double* values);

}  // namespace pagor
