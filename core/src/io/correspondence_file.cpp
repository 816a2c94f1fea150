#include "pagor/io/correspondence_file.hpp"

#include <cmath>
#include <optional>
#include <sstream>

#include "io/parse_numbers.hpp"
#include "pagor/errors.hpp"
#include "pagor/io/file_input.hpp"

namespace pagor {
namespace {

// One field of a line: its text and 1-based column (for messages).
struct Field {
  std::string text;
  std::size_t column = 0;
};

// Splits a line (comment removed) into fields separated by blanks or commas.
std::vector<Field> fields(const std::string& line) {
  std::vector<Field> out;
  Field cur;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (ch == ' ' || ch == '\t' || ch == ',' || ch == '\r') {
      if (!cur.text.empty()) out.push_back(std::move(cur));
      cur = Field{};
    } else {
      if (cur.text.empty()) cur.column = i + 1;
      cur.text.push_back(ch);
    }
  }
  if (!cur.text.empty()) out.push_back(std::move(cur));
  return out;
}

// A decimal number (parse::to_double: no hexadecimal, no locale); `what` names the column's
// meaning. Messages keep the form `where: what 'text' ...` and add the 1-based column.
double number(const Field& field, const std::string& where, const char* what) {
  const std::string at = where + ": " + what + " '" + parse::printable(field.text) + "'";
  const std::string column = "column " + std::to_string(field.column);
  const std::optional<double> v = parse::to_double(field.text);
  if (!v || !std::isfinite(*v)) {
    const std::size_t digits = field.text.find_first_not_of("+-");
    const bool hex = digits != std::string::npos && field.text.size() > digits + 1 &&
                     field.text[digits] == '0' &&
                     (field.text[digits + 1] == 'x' || field.text[digits + 1] == 'X');
    throw InputError(at + " is not a finite number (" + column +
                     (hex ? "; numbers are decimal, hexadecimal is not read)" : ")"));
  }
  return *v;
}

// A coordinate: a number within kMaxMatchCoordinate of the origin on its axis.
double coordinate(const Field& field, const std::string& where, const char* what) {
  const double v = number(field, where, what);
  if (!(std::abs(v) <= kMaxMatchCoordinate))
    throw InputError(where + ": " + what + " '" + parse::printable(field.text) +
                     "' lies farther than 1e7 m from the origin, corrupt (column " +
                     std::to_string(field.column) + ")");
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
    const std::vector<Field> f = fields(hash == std::string::npos ? line : line.substr(0, hash));
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
    for (int k = 0; k < 6; ++k) v[k] = coordinate(f[static_cast<std::size_t>(k)], where, names[k]);
    Correspondence c;
    c.class_index = -1;
    c.origin = CorrespondenceOrigin::matcher;
    c.source = c.target = static_cast<int>(out.items.size());
    c.p = Eigen::Vector3d(v[0], v[1], v[2]);
    c.q = Eigen::Vector3d(v[3], v[4], v[5]);
    c.score = 1.0;
    if (columns >= 7) {
      const double w = number(f[6], where, "weight");
      if (w < 0)
        throw InputError(where + ": weight '" + parse::printable(f[6].text) + "' is negative");
      c.score = w;
      out.weights.push_back(w);
    }
    if (columns == 8) {
      if (f[7].text != "0" && f[7].text != "1")
        throw InputError(where + ": inlier flag '" + parse::printable(f[7].text) +
                         "' is not 0 or 1");
      out.inlier.push_back(f[7].text == "1");
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
