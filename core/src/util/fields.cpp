#include "pagor/util/fields.hpp"

#include <cmath>
#include <cstdio>

namespace pagor {
std::string number_text(double v) {
  char buf[32];
  if (v == std::floor(v) && std::abs(v) < 1e9) {
    std::snprintf(buf, sizeof(buf), "%.0f", v);
    return buf;
  }
  std::snprintf(buf, sizeof(buf), "%g", v);
  std::string s = buf;  // 1e+12 -> 1e12, 1e-06 -> 1e-6
  const auto e = s.find('e');
  if (e != std::string::npos) {
    std::string exp = s.substr(e + 1);
    const bool negative = exp[0] == '-';
    exp.erase(0, exp.find_first_not_of("+-0"));
    s = s.substr(0, e + 1) + (negative ? "-" : "") + exp;
  }
  return s;
}

std::string Range::text() const {
  const bool lo = std::isfinite(min), hi = std::isfinite(max);
  if (lo && hi)
    return std::string(min_open ? "(" : "[") + number_text(min) + ", " + number_text(max) +
           (max_open ? ")" : "]");
  if (lo) return std::string(min_open ? "> " : ">= ") + number_text(min);
  if (hi) return std::string(max_open ? "< " : "<= ") + number_text(max);
  return "any number";
}

}  // namespace pagor
