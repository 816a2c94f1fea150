#include "pagor/eval/pair_set.hpp"

#include <Eigen/LU>
#include <cstdio>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "pagor/errors.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/io/file_input.hpp"
#include "pagor/io/kitti.hpp"

namespace pagor {
namespace fs = std::filesystem;
namespace {

// Tolerance of the rigid-transform check: |R^T R - I| and |det R - 1|.
constexpr double kRigidTolerance = 1e-3;

// The lines of a text file (regular files only, size-limited: file_input.hpp).
std::vector<std::string> text_lines(const std::string& path, const char* what) {
  std::istringstream in(read_file(path, what, kMaxTextFileBytes));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(std::move(line));
  return lines;
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

// A word of a manifest line; `eq` is the position of its first '=' outside quotes (npos: none).
struct ManifestWord {
  std::string text;
  std::size_t eq = std::string::npos;
};

// Splits a manifest line into words at blanks outside double quotes; inside quotes a backslash
// makes the next '"' or backslash literal. A word starting with an unquoted '#' ends the line.
std::vector<ManifestWord> manifest_words(const std::string& line, const std::string& where) {
  std::vector<ManifestWord> out;
  std::size_t i = 0;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    if (i >= line.size() || line[i] == '#') break;
    ManifestWord w;
    bool quoted = false;
    for (; i < line.size() && (quoted || !blank(line[i])); ++i) {
      const char c = line[i];
      if (c == '"') {
        quoted = !quoted;
      } else if (quoted && c == '\\' && i + 1 < line.size() &&
                 (line[i + 1] == '"' || line[i + 1] == '\\')) {
        w.text += line[++i];
      } else {
        if (c == '=' && !quoted && w.eq == std::string::npos) w.eq = w.text.size();
        w.text += c;
      }
    }
    if (quoted) throw InputError(where + ": a quoted path is not closed (a '\"' is missing)");
    out.push_back(std::move(w));
  }
  return out;
}

// The pair a manifest line's words describe (its name left empty when the line gives none).
PairEntry manifest_entry(const std::string& path, const std::vector<ManifestWord>& words,
                         const std::string& where) {
  PairEntry e;
  e.origin = where;
  e.source.kind = PairSource::Kind::files;
  e.source.source = resolve(path, words[0].text);
  e.source.target = resolve(path, words[1].text);
  for (std::size_t k = 2; k < words.size(); ++k) {
    const std::string& w = words[k].text;
    const std::size_t eq = words[k].eq;
    if (eq == std::string::npos || eq == 0 || eq + 1 == w.size())
      throw InputError(where + ": '" + w + "' is not a key=value option");
    const std::string key = w.substr(0, eq), value = w.substr(eq + 1);
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
  return e;
}

// What a manifest pair reads, by file identity (symbolic links and "./" resolved), and whether
// it is a negative: two lines with the same identity are the same pair.
std::vector<std::string> identity(const PairEntry& e) {
  std::vector<std::string> id;
  for (const std::string* f : {&e.source.source, &e.source.target, &e.source.source_labels,
                               &e.source.target_labels, &e.source.ground_truth}) {
    std::error_code ec;
    const fs::path canonical = f->empty() ? fs::path() : fs::weakly_canonical(*f, ec);
    id.push_back(ec ? *f : canonical.string());
  }
  id.push_back(e.negative ? "negative" : "");
  id.push_back(e.source.label_scheme);
  return id;
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

std::string transform_file_text(const Transform& T) {
  std::string text;
  char row[128];
  for (int r = 0; r < 4; ++r) {
    std::snprintf(row, sizeof(row), "%.17g %.17g %.17g %.17g\n", T(r, 0), T(r, 1), T(r, 2),
                  T(r, 3));
    text += row;
  }
  return text;
}

Transform read_transform_file(const std::string& path) {
  std::vector<double> values;
  std::string token;
  int line_no = 0, last_line = 0;
  for (const std::string& line : text_lines(path, "transform file")) {
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
  PairSet set;
  set.origin = path;
  std::map<std::string, int> name_line;          // name -> line that used it
  std::map<std::vector<std::string>, int> same;  // what a pair reads -> line
  int line_no = 0;
  for (const std::string& line : text_lines(path, "manifest")) {
    ++line_no;
    const std::string where = path + ":" + std::to_string(line_no);
    const std::vector<ManifestWord> words = manifest_words(line, where);
    if (words.empty()) continue;
    if (words.size() < 2 || words[0].eq != std::string::npos || words[1].eq != std::string::npos)
      throw InputError(
          where +
          ": expected 'SOURCE TARGET [gt=FILE] [source_labels=FILE] "
          "[target_labels=FILE] [scheme=NAME] [name=TEXT] [overlap=no]' (quote a path with "
          "spaces: \"my scan.pcd\")");
    PairEntry e = manifest_entry(path, words, where);
    e.name = e.name.empty() ? std::to_string(line_no) : e.name;
    if (const auto [it, fresh] = name_line.emplace(e.name, line_no); !fresh)
      throw InputError(where + ": the name '" + e.name + "' is already used by line " +
                       std::to_string(it->second) + "; every pair needs its own name");
    if (const auto [it, fresh] = same.emplace(identity(e), line_no); !fresh)
      throw InputError(where + ": the same pair as line " + std::to_string(it->second) +
                       " (the same files, perhaps spelled another way)");
    set.pairs.push_back(std::move(e));
  }
  if (set.pairs.empty()) throw InputError(path + ": no pairs");
  return set;
}

std::string pair_fingerprint(const PairEntry& e) {
  const PairSource& s = e.source;
  std::string id = "name=" + e.name + (e.negative ? "\nnegative" : "") + "\n";
  if (!s.label_scheme.empty()) id += "scheme=" + s.label_scheme + "\n";
  const auto file = [&](const char* role, const std::string& path, const char* what,
                        std::uint64_t max_bytes) {
    id += std::string(role) + "=" + (path.empty() ? "-" : file_fingerprint(path, what, max_bytes));
    id += "\n";
  };
  switch (s.kind) {
    case PairSource::Kind::files:
      file("source", s.source, "point cloud", kMaxCloudFileBytes);
      file(is_floor_plan_path(s.target) ? "plan" : "target", s.target, "target",
           kMaxCloudFileBytes);
      file("source_labels", s.source_labels, "label file", kMaxCloudFileBytes);
      file("target_labels", s.target_labels, "label file", kMaxCloudFileBytes);
      break;
    case PairSource::Kind::kitti: {
      const KittiSequence seq(s.kitti_root, s.sequence);
      file("poses", seq.directory() + "/poses.txt", "poses file", kMaxTextFileBytes);
      file("calib", seq.directory() + "/calib.txt", "calibration file", kMaxTextFileBytes);
      file("source", seq.scan_path(s.source_frame), "scan", kMaxCloudFileBytes);
      file("target", seq.scan_path(s.target_frame), "scan", kMaxCloudFileBytes);
      for (const auto& [role, frame] :
           {std::pair{"source_labels", s.source_frame}, std::pair{"target_labels", s.target_frame}})
        file(role, seq.has_labels(frame) ? seq.label_path(frame) : "", "label file",
             kMaxCloudFileBytes);
      id +=
          "frames=" + std::to_string(s.source_frame) + " " + std::to_string(s.target_frame) + "\n";
      break;
    }
    case PairSource::Kind::synthetic:
      id += "synthetic=" + std::to_string(s.synthetic_seed) + "\n";
      break;
  }
  file("ground_truth", s.ground_truth, "transform file", kMaxTextFileBytes);
  return fingerprint(id);
}

PairSet kitti_pair_set(const std::string& kitti_root, const std::string& sequence,
                       const std::string& pairs_file) {
  PairSet set;
  set.origin = pairs_file;
  const KittiSequence seq(kitti_root, sequence);  // a broken poses.txt or calib.txt fails here
  std::set<std::pair<int, int>> seen;
  for (const auto& [s, t] : read_pairs_file(pairs_file)) {
    if (!seen.insert({s, t}).second)
      throw InputError(pairs_file + ": the pair " + std::to_string(s) + " " + std::to_string(t) +
                       " is listed twice; every pair needs its own line");
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
