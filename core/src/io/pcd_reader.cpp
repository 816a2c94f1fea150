#include "io/pcd_reader.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include "io/cloud_frame.hpp"
#include "io/lzf.hpp"
#include "io/parse_numbers.hpp"
#include "pagor/errors.hpp"

namespace pagor {
namespace {

using parse::printable;
using parse::words;

using parse::Scalar;

// Limits on what a header may declare; real files are far below them, and the body is checked
// against the file size in any case.
constexpr std::size_t kMaxFields = 1024;
constexpr std::uint64_t kMaxCount = 1u << 20;  // elements per field

struct Field {
  std::string name;
  Scalar type = Scalar::f32;
  std::size_t count = 1;
  std::size_t offset = 0;  // byte offset inside one point record
};

struct Header {
  std::vector<Field> fields;
  std::size_t point_step = 0;  // bytes per point record
  std::size_t points = 0;
  std::string data;      // ascii, binary, binary_compressed
  std::size_t body = 0;  // offset of the first body byte
  int body_line = 0;     // line number of the first body line
};

class HeaderParser {
 public:
  HeaderParser(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  Header parse() {
    std::vector<std::string_view> names, sizes, types, counts;
    bool have_points = false, have_width = false;
    std::uint64_t width = 0, height = 1;
    std::size_t pos = 0;
    int line_no = 0;
    while (pos < bytes_.size()) {
      const std::size_t nl = bytes_.find('\n', pos);
      const std::size_t end = nl == std::string_view::npos ? bytes_.size() : nl;
      const std::string_view line = bytes_.substr(pos, end - pos);
      pos = nl == std::string_view::npos ? bytes_.size() : nl + 1;
      line_ = ++line_no;
      const auto w = words(line);
      if (w.empty() || w[0][0] == '#') continue;
      const std::string_view key = w[0];
      const std::vector<std::string_view> args(w.begin() + 1, w.end());
      if (key == "VERSION" || key == "VIEWPOINT") continue;
      if (key == "FIELDS" || key == "COLUMNS")
        once(names, args, "FIELDS");
      else if (key == "SIZE")
        once(sizes, args, "SIZE");
      else if (key == "TYPE")
        once(types, args, "TYPE");
      else if (key == "COUNT")
        once(counts, args, "COUNT");
      else if (key == "WIDTH") {
        width = number(args, "WIDTH", 0xFFFFFFFFu);
        have_width = true;
      } else if (key == "HEIGHT") {
        height = number(args, "HEIGHT", 0xFFFFFFFFu);
      } else if (key == "POINTS") {
        h_.points = static_cast<std::size_t>(number(args, "POINTS", std::uint64_t{1} << 40));
        have_points = true;
      } else if (key == "DATA") {
        if (args.size() != 1) fail("DATA needs one of ascii, binary, binary_compressed");
        h_.data = std::string(args[0]);
        if (h_.data != "ascii" && h_.data != "binary" && h_.data != "binary_compressed")
          fail("unknown DATA kind '" + printable(args[0]) +
               "' (expected ascii, binary or binary_compressed)");
        h_.body = pos;
        h_.body_line = line_no + 1;
        break;
      } else {
        fail("not a PCD header line: '" + printable(line) + "'");
      }
    }
    if (h_.data.empty()) throw InputError(name_ + ": not a PCD file (no DATA line in the header)");
    if (names.empty()) throw InputError(name_ + ": PCD header has no FIELDS line");
    if (!have_points) {
      if (!have_width) throw InputError(name_ + ": PCD header has neither POINTS nor WIDTH");
      h_.points = static_cast<std::size_t>(width * height);
    } else if (have_width && width * height != h_.points) {
      throw InputError(name_ + ": PCD header: WIDTH x HEIGHT = " + std::to_string(width * height) +
                       " but POINTS = " + std::to_string(h_.points));
    }
    make_fields(names, sizes, types, counts);
    return h_;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(name_ + ":" + std::to_string(line_) + ": " + what);
  }
  void once(std::vector<std::string_view>& slot, const std::vector<std::string_view>& args,
            const char* key) {
    if (!slot.empty()) fail(std::string(key) + " given twice");
    if (args.empty()) fail(std::string(key) + " lists nothing");
    if (args.size() > kMaxFields) fail(std::string(key) + " lists more than 1024 fields");
    slot = args;
  }
  std::uint64_t number(const std::vector<std::string_view>& args, const char* key,
                       std::uint64_t max) const {
    const auto v = args.size() == 1 ? parse::to_uint(args[0]) : std::nullopt;
    if (!v || *v > max)
      fail(std::string(key) + " needs one integer in [0, " + std::to_string(max) + "]");
    return *v;
  }

  void make_fields(const std::vector<std::string_view>& names,
                   const std::vector<std::string_view>& sizes,
                   const std::vector<std::string_view>& types,
                   const std::vector<std::string_view>& counts) {
    const std::size_t n = names.size();
    if (sizes.size() != n || types.size() != n || (!counts.empty() && counts.size() != n))
      throw InputError(name_ + ": PCD header declares " + std::to_string(n) + " fields but " +
                       std::to_string(sizes.size()) + " sizes, " + std::to_string(types.size()) +
                       " types and " + std::to_string(counts.size()) + " counts");
    for (std::size_t i = 0; i < n; ++i) {
      Field f;
      f.name = std::string(names[i]);
      const std::string where = name_ + ": PCD field '" + printable(f.name) + "': ";
      const auto size = parse::to_uint(sizes[i]);
      const std::string_view type = types[i];
      f.type = scalar_type(type, size ? *size : 0,
                           where + "SIZE " + printable(sizes[i]) + " with TYPE " + printable(type));
      const auto count =
          counts.empty() ? std::optional<std::uint64_t>(1) : parse::to_uint(counts[i]);
      if (!count || *count < 1 || *count > kMaxCount)
        throw InputError(where + "COUNT must be an integer in [1, 1048576]");
      f.count = static_cast<std::size_t>(*count);
      f.offset = h_.point_step;
      h_.point_step += f.count * static_cast<std::size_t>(parse::scalar_size(f.type));
      h_.fields.push_back(std::move(f));
    }
  }

  static Scalar scalar_type(std::string_view type, std::uint64_t size, const std::string& what) {
    if (type == "F" && size == 4) return Scalar::f32;
    if (type == "F" && size == 8) return Scalar::f64;
    if (type == "U" || type == "I") {
      const bool u = type == "U";
      switch (size) {
        case 1:
          return u ? Scalar::u8 : Scalar::i8;
        case 2:
          return u ? Scalar::u16 : Scalar::i16;
        case 4:
          return u ? Scalar::u32 : Scalar::i32;
        case 8:
          return u ? Scalar::u64 : Scalar::i64;
        default:
          break;
      }
    }
    throw InputError(what +
                     " is not a valid type (F takes SIZE 4 or 8; I and U take 1, 2, 4 or 8)");
  }

  std::string_view bytes_;
  const std::string& name_;
  Header h_;
  int line_ = 0;
};

// Which fields the cloud needs, by index into Header::fields (-1 when absent).
struct Wanted {
  int x = -1, y = -1, z = -1, intensity = -1, label = -1;
};

Wanted find_fields(const Header& h, const std::string& name) {
  Wanted w;
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    int* slot = h.fields[i].name == "x"           ? &w.x
                : h.fields[i].name == "y"         ? &w.y
                : h.fields[i].name == "z"         ? &w.z
                : h.fields[i].name == "intensity" ? &w.intensity
                : h.fields[i].name == "label"     ? &w.label
                                                  : nullptr;
    if (slot && *slot < 0) *slot = static_cast<int>(i);
  }
  if (w.x < 0 || w.y < 0 || w.z < 0) throw InputError(name + ": PCD file has no x, y, z fields");
  return w;
}

// Stores the values of point `i` (x, y, z, intensity, label as doubles, NaN-free checks for the
// label) into the cloud, the coordinates relative to its frame origin; `loss` grows to the largest
// rounding error of a coordinate [m].
void store(PointCloud& c, const Wanted& w, std::size_t i, const double* v, const std::string& at,
           double& loss) {
  c.points[i] =
      Eigen::Vector3f(narrowed(v[0], c.origin.x(), loss), narrowed(v[1], c.origin.y(), loss),
                      narrowed(v[2], c.origin.z(), loss));
  if (w.intensity >= 0) c.intensities[i] = parse::to_float(v[3]);
  if (w.label >= 0) {
    if (!parse::is_uint32(v[4]))
      throw InputError(at + ": label " + std::to_string(v[4]) +
                       " is not an unsigned 32-bit integer");
    c.labels[i] = static_cast<std::uint32_t>(v[4]);
  }
}

PointCloud sized_cloud(const Wanted& w, std::size_t n) {
  PointCloud c;
  c.points.resize(n);
  if (w.intensity >= 0) c.intensities.resize(n);
  if (w.label >= 0) c.labels.resize(n);
  return c;
}

PointCloud read_ascii(std::string_view bytes, const Header& h, const Wanted& w,
                      const std::string& name, double& loss) {
  std::size_t values_per_row = 0;
  for (const auto& f : h.fields) values_per_row += f.count;
  // First element of each wanted field within a row.
  std::vector<std::size_t> first(h.fields.size());
  for (std::size_t i = 0, k = 0; i < h.fields.size(); k += h.fields[i].count, ++i) first[i] = k;
  const int slots[5] = {w.x, w.y, w.z, w.intensity, w.label};

  std::vector<double> rows;  // the 5 wanted values of each row, row after row
  std::size_t pos = h.body;
  int line_no = h.body_line - 1;
  while (pos < bytes.size()) {
    const std::size_t nl = bytes.find('\n', pos);
    const std::size_t end = nl == std::string_view::npos ? bytes.size() : nl;
    const std::string_view line = bytes.substr(pos, end - pos);
    pos = nl == std::string_view::npos ? bytes.size() : nl + 1;
    ++line_no;
    const auto tokens = words(line);
    if (tokens.empty()) continue;
    const std::string at = name + ":" + std::to_string(line_no);
    if (rows.size() / 5 == h.points)
      throw InputError(at + ": more rows than the " + std::to_string(h.points) +
                       " points the header declares");
    if (tokens.size() != values_per_row)
      throw InputError(at + ": expected " + std::to_string(values_per_row) +
                       " values per row (one per FIELDS entry and COUNT), got " +
                       std::to_string(tokens.size()));
    double v[5] = {0, 0, 0, 0, 0};
    for (int s = 0; s < 5; ++s) {
      if (slots[s] < 0) continue;
      const Field& f = h.fields[static_cast<std::size_t>(slots[s])];
      const std::string_view tok = tokens[first[static_cast<std::size_t>(slots[s])]];
      const auto x = parse::parse_scalar(tok, f.type);
      if (!x)
        throw InputError(at + ": '" + printable(tok) + "' is not a valid value for field " +
                         f.name);
      v[s] = *x;
    }
    rows.insert(rows.end(), v, v + 5);
  }
  const std::size_t n = rows.size() / 5;
  if (n != h.points)
    throw InputError(name + ": the header declares " + std::to_string(h.points) +
                     " points but the ASCII body has " + std::to_string(n) + " rows");
  PointCloud c = sized_cloud(w, n);
  c.origin = frame_origin(n, [&](std::size_t i) {
    return Eigen::Vector3d(rows[5 * i], rows[5 * i + 1], rows[5 * i + 2]);
  });
  for (std::size_t i = 0; i < n; ++i)
    store(c, w, i, rows.data() + 5 * i, name + ": point " + std::to_string(i), loss);
  return c;
}

// `record(i, field)` gives the address of field's first element of point i.
template <class At>
PointCloud read_records(const Header& h, const Wanted& w, const std::string& name, At record,
                        double& loss) {
  PointCloud c = sized_cloud(w, h.points);
  const int slots[5] = {w.x, w.y, w.z, w.intensity, w.label};
  const auto value = [&](std::size_t i, int slot) {
    const Field& f = h.fields[static_cast<std::size_t>(slot)];
    return parse::decode_scalar(record(i, f), f.type, false);
  };
  c.origin = frame_origin(h.points, [&](std::size_t i) {
    return Eigen::Vector3d(value(i, w.x), value(i, w.y), value(i, w.z));
  });
  for (std::size_t i = 0; i < h.points; ++i) {
    double v[5] = {0, 0, 0, 0, 0};
    for (int s = 0; s < 5; ++s)
      if (slots[s] >= 0) v[s] = value(i, slots[s]);
    store(c, w, i, v, name + ": point " + std::to_string(i), loss);
  }
  return c;
}

PointCloud read_binary(std::string_view bytes, const Header& h, const Wanted& w,
                       const std::string& name, double& loss) {
  const std::size_t available = bytes.size() - h.body;
  if (h.point_step == 0 || h.points > available / h.point_step)
    throw InputError(name + ": truncated PCD body: " + std::to_string(h.points) + " points of " +
                     std::to_string(h.point_step) + " bytes need more than the " +
                     std::to_string(available) + " bytes after the header");
  const auto* base = reinterpret_cast<const unsigned char*>(bytes.data()) + h.body;
  return read_records(
      h, w, name, [&](std::size_t i, const Field& f) { return base + i * h.point_step + f.offset; },
      loss);
}

PointCloud read_compressed(std::string_view bytes, const Header& h, const Wanted& w,
                           const std::string& name, double& loss) {
  const std::size_t available = bytes.size() - h.body;
  if (available < 8)
    throw InputError(name + ": binary_compressed PCD body lacks its two 4-byte sizes");
  const auto* base = reinterpret_cast<const unsigned char*>(bytes.data()) + h.body;
  const auto u32 = [](const unsigned char* p) {
    return static_cast<std::size_t>(parse::decode_scalar(p, Scalar::u32, false));
  };
  const std::size_t compressed = u32(base), uncompressed = u32(base + 4);
  if (compressed > available - 8)
    throw InputError(name + ": binary_compressed PCD declares " + std::to_string(compressed) +
                     " compressed bytes but only " + std::to_string(available - 8) + " follow");
  if (h.point_step == 0 || h.points > (std::size_t{1} << 32) / h.point_step ||
      uncompressed != h.points * h.point_step)
    throw InputError(name + ": binary_compressed PCD declares " + std::to_string(uncompressed) +
                     " uncompressed bytes, but " + std::to_string(h.points) + " points of " +
                     std::to_string(h.point_step) + " bytes need exactly " +
                     std::to_string(h.points * h.point_step));
  // An LZF run expands at most 264 bytes from 2, so a larger claim is a lie: check before
  // allocating the output.
  if (uncompressed / 132 > compressed)
    throw InputError(name + ": binary_compressed PCD: " + std::to_string(compressed) +
                     " compressed bytes cannot hold " + std::to_string(uncompressed) + " bytes");
  std::vector<std::uint8_t> data(uncompressed);
  if (!lzf_decompress(base + 8, compressed, data.data(), data.size()))
    throw InputError(name + ": binary_compressed PCD body is not valid LZF data of " +
                     std::to_string(uncompressed) + " bytes");
  // The decompressed body stores each field for all points in turn.
  return read_records(
      h, w, name,
      [&](std::size_t i, const Field& f) {
        const std::size_t fsize = f.count * static_cast<std::size_t>(parse::scalar_size(f.type));
        return data.data() + f.offset * h.points + i * fsize;
      },
      loss);
}

}  // namespace

PointCloud parse_pcd(std::string_view bytes, const std::string& name, double* narrowing_loss) {
  const Header h = HeaderParser(bytes, name).parse();
  const Wanted w = find_fields(h, name);
  double loss = 0;
  PointCloud c = h.data == "ascii"    ? read_ascii(bytes, h, w, name, loss)
                 : h.data == "binary" ? read_binary(bytes, h, w, name, loss)
                                      : read_compressed(bytes, h, w, name, loss);
  if (narrowing_loss) *narrowing_loss = loss;
  return c;
}

}  // namespace pagor
