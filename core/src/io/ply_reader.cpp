#include "io/ply_reader.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "io/cloud_frame.hpp"
#include "io/parse_numbers.hpp"
#include "pagor/errors.hpp"

namespace pagor {
namespace {

using parse::printable;
using parse::words;

using parse::Scalar;

constexpr std::uint64_t kMaxElementCount = std::uint64_t{1} << 40;

struct Property {
  std::string name;
  Scalar type = Scalar::f32;
  bool is_list = false;
  Scalar count_type = Scalar::u8;  // lists: type of the length
};

struct Element {
  std::string name;
  std::size_t count = 0;
  std::vector<Property> props;
};

enum class Format { ascii, little, big };

struct Header {
  Format format = Format::ascii;
  std::vector<Element> elements;
  std::size_t body = 0;
  int body_line = 0;
};

std::optional<Scalar> scalar_type(std::string_view t) {
  if (t == "char" || t == "int8") return Scalar::i8;
  if (t == "uchar" || t == "uint8") return Scalar::u8;
  if (t == "short" || t == "int16") return Scalar::i16;
  if (t == "ushort" || t == "uint16") return Scalar::u16;
  if (t == "int" || t == "int32") return Scalar::i32;
  if (t == "uint" || t == "uint32") return Scalar::u32;
  if (t == "float" || t == "float32") return Scalar::f32;
  if (t == "double" || t == "float64") return Scalar::f64;
  return std::nullopt;
}

Header parse_header(std::string_view bytes, const std::string& name) {
  Header h;
  std::size_t pos = 0;
  int line_no = 0;
  bool have_format = false, ended = false;
  while (pos < bytes.size() && !ended) {
    const std::size_t nl = bytes.find('\n', pos);
    const std::size_t end = nl == std::string_view::npos ? bytes.size() : nl;
    const std::string_view line = bytes.substr(pos, end - pos);
    pos = nl == std::string_view::npos ? bytes.size() : nl + 1;
    ++line_no;
    const std::string at = name + ":" + std::to_string(line_no) + ": ";
    const auto w = words(line);
    if (line_no == 1) {
      if (w.size() != 1 || w[0] != "ply") throw InputError(name + ": not a PLY file");
      continue;
    }
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header" && w.size() == 1) {
      ended = true;
    } else if (w[0] == "format") {
      if (have_format) throw InputError(at + "format given twice");
      if (w.size() != 3 || w[2] != "1.0")
        throw InputError(at +
                         "expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
      if (w[1] == "ascii")
        h.format = Format::ascii;
      else if (w[1] == "binary_little_endian")
        h.format = Format::little;
      else if (w[1] == "binary_big_endian")
        h.format = Format::big;
      else
        throw InputError(at + "unknown format '" + printable(w[1]) + "'");
      have_format = true;
    } else if (w[0] == "element") {
      const auto count = w.size() == 3 ? parse::to_uint(w[2]) : std::nullopt;
      if (!count || *count > kMaxElementCount)
        throw InputError(at + "expected 'element <name> <count>' with a count in [0, 2^40], got '" +
                         printable(line) + "'");
      h.elements.push_back({std::string(w[1]), static_cast<std::size_t>(*count), {}});
    } else if (w[0] == "property") {
      if (h.elements.empty()) throw InputError(at + "property before any element");
      Property p;
      const bool list = w.size() == 5 && w[1] == "list";
      const auto type = list ? scalar_type(w[3]) : w.size() == 3 ? scalar_type(w[1]) : std::nullopt;
      const auto count_type = list ? scalar_type(w[2]) : std::optional<Scalar>(Scalar::u8);
      if (!type || !count_type ||
          (list && (*count_type == Scalar::f32 || *count_type == Scalar::f64)))
        throw InputError(at +
                         "expected 'property <type> <name>' or 'property list <int type> "
                         "<type> <name>', got '" +
                         printable(line) + "'");
      p.name = std::string(w.back());
      p.type = *type;
      p.is_list = list;
      p.count_type = *count_type;
      h.elements.back().props.push_back(std::move(p));
    } else {
      throw InputError(at + "not a PLY header line: '" + printable(line) + "'");
    }
    h.body = pos;
    h.body_line = line_no + 1;
  }
  if (line_no == 0) throw InputError(name + ": not a PLY file (it is empty)");
  if (!ended) throw InputError(name + ": PLY header has no end_header line");
  if (!have_format) throw InputError(name + ": PLY header has no format line");
  bool has_vertex = false;
  for (const auto& e : h.elements) has_vertex = has_vertex || e.name == "vertex";
  if (!has_vertex) throw InputError(name + ": PLY file has no 'vertex' element");
  return h;
}

// Reads values one at a time from the body, with bounds checks; ASCII by whitespace-separated
// tokens (one record per line), binary by byte counts.
class BodyReader {
 public:
  BodyReader(std::string_view bytes, const Header& h, const std::string& name)
      : bytes_(bytes), pos_(h.body), line_(h.body_line - 1), format_(h.format), name_(name) {}

  // Starts record `index` of `element` (ASCII: the next non-empty line).
  void begin_record(const Element& e, std::size_t index) {
    where_ = name_ + ": element '" + e.name + "' record " + std::to_string(index);
    if (format_ != Format::ascii) return;
    tokens_.clear();
    next_token_ = 0;
    while (tokens_.empty()) {
      if (pos_ >= bytes_.size())
        throw InputError(where_ + ": the file ends (" + std::to_string(e.count) +
                         " records declared)");
      const std::size_t nl = bytes_.find('\n', pos_);
      const std::size_t end = nl == std::string_view::npos ? bytes_.size() : nl;
      tokens_ = words(bytes_.substr(pos_, end - pos_));
      pos_ = nl == std::string_view::npos ? bytes_.size() : nl + 1;
      ++line_;
    }
    where_ = name_ + ":" + std::to_string(line_) + ": element '" + e.name + "' record " +
             std::to_string(index);
  }
  void end_record() const {
    if (format_ == Format::ascii && next_token_ != tokens_.size())
      throw InputError(where_ + ": " + std::to_string(tokens_.size() - next_token_) +
                       " values more than its properties");
  }

  double value(Scalar t, const std::string& prop) {
    if (format_ == Format::ascii) {
      if (next_token_ >= tokens_.size())
        throw InputError(where_ + ": missing value for property '" + prop + "'");
      const std::string_view tok = tokens_[next_token_++];
      const auto v = parse::parse_scalar(tok, t);
      if (!v)
        throw InputError(where_ + ": '" + printable(tok) + "' is not a valid value for property '" +
                         prop + "'");
      return *v;
    }
    const std::size_t n = static_cast<std::size_t>(parse::scalar_size(t));
    if (n > bytes_.size() - pos_)
      throw InputError(where_ + ": the file ends inside property '" + prop + "'");
    const double v = parse::decode_scalar(
        reinterpret_cast<const unsigned char*>(bytes_.data()) + pos_, t, format_ == Format::big);
    pos_ += n;
    return v;
  }

  // Reads a list property and discards its items.
  void skip_list(const Property& p) {
    const double len = value(p.count_type, p.name);
    if (!(len >= 0) || len > static_cast<double>(bytes_.size()))
      throw InputError(where_ + ": list '" + p.name + "' has an invalid length");
    const std::size_t n = static_cast<std::size_t>(len);
    if (format_ != Format::ascii) {
      const std::size_t item = static_cast<std::size_t>(parse::scalar_size(p.type));
      if (n > (bytes_.size() - pos_) / item)
        throw InputError(where_ + ": list '" + p.name + "' of " + std::to_string(n) +
                         " items runs past the end of the file");
      pos_ += n * item;
      return;
    }
    for (std::size_t k = 0; k < n; ++k) value(p.type, p.name);
  }

  // Steps over a whole element. Fixed-size binary records are checked and skipped in one step;
  // every other record consumes at least one byte or line, so the loop is bounded by the file.
  void skip_element(const Element& e) {
    bool fixed = format_ != Format::ascii;
    std::size_t record = 0;
    for (const auto& p : e.props) {
      fixed = fixed && !p.is_list;
      record += static_cast<std::size_t>(parse::scalar_size(p.is_list ? p.count_type : p.type));
    }
    if (fixed) {
      if (record > 0 && e.count > (bytes_.size() - pos_) / record)
        throw InputError(name_ + ": element '" + e.name + "': " + std::to_string(e.count) +
                         " records of " + std::to_string(record) +
                         " bytes run past the end of the file");
      pos_ += e.count * record;
      return;
    }
    for (std::size_t i = 0; i < e.count; ++i) {
      begin_record(e, i);
      for (const auto& p : e.props) {
        if (p.is_list)
          skip_list(p);
        else
          value(p.type, p.name);
      }
      end_record();
    }
  }

  // Upper bound on the records left: each needs at least one byte (binary, when the record has
  // any property) or one line (ASCII).
  std::size_t bytes_left() const { return bytes_.size() - pos_; }
  bool ascii() const { return format_ == Format::ascii; }
  const std::string& where() const { return where_; }

 private:
  std::string_view bytes_;
  std::size_t pos_;
  int line_;
  Format format_;
  const std::string& name_;
  std::string where_;
  std::vector<std::string_view> tokens_;
  std::size_t next_token_ = 0;
};

// Whether a coordinate of this kind can hold more than a float32 does (24 significant bits).
bool wider_than_float(parse::Scalar t) {
  using parse::Scalar;
  return t == Scalar::f64 || t == Scalar::i32 || t == Scalar::u32 || t == Scalar::i64 ||
         t == Scalar::u64;
}

PointCloud read_vertices(BodyReader& body, const Element& e, const std::string& name,
                         double& loss) {
  int x = -1, y = -1, z = -1, in = -1, lb = -1;
  std::size_t record = 0;
  for (std::size_t i = 0; i < e.props.size(); ++i) {
    const Property& p = e.props[i];
    record += static_cast<std::size_t>(parse::scalar_size(p.is_list ? p.count_type : p.type));
    if (p.is_list) continue;
    int* slot = p.name == "x"           ? &x
                : p.name == "y"         ? &y
                : p.name == "z"         ? &z
                : p.name == "intensity" ? &in
                : p.name == "label"     ? &lb
                                        : nullptr;
    if (slot && *slot < 0) *slot = static_cast<int>(i);
  }
  if (x < 0 || y < 0 || z < 0)
    throw InputError(name + ": PLY element 'vertex' has no x, y, z properties");
  // Each record takes at least `record` bytes (binary) or two per value but the last (ASCII: a
  // digit and a separator): a count beyond that is a lie, caught before allocating.
  const std::size_t min_bytes = body.ascii() ? 2 * e.props.size() - 1 : record;
  if (e.count > body.bytes_left() / min_bytes)
    throw InputError(name + ": PLY element 'vertex' declares " + std::to_string(e.count) +
                     " records, more than the " + std::to_string(body.bytes_left()) +
                     " bytes after the header can hold");
  PointCloud c;
  c.points.resize(e.count);
  if (in >= 0) c.intensities.resize(e.count);
  if (lb >= 0) c.labels.resize(e.count);
  // Wide coordinates are kept in double until the cloud's frame origin is known (cloud_frame.hpp);
  // binary float32 ones are exact as they are (load_cloud moves them to their frame).
  const bool wide = body.ascii() ||  // ASCII text holds every digit written
                    wider_than_float(e.props[static_cast<std::size_t>(x)].type) ||
                    wider_than_float(e.props[static_cast<std::size_t>(y)].type) ||
                    wider_than_float(e.props[static_cast<std::size_t>(z)].type);
  std::vector<Eigen::Vector3d> exact(wide ? e.count : 0);
  std::vector<double> v(e.props.size());
  for (std::size_t r = 0; r < e.count; ++r) {
    body.begin_record(e, r);
    for (std::size_t i = 0; i < e.props.size(); ++i) {
      if (e.props[i].is_list)
        body.skip_list(e.props[i]);
      else
        v[i] = body.value(e.props[i].type, e.props[i].name);
    }
    body.end_record();
    const auto at = [&](int k) { return v[static_cast<std::size_t>(k)]; };
    if (wide)
      exact[r] = Eigen::Vector3d(at(x), at(y), at(z));
    else
      c.points[r] =
          Eigen::Vector3f(parse::to_float(at(x)), parse::to_float(at(y)), parse::to_float(at(z)));
    if (in >= 0) c.intensities[r] = parse::to_float(at(in));
    if (lb >= 0) {
      if (!parse::is_uint32(at(lb)))
        throw InputError(body.where() + ": label " + std::to_string(at(lb)) +
                         " is not an unsigned 32-bit integer");
      c.labels[r] = static_cast<std::uint32_t>(at(lb));
    }
  }
  if (wide) {
    c.origin = frame_origin(exact.size(), [&](std::size_t i) { return exact[i]; });
    for (std::size_t r = 0; r < exact.size(); ++r)
      for (int k = 0; k < 3; ++k) c.points[r][k] = narrowed(exact[r][k], c.origin[k], loss);
  }
  return c;
}

}  // namespace

PointCloud parse_ply(std::string_view bytes, const std::string& name, double* narrowing_loss) {
  const Header h = parse_header(bytes, name);
  BodyReader body(bytes, h, name);
  for (const auto& e : h.elements) {
    if (e.name == "vertex") {
      double loss = 0;
      PointCloud c = read_vertices(body, e, name, loss);
      if (narrowing_loss) *narrowing_loss = loss;
      return c;
    }
    body.skip_element(e);
  }
  throw InputError(name + ": PLY file has no 'vertex' element");
}

}  // namespace pagor
