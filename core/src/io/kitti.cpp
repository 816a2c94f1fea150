#include "pagor/io/kitti.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <string_view>

#include "io/parse_numbers.hpp"
#include "pagor/errors.hpp"
#include "pagor/io/file_input.hpp"

namespace pagor {
namespace {

// Largest deviation of R^T R from the identity, and of det R from 1, accepted in a pose or Tr.
constexpr double kRotationTolerance = 1e-3;

std::string frame_name(int frame) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%06d", frame);
  return buf;
}

// The text of a KITTI file (regular files only, size-limited: file_input.hpp), to read by lines.
std::istringstream open_text(const std::string& path, const char* what) {
  return std::istringstream(read_file(path, what, kMaxTextFileBytes));
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t b = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

// Twelve finite numbers forming a rigid 3x4 transform [R | t] (R orthonormal with det +1, to
// the precision KITTI's files are written with). `where()` is "file:line: what", made only for
// an error (a sequence's poses file has thousands of lines).
template <class Where>
Transform rigid_3x4(const std::vector<std::string_view>& w, const Where& where) {
  if (w.size() != 12)
    throw InputError(where() + " needs 12 numbers (a 3x4 transform), got " +
                     std::to_string(w.size()));
  double v[12];
  for (int k = 0; k < 12; ++k) {
    const auto x = parse::to_double(w[static_cast<std::size_t>(k)]);
    if (!x || !std::isfinite(*x))
      throw InputError(where() + ": value " + std::to_string(k + 1) + " is not a finite number");
    v[k] = *x;
  }
  const Transform T = transform_from_3x4(v);
  const Eigen::Matrix3d R = T.block<3, 3>(0, 0);
  const double orth = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(orth <= kRotationTolerance) || !(std::abs(R.determinant() - 1.0) <= kRotationTolerance))
    throw InputError(where() + " is not a rigid transform (its rotation part is not orthonormal " +
                     "with determinant 1)");
  return T;
}

// The poses of `path`, read in place line by line.
std::vector<Transform> read_poses(const std::string& path) {
  const std::string text = read_file(path, "poses file", kMaxTextFileBytes);
  std::vector<Transform> poses;
  poses.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
  int line_no = 0;
  for (std::size_t begin = 0; begin < text.size();) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    ++line_no;
    const auto w = split_words(std::string_view(text).substr(begin, end - begin));
    begin = end + 1;
    if (w.empty()) continue;
    poses.push_back(
        rigid_3x4(w, [&] { return path + ":" + std::to_string(line_no) + ": the pose"; }));
  }
  if (poses.empty()) throw InputError(path + ": no poses");
  return poses;
}

// The poses of `path`, parsed once a process for each content the file has had (known by its
// fingerprint, read in small pieces): a set of KITTI pairs opens the sequence for every pair, and
// parsing 4,541 poses took 5 ms.
std::shared_ptr<const std::vector<Transform>> poses_of(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const std::vector<Transform>>> parsed;
  const std::string key = path + "\n" + file_fingerprint(path, "poses file", kMaxTextFileBytes);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto it = parsed.find(key);
    if (it != parsed.end()) return it->second;
  }
  auto poses = std::make_shared<const std::vector<Transform>>(read_poses(path));
  const std::lock_guard<std::mutex> lock(mutex);
  return parsed.emplace(key, std::move(poses)).first->second;
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

  poses_ = poses_of(dir_ + "/poses.txt");

  const std::string calib_path = dir_ + "/calib.txt";
  std::istringstream calib = open_text(calib_path, "calibration file");
  std::string line;
  int line_no = 0;
  bool found = false;
  while (std::getline(calib, line)) {
    ++line_no;
    if (line.rfind("Tr:", 0) != 0) continue;
    T_cam_velo_ = rigid_3x4(split_words(std::string_view(line).substr(3)),
                            [&] { return calib_path + ":" + std::to_string(line_no) + ": Tr"; });
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
  if (frame < 0 || static_cast<std::size_t>(frame) >= poses_->size())
    throw InputError(dir_ + "/poses.txt: no pose for frame " + std::to_string(frame) + " (" +
                     std::to_string(poses_->size()) + " poses)");
  return (*poses_)[static_cast<std::size_t>(frame)];
}

Transform KittiSequence::ground_truth(int source_frame, int target_frame) const {
  const Transform& P_s = camera_pose(source_frame);
  const Transform& P_t = camera_pose(target_frame);
  return T_cam_velo_.inverse() * P_t.inverse() * P_s * T_cam_velo_;
}

std::vector<std::pair<int, int>> read_pairs_file(const std::string& path) {
  std::istringstream in = open_text(path, "pairs file");
  std::vector<std::pair<int, int>> pairs;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto w = split_words(line);
    const std::string at = path + ":" + std::to_string(line_no);
    if (w.size() != 2)
      throw InputError(at + ": expected two frame numbers 'source target', got " +
                       std::to_string(w.size()) + " words");
    int frames[2];
    for (int k = 0; k < 2; ++k) {
      const auto f = parse::to_uint(w[static_cast<std::size_t>(k)]);
      if (!f || *f > 999999)  // frame files are named with six digits
        throw InputError(at + ": expected two frame numbers 'source target', but '" +
                         std::string(w[static_cast<std::size_t>(k)].substr(0, 40)) +
                         "' is not a frame number (an integer in [0, 999999])");
      frames[k] = static_cast<int>(*f);
    }
    pairs.emplace_back(frames[0], frames[1]);
  }
  if (pairs.empty()) throw InputError(path + ": no pairs");
  return pairs;
}

}  // namespace pagor
