#include "pagor/io/json_input.hpp"

#include <cmath>

#include "pagor/errors.hpp"

namespace pagor {

using json = nlohmann::json;

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw ConfigError(where + ": " + what);
}

// Exactly representable bounds: 2^63 and 2^64 as doubles.
constexpr double kTwo63 = 9223372036854775808.0;
constexpr double kTwo64 = 18446744073709551616.0;

}  // namespace

namespace {

// Rejects nesting deeper than `max_depth` before anything is parsed: brackets outside strings
// are counted in one pass (nlohmann's depth callback would do it while parsing, but makes the
// parse quadratic in the number of values). Text that is not JSON fails in the parser afterwards.
void check_depth(const std::string& text, const std::string& origin, int max_depth) {
  int depth = 0, line = 1;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (in_string) {
      if (c == '\\')
        ++i;  // an escaped character, '"' included
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth)
        throw ConfigError(origin + ": nesting deeper than " + std::to_string(max_depth) +
                          " levels of arrays and objects (line " + std::to_string(line) + ")");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace

json parse_json_limited(const std::string& text, const std::string& origin, int max_depth) {
  check_depth(text, origin, max_depth);
  try {
    return json::parse(text);
  } catch (const json::exception& e) {
    // parse_error names the line and column; out_of_range (e.g. 1e400) the number.
    throw ConfigError(origin + ": not valid JSON (" + e.what() + ")");
  }
}

std::int64_t json_integer(const json& j, const std::string& where, std::int64_t lo,
                          std::int64_t hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (j.is_number_unsigned()) {
    const std::uint64_t v = j.get<std::uint64_t>();
    if (hi < 0 || v > static_cast<std::uint64_t>(hi))
      fail(where, "expected an integer in " + range + ", got " + json_excerpt(j));
    return static_cast<std::int64_t>(v);
  }
  if (j.is_number_integer()) {
    const std::int64_t v = j.get<std::int64_t>();
    if (v < lo || v > hi)
      fail(where, "expected an integer in " + range + ", got " + json_excerpt(j));
    return v;
  }
  if (j.is_number_float()) {
    const double d = j.get<double>();
    if (!std::isfinite(d) || d != std::floor(d))
      fail(where, "expected an integer, got " + json_excerpt(j));
    if (d < static_cast<double>(lo) || d >= kTwo63 || d > static_cast<double>(hi))
      fail(where, "expected an integer in " + range + ", got " + json_excerpt(j));
    const auto v = static_cast<std::int64_t>(d);  // in range: checked above
    if (v < lo || v > hi)
      fail(where, "expected an integer in " + range + ", got " + json_excerpt(j));
    return v;
  }
  fail(where, std::string("expected an integer, got ") + j.type_name());
}

std::uint64_t json_unsigned(const json& j, const std::string& where, std::uint64_t hi) {
  const std::string range = "[0, " + std::to_string(hi) + "]";
  if (j.is_number_unsigned()) {
    const std::uint64_t v = j.get<std::uint64_t>();
    if (v > hi) fail(where, "expected an integer in " + range + ", got " + json_excerpt(j));
    return v;
  }
  if (j.is_number_integer())  // a negative integer: unsigned ones are caught above
    fail(where, "expected a non-negative integer, got " + json_excerpt(j));
  if (j.is_number_float()) {
    const double d = j.get<double>();
    if (!std::isfinite(d) || d != std::floor(d))
      fail(where, "expected an integer, got " + json_excerpt(j));
    if (d < 0) fail(where, "expected a non-negative integer, got " + json_excerpt(j));
    if (d >= kTwo64 || d > static_cast<double>(hi))
      fail(where, "expected an integer in " + range + ", got " + json_excerpt(j));
    const auto v = static_cast<std::uint64_t>(d);
    if (v > hi) fail(where, "expected an integer in " + range + ", got " + json_excerpt(j));
    return v;
  }
  fail(where, std::string("expected an integer, got ") + j.type_name());
}

double json_finite(const json& j, const std::string& where) {
  if (!j.is_number()) fail(where, std::string("expected a number, got ") + j.type_name());
  const double d = j.get<double>();
  if (!std::isfinite(d)) fail(where, "expected a finite number");
  return d;
}

std::string json_excerpt(const json& j, std::size_t max_chars) {
  std::string s = j.dump(-1, ' ', false, json::error_handler_t::replace);
  if (s.size() > max_chars) s = s.substr(0, max_chars) + "...";
  return s;
}

}  // namespace pagor
