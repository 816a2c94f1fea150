#include "pagor/kitti.hpp"

#include <Eigen/LU>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pagor/errors.hpp"

namespace pagor {
namespace {

std::string frame_name(int frame) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%06d", frame);
  return buf;
}

std::ifstream open_text(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": does not exist");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open for reading");
  return in;
}

}  // namespace

Transform transform_from_3x4(const double* v) {
  Transform T = Transform::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) T(r, c) = v[4 * r + c];
  return T;
}

KittiSequence::KittiSequence(const std::string& root, const std::string& sequence)
    : root_(root), sequence_(sequence) {
  dir_ = (std::filesystem::path(root) / "sequences" / sequence).string();
  std::error_code ec;
  if (!std::filesystem::is_directory(dir_, ec))
    throw InputError(dir_ + ": no such sequence directory (expected <root>/sequences/<seq>)");

  const std::string poses_path = dir_ + "/poses.txt";
  std::ifstream poses = open_text(poses_path);
  std::string line;
  int line_no = 0;
  while (std::getline(poses, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream ss(line);
    double v[12];
    for (double& x : v)
      if (!(ss >> x))
        throw InputError(poses_path + ":" + std::to_string(line_no) +
                         ": expected 12 numbers (a 3x4 pose)");
    poses_.push_back(transform_from_3x4(v));
  }
  if (poses_.empty()) throw InputError(poses_path + ": no poses");

  const std::string calib_path = dir_ + "/calib.txt";
  std::ifstream calib = open_text(calib_path);
  line_no = 0;
  bool found = false;
  while (std::getline(calib, line)) {
    ++line_no;
    if (line.rfind("Tr:", 0) != 0) continue;
    std::istringstream ss(line.substr(3));
    double v[12];
    for (double& x : v)
      if (!(ss >> x))
        throw InputError(calib_path + ":" + std::to_string(line_no) +
                         ": Tr needs 12 numbers (a 3x4 transform)");
    T_cam_velo_ = transform_from_3x4(v);
    found = true;
  }
  if (!found) throw InputError(calib_path + ": no 'Tr:' line (Velodyne-to-cam0 transform)");
}

std::string KittiSequence::scan_path(int frame) const {
  return dir_ + "/velodyne/" + frame_name(frame) + ".bin";
}

std::string KittiSequence::label_path(int frame) const {
  return dir_ + "/labels/" + frame_name(frame) + ".label";
}

bool KittiSequence::has_labels(int frame) const {
  std::error_code ec;
  return std::filesystem::exists(label_path(frame), ec);
}

LoadedCloud KittiSequence::load_frame(int frame) const {
  if (frame < 0) throw InputError("frame " + std::to_string(frame) + ": frame numbers start at 0");
  const bool labelled = has_labels(frame);
  LoadedCloud out = load_cloud(scan_path(frame), labelled ? label_path(frame) : "");
  if (!labelled)
    out.warnings.push_back(label_path(frame) + ": no label file; the scan has no semantic labels");
  return out;
}

const Transform& KittiSequence::camera_pose(int frame) const {
  if (frame < 0 || static_cast<std::size_t>(frame) >= poses_.size())
    throw InputError(dir_ + "/poses.txt: no pose for frame " + std::to_string(frame) + " (" +
                     std::to_string(poses_.size()) + " poses)");
  return poses_[static_cast<std::size_t>(frame)];
}

Transform KittiSequence::ground_truth(int source_frame, int target_frame) const {
  const Transform& P_s = camera_pose(source_frame);
  const Transform& P_t = camera_pose(target_frame);
  return T_cam_velo_.inverse() * P_t.inverse() * P_s * T_cam_velo_;
}

std::vector<std::pair<int, int>> read_pairs_file(const std::string& path) {
  std::ifstream in = open_text(path);
  std::vector<std::pair<int, int>> pairs;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream ss(line);
    int s = -1, t = -1;
    if (!(ss >> s >> t) || s < 0 || t < 0)
      throw InputError(path + ":" + std::to_string(line_no) +
                       ": expected two frame numbers 'source target'");
    pairs.emplace_back(s, t);
  }
  if (pairs.empty()) throw InputError(path + ": no pairs");
  return pairs;
}

}  // namespace pagor
