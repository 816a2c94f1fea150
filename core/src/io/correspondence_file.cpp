#include "pagor/io/correspondence_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "pagor/errors.hpp"
#include "pagor/io/file_input.hpp"

namespace pagor {
namespace {

// Splits a line (comment removed) into fields separated by blanks or commas.
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char ch : line) {
    if (ch == ' ' || ch == '\t' || ch == ',' || ch == '\r') {
      if (!cur.empty()) out.push_back(std::move(cur));
      cur.clear();
    } else {
      cur.push_back(ch);
    }
  }
  if (!cur.empty()) out.push_back(std::move(cur));
  return out;
}

double number(const std::string& field, const std::string& where, const char* what) {
  const char* begin = field.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    throw InputError(where + ": " + what + " '" + field + "' is not a finite number");
  return v;
}

}  // namespace

CorrespondenceFile parse_correspondence_file(const std::string& text, const std::string& origin) {
  static const char* const names[] = {"px", "py", "pz", "qx", "qy", "qz"};
  CorrespondenceFile out;
  std::istringstream in(text);
  std::string line;
  std::size_t columns = 0;
  int line_no = 0, columns_line = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string where = origin + ":" + std::to_string(line_no);
    const auto hash = line.find('#');
    const std::vector<std::string> f =
        fields(hash == std::string::npos ? line : line.substr(0, hash));
    if (f.empty()) continue;
    if (f.size() < 6 || f.size() > 8)
      throw InputError(where +
                       ": expected 6 to 8 columns (px py pz qx qy qz [weight [inlier]]), got " +
                       std::to_string(f.size()));
    if (columns == 0) {
      columns = f.size();
      columns_line = line_no;
    } else if (f.size() != columns) {
      throw InputError(where + ": " + std::to_string(f.size()) + " columns, but line " +
                       std::to_string(columns_line) + " has " + std::to_string(columns));
    }
    if (out.items.size() == kMaxFileCorrespondences)
      throw InputError(where + ": more than " + std::to_string(kMaxFileCorrespondences) +
                       " correspondences, the most the consistency graph takes "
                       "(kMaxGraphCorrespondences); keep the best ones");
    double v[6];
    for (int k = 0; k < 6; ++k) v[k] = number(f[static_cast<std::size_t>(k)], where, names[k]);
    Correspondence c;
    c.class_index = -1;
    c.origin = CorrespondenceOrigin::matcher;
    c.source = c.target = static_cast<int>(out.items.size());
    c.p = Eigen::Vector3d(v[0], v[1], v[2]);
    c.q = Eigen::Vector3d(v[3], v[4], v[5]);
    c.score = 1.0;
    if (columns >= 7) {
      const double w = number(f[6], where, "weight");
      if (w < 0) throw InputError(where + ": weight '" + f[6] + "' is negative");
      c.score = w;
      out.weights.push_back(w);
    }
    if (columns == 8) {
      if (f[7] != "0" && f[7] != "1")
        throw InputError(where + ": inlier flag '" + f[7] + "' is not 0 or 1");
      out.inlier.push_back(f[7] == "1");
    }
    out.items.push_back(c);
    out.lines.push_back(line_no);
  }
  if (out.items.empty()) throw InputError(origin + ": no correspondences");
  return out;
}

CorrespondenceFile read_correspondence_file(const std::string& path) {
  return parse_correspondence_file(
      read_file(path, "correspondences file", kMaxCorrespondenceFileBytes), path);
}

InlierQuality inlier_quality(const std::vector<int>& indices, const std::vector<char>& inlier) {
  InlierQuality q;
  q.selected = indices.size();
  for (char f : inlier) q.inliers += f != 0;
  for (int i : indices) q.true_inliers += inlier.at(static_cast<std::size_t>(i)) != 0;
  q.precision = q.selected ? double(q.true_inliers) / q.selected : 0.0;
  q.recall = q.inliers ? double(q.true_inliers) / q.inliers : 0.0;
  return q;
}

}  // namespace pagor
