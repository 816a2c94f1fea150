#pragma once
/// \file number_format.hpp
/// Shortest exact decimals: a float edited in the UI becomes the double its shortest decimal
/// names (0.3f -> 0.3), so that sessions and configs say 0.3, not 0.30000001192092896.

#include <charconv>
#include <cstdlib>

namespace pagor::studio {

/// The double whose shortest decimal equals the float's shortest decimal.
inline double shortest(float f) {
  char buf[48];
  const auto res = std::to_chars(buf, buf + sizeof(buf) - 1, f);
  *res.ptr = '\0';
  return std::strtod(buf, nullptr);
}

}  // namespace pagor::studio
