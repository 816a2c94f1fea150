#pragma once
// Strict number parsing and scalar decoding shared by the parsers of untrusted bytes (PCD, PLY,
// KITTI text files). Every function checks ranges before converting; none has undefined behaviour
// on any input.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pagor::parse {

/// The whitespace-separated words of a header or body line (space, tab, CR, FF, VT).
inline std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  const auto space = [](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
  };
  while (i < line.size()) {
    while (i < line.size() && space(line[i])) ++i;
    const std::size_t b = i;
    while (i < line.size() && !space(line[i])) ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

/// The first 40 bytes of untrusted text for a message, non-printable bytes as '?'.
inline std::string printable(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 40))
    out += (static_cast<unsigned char>(c) >= 32 && static_cast<unsigned char>(c) < 127) ? c : '?';
  return s.size() > 40 ? out + "..." : out;
}

/// The whole token as an unsigned decimal integer, or nullopt ("-5", "1e3", "20.5", "" fail).
inline std::optional<std::uint64_t> to_uint(std::string_view s) {
  std::uint64_t v = 0;
  if (s.empty()) return std::nullopt;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

/// The whole token as a signed decimal integer, or nullopt.
inline std::optional<std::int64_t> to_int(std::string_view s) {
  std::int64_t v = 0;
  if (s.empty()) return std::nullopt;
  const char* begin = s.data();
  if (s.size() > 1 && s[0] == '+') ++begin;  // from_chars takes no leading '+'
  const auto [end, ec] = std::from_chars(begin, s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

/// The whole token as a floating-point number (decimal or exponent form, "nan", "inf"); nullopt
/// for anything else, including values beyond the range of a double.
inline std::optional<double> to_double(std::string_view s) {
  double v = 0;
  if (s.empty()) return std::nullopt;
  const char* begin = s.data();
  if (s.size() > 1 && s[0] == '+') ++begin;
  const auto [end, ec] = std::from_chars(begin, s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

/// A double narrowed to float without undefined behaviour: beyond float's range gives +-inf.
inline float to_float(double v) {
  if (std::isnan(v)) return std::numeric_limits<float>::quiet_NaN();
  if (v > std::numeric_limits<float>::max()) return std::numeric_limits<float>::infinity();
  if (v < -std::numeric_limits<float>::max()) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(v);
}

/// Whether a double holds an integer in [0, 2^32 - 1], i.e. converts exactly to a uint32 label.
inline bool is_uint32(double v) {
  return std::isfinite(v) && v >= 0 && v <= 4294967295.0 && v == std::floor(v);
}

/// Kinds of scalar a point-cloud file can store.
enum class Scalar { i8, u8, i16, u16, i32, u32, i64, u64, f32, f64 };

/// Bytes of one scalar of that kind.
inline int scalar_size(Scalar t) {
  switch (t) {
    case Scalar::i8:
    case Scalar::u8:
      return 1;
    case Scalar::i16:
    case Scalar::u16:
      return 2;
    case Scalar::i32:
    case Scalar::u32:
    case Scalar::f32:
      return 4;
    default:
      return 8;
  }
}

/// Decodes one scalar at `p` (scalar_size(t) readable bytes); `swap` reverses the byte order
/// (big-endian data on this little-endian host).
inline double decode_scalar(const unsigned char* p, Scalar t, bool swap) {
  unsigned char b[8];
  const int n = scalar_size(t);
  for (int i = 0; i < n; ++i) b[i] = swap ? p[n - 1 - i] : p[i];
  switch (t) {
    case Scalar::i8: {
      std::int8_t v;
      std::memcpy(&v, b, 1);
      return v;
    }
    case Scalar::u8:
      return b[0];
    case Scalar::i16: {
      std::int16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case Scalar::u16: {
      std::uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case Scalar::i32: {
      std::int32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case Scalar::u32: {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case Scalar::i64: {
      std::int64_t v;
      std::memcpy(&v, b, 8);
      return static_cast<double>(v);
    }
    case Scalar::u64: {
      std::uint64_t v;
      std::memcpy(&v, b, 8);
      return static_cast<double>(v);
    }
    case Scalar::f32: {
      float v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case Scalar::f64: {
      double v;
      std::memcpy(&v, b, 8);
      return v;
    }
  }
  return 0.0;
}

/// Parses an ASCII token as a scalar of kind `t`, checking the kind's range (an unsigned field
/// rejects "-5", an integer field rejects "2.5"). nullopt when the token does not fit.
inline std::optional<double> parse_scalar(std::string_view s, Scalar t) {
  if (t == Scalar::f32 || t == Scalar::f64) return to_double(s);
  const bool is_unsigned =
      t == Scalar::u8 || t == Scalar::u16 || t == Scalar::u32 || t == Scalar::u64;
  const int bits = 8 * scalar_size(t);
  if (is_unsigned) {
    const auto v = to_uint(s);
    if (!v || (bits < 64 && *v >> bits)) return std::nullopt;
    return static_cast<double>(*v);
  }
  const auto v = to_int(s);
  if (!v) return std::nullopt;
  if (bits < 64) {
    const std::int64_t lim = std::int64_t{1} << (bits - 1);
    if (*v < -lim || *v >= lim) return std::nullopt;
  }
  return static_cast<double>(*v);
}

}  // namespace pagor::parse
