#pragma once
/// \file json_input.hpp
/// Reading JSON that comes from users (configs, sessions): a parse with a nesting limit, and
/// getters that check a value's type and range before converting it. Every failure throws
/// ConfigError whose message starts with the origin (the file) and the key path.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace pagor {

/// Deepest nesting of arrays and objects a user document may have.
constexpr int kMaxJsonDepth = 64;

/// Parses `text`, rejecting nesting deeper than `max_depth` while parsing (before anything deep
/// is built), numbers beyond the range of a double ("1e400") and malformed text. Throws
/// ConfigError "<origin>: ..." naming the line and column where the parser stopped.
nlohmann::json parse_json_limited(const std::string& text, const std::string& origin,
                                  int max_depth = kMaxJsonDepth);

/// `j` as an integer in [lo, hi]. Accepts integer literals and floating literals with an integral
/// value ("3.0"); the range is checked before any conversion. `where` is "<origin>: <key path>".
std::int64_t json_integer(const nlohmann::json& j, const std::string& where, std::int64_t lo,
                          std::int64_t hi);

/// `j` as an unsigned integer in [0, hi], checked like json_integer.
std::uint64_t json_unsigned(const nlohmann::json& j, const std::string& where, std::uint64_t hi);

/// `j` as a finite number.
double json_finite(const nlohmann::json& j, const std::string& where);

/// At most `max_chars` of `j` serialised, for messages (invalid UTF-8 is replaced, not thrown).
std::string json_excerpt(const nlohmann::json& j, std::size_t max_chars = 60);

}  // namespace pagor
