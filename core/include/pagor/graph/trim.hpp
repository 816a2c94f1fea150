#pragma once
/// \file trim.hpp
/// Translation-and-rotation-invariant measurements (TRIM) between two correspondences
/// (p_i, q_i) and (p_j, q_j): they compare the source length a = |p_i - p_j| with the target
/// length b = |q_i - q_j|, which a rigid transform preserves.

#include <algorithm>
#include <cmath>

#include "pagor/params.hpp"

namespace pagor {

/// The unit of a TRIM value and so of the thresholds: "m" for a difference, "" for a ratio.
inline const char* trim_unit(TrimKind kind) {
  return kind == TrimKind::difference ? "m" : "";
}
/// The same to write after a value: " m" or "".
inline const char* trim_unit_suffix(TrimKind kind) {
  return kind == TrimKind::difference ? " m" : "";
}

/// TRIM of two lengths a, b [m]: `difference` |a - b| [m]; `ratio` max(a/b, b/a) - 1 [unitless].
/// A ratio with a zero length is +infinity.
inline double trim_value(TrimKind kind, double a, double b) {
  if (kind == TrimKind::difference) return std::abs(a - b);
  const double lo = std::min(a, b), hi = std::max(a, b);
  return lo > 0 ? hi / lo - 1.0 : HUGE_VAL;
}

}  // namespace pagor
