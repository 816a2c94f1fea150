#include "pagor/sets/pair_set.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pagor/errors.hpp"
#include "pagor/io/kitti.hpp"

namespace pagor {
namespace fs = std::filesystem;
namespace {

// Tolerance of the rigid-transform check: |R^T R - I| and |det R - 1|.
constexpr double kRigidTolerance = 1e-3;

std::ifstream open_text(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": does not exist");
  if (fs::is_directory(path, ec)) throw InputError(path + ": is a directory, not a file");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open for reading");
  return in;
}

bool blank_or_comment(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#';
}

// `relative` taken against the manifest's directory (absolute paths stay as they are).
std::string resolve(const std::string& manifest, const std::string& relative) {
  const fs::path p(relative);
  if (p.is_absolute()) return relative;
  return (fs::path(manifest).parent_path() / p).lexically_normal().string();
}

}  // namespace

void check_rigid(const Transform& T, const std::string& where) {
  if (!T.allFinite()) throw InputError(where + ": not all entries are finite numbers");
  if ((T.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9)
    throw InputError(where + ": the last row is not (0 0 0 1); expected a 4x4 rigid transform");
  const Eigen::Matrix3d R = T.block<3, 3>(0, 0);
  const double orthonormality = (R.transpose() * R - Eigen::Matrix3d::Identity()).norm();
  if (orthonormality > kRigidTolerance)
    throw InputError(where + ": the rotation part is not orthonormal (|R^T R - I| = " +
                     std::to_string(orthonormality) + "); expected a rigid transform");
  if (std::abs(R.determinant() - 1.0) > kRigidTolerance)
    throw InputError(where + ": the rotation part has determinant " +
                     std::to_string(R.determinant()) + " (a reflection?); expected +1");
}

Transform read_transform_file(const std::string& path) {
  std::ifstream in = open_text(path);
  std::vector<double> values;
  std::string line, token;
  int line_no = 0, last_line = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (blank_or_comment(line)) continue;
    std::istringstream ss(line);
    while (ss >> token) {
      std::size_t used = 0;
      double v = 0;
      try {
        v = std::stod(token, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != token.size() || !std::isfinite(v))
        throw InputError(path + ":" + std::to_string(line_no) + ": '" + token +
                         "' is not a finite number");
      if (values.size() == 16)
        throw InputError(path + ":" + std::to_string(line_no) +
                         ": more than 16 numbers; expected a 4x4 matrix");
      values.push_back(v);
      last_line = line_no;
    }
  }
  if (values.size() != 12 && values.size() != 16)
    throw InputError(path + ": " + std::to_string(values.size()) +
                     " numbers; expected a 4x4 matrix (16, row-major) or its top 3x4 rows (12)");
  Transform T = Transform::Identity();
  for (std::size_t i = 0; i < values.size(); ++i)
    T(static_cast<int>(i / 4), static_cast<int>(i % 4)) = values[i];
  check_rigid(T, path + ":" + std::to_string(last_line));
  return T;
}

PairSet read_pair_manifest(const std::string& path) {
  std::ifstream in = open_text(path);
  PairSet set;
  set.origin = path;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (blank_or_comment(line)) continue;
    const std::string where = path + ":" + std::to_string(line_no);
    std::istringstream ss(line);
    std::vector<std::string> words;
    for (std::string w; ss >> w;) {
      if (w[0] == '#') break;
      words.push_back(w);
    }
    if (words.size() < 2 || words[0].find('=') != std::string::npos ||
        words[1].find('=') != std::string::npos)
      throw InputError(where +
                       ": expected 'SOURCE TARGET [gt=FILE] [source_labels=FILE] "
                       "[target_labels=FILE] [scheme=NAME] [name=TEXT] [overlap=no]'");
    PairEntry e;
    e.origin = where;
    e.name = std::to_string(line_no);
    e.source.kind = PairSource::Kind::files;
    e.source.source = resolve(path, words[0]);
    e.source.target = resolve(path, words[1]);
    for (std::size_t k = 2; k < words.size(); ++k) {
      const auto eq = words[k].find('=');
      if (eq == std::string::npos || eq == 0 || eq + 1 == words[k].size())
        throw InputError(where + ": '" + words[k] + "' is not a key=value option");
      const std::string key = words[k].substr(0, eq), value = words[k].substr(eq + 1);
      if (key == "gt")
        e.source.ground_truth = resolve(path, value);
      else if (key == "source_labels")
        e.source.source_labels = resolve(path, value);
      else if (key == "target_labels")
        e.source.target_labels = resolve(path, value);
      else if (key == "name")
        e.name = value;
      else if (key == "scheme") {
        try {
          builtin_label_scheme(value);
        } catch (const ConfigError& error) {
          throw InputError(where + ": scheme: " + error.what());
        }
        e.source.label_scheme = value;
      } else if (key == "overlap") {
        if (value != "no" && value != "yes")
          throw InputError(where + ": overlap must be 'yes' or 'no', not '" + value + "'");
        e.negative = value == "no";
      } else
        throw InputError(where + ": unknown key '" + key +
                         "' (known: gt, source_labels, target_labels, scheme, name, overlap)");
    }
    if (e.negative && !e.source.ground_truth.empty())
      throw InputError(where + ": a pair with overlap=no cannot have a ground truth (gt=)");
    for (const std::string* f : {&e.source.source, &e.source.target, &e.source.source_labels,
                                 &e.source.target_labels, &e.source.ground_truth}) {
      std::error_code ec;
      if (!f->empty() && !fs::is_regular_file(*f, ec))
        throw InputError(where + ": " + *f + " does not exist");
    }
    set.pairs.push_back(std::move(e));
  }
  if (set.pairs.empty()) throw InputError(path + ": no pairs");
  return set;
}

PairSet kitti_pair_set(const std::string& kitti_root, const std::string& sequence,
                       const std::string& pairs_file) {
  PairSet set;
  set.origin = pairs_file;
  const KittiSequence seq(kitti_root, sequence);  // a broken poses.txt or calib.txt fails here
  for (const auto& [s, t] : read_pairs_file(pairs_file)) {
    if (static_cast<std::size_t>(std::max(s, t)) >= seq.pose_count())
      throw InputError(pairs_file + ": frame " + std::to_string(std::max(s, t)) +
                       " has no pose in " + seq.directory() + "/poses.txt (" +
                       std::to_string(seq.pose_count()) + " poses)");
    PairEntry e;
    e.name = std::to_string(s) + " -> " + std::to_string(t);
    e.origin = pairs_file;
    e.source.kind = PairSource::Kind::kitti;
    e.source.kitti_root = kitti_root;
    e.source.sequence = sequence;
    e.source.source_frame = s;
    e.source.target_frame = t;
    set.pairs.push_back(std::move(e));
  }
  return set;
}

}  // namespace pagor
