#pragma once
/// \file timings.hpp
/// Wall-clock times as the UI prints them. They differ from run to run, so a headless render for
/// regression tests hides them (`set_timings_shown(false)`): two renders of the same inputs are
/// then equal byte for byte, and a checksum can stand for the picture.

#include <cstdio>
#include <string>

namespace pagor::studio::ui {

namespace detail {
inline bool& timings_shown() {
  static bool shown = true;
  return shown;
}
}  // namespace detail

/// Shows (the window) or hides (headless renders, unless asked) every wall-clock time.
inline void set_timings_shown(bool shown) {
  detail::timings_shown() = shown;
}
inline bool timings_shown() {
  return detail::timings_shown();
}

/// The text shown in place of a hidden time.
inline constexpr const char* kHiddenTiming = "--";

/// `value` printed with `format` (one floating-point conversion, e.g. "%.0f ms"), or the format
/// with "--" in place of the number while timings are hidden ("-- ms").
inline std::string timing(const char* format, double value) {
  char buf[96];
  if (timings_shown()) {
    std::snprintf(buf, sizeof(buf), format, value);
    return buf;
  }
  std::string f(format);
  const auto start = f.find('%');
  const auto end = f.find_first_of("fgeFGE", start);
  if (start == std::string::npos || end == std::string::npos) return kHiddenTiming;
  return f.substr(0, start) + kHiddenTiming + f.substr(end + 1);
}

}  // namespace pagor::studio::ui
