#pragma once
/// \file number_format.hpp
/// Shortest exact decimals: a float edited in the UI becomes the double its shortest decimal
/// names (0.3f -> 0.3), so that sessions and configs say 0.3, not 0.30000001192092896. And numbers
/// as the studio prints them: never "-0.00", a unit after every figure that has one.

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace pagor::studio {

/// The double whose shortest decimal equals the float's shortest decimal.
inline double shortest(float f) {
  char buf[48];
  const auto res = std::to_chars(buf, buf + sizeof(buf) - 1, f);
  *res.ptr = '\0';
  return std::strtod(buf, nullptr);
}

/// `text` printed from a number, without the sign of a negative zero: "-0.00" -> "0.00",
/// "-0" -> "0" ("-0.01" stays).
inline std::string drop_negative_zero(std::string text) {
  if (text.size() > 1 && text[0] == '-' &&
      text.find_first_not_of("0.", 1) == std::string::npos)
    text.erase(0, 1);
  return text;
}

/// `v` with `decimals` decimals: 0.00 for a value that rounds to zero, never -0.00.
inline std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return drop_negative_zero(buf);
}

/// A figure with its unit, to three significant digits: "1 m", "0.25 m", "-3.5 m"; from 1000 on
/// a whole number ("3052 m", never "3.05e+03 m"); no unit (empty): the number alone.
inline std::string with_unit(double v, const std::string& unit) {
  char buf[64];
  if (std::abs(v) >= 999.5 && std::abs(v) < 1e15)
    std::snprintf(buf, sizeof(buf), "%.0f", v);
  else
    std::snprintf(buf, sizeof(buf), "%.3g", v);
  return drop_negative_zero(buf) + (unit.empty() ? "" : " " + unit);
}

}  // namespace pagor::studio
