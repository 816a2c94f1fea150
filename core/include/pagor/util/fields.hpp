#pragma once
/// \file fields.hpp
/// The vocabulary of the parameter tables. Every stage's `Params` struct (params.hpp) lists its
/// fields once, as a static `fields(v)` that calls `v(&Params::member, FieldInfo{...})` for
/// each: its JSON key, documentation, unit and valid range. The configuration's reader, writer,
/// checks and documentation (config.hpp) and the studio's parameter editor are all generated from
/// these lists, so a new field appears everywhere by being listed once. Enums list their names
/// the same way (`enum_entries`).

#include <cstddef>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace pagor {

/// A number as short text for messages and tables: 1000000, 0.001, 1e12, 1e-6.
std::string number_text(double v);

/// The values a number may take: [min, max], either end open. Integers use whole numbers of it.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< min itself excluded
  bool max_open = false;  ///< max itself excluded

  /// [lo, hi]
  static constexpr Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  /// (lo, hi]: e.g. a length that must be positive
  static constexpr Range above(double lo, double hi) { return {lo, hi, true, false}; }
  /// [lo, hi)
  static constexpr Range below(double lo, double hi) { return {lo, hi, false, true}; }
  /// (lo, hi)
  static constexpr Range open(double lo, double hi) { return {lo, hi, true, true}; }

  bool contains(double v) const {
    return (min_open ? v > min : v >= min) && (max_open ? v < max : v <= max);
  }
  /// "[0, 1]", "(0, 100]", ">= 1" (an infinite end is left out).
  std::string text() const;
};

/// What the tables say of one field.
struct FieldInfo {
  const char* key = "";   ///< JSON key
  const char* doc = "";   ///< one or two sentences: what it does (the studio's tooltip)
  const char* unit = "";  ///< "m", "deg", "ms", ... ("" for counts, flags and ratios)
  Range range{};          ///< valid values of a number (each element of a list of numbers)
  /// A value that switches the field off or means "no limit" although outside `range` (e.g. 0
  /// for "no voxel"); NaN when there is none.
  double off = std::numeric_limits<double>::quiet_NaN();
  bool log_scale = false;  ///< values span decades: sliders and sweeps step geometrically
};

/// One named value of an enum.
template <class E>
struct EnumEntry {
  E value;
  const char* name;  ///< as written in JSON
  const char* doc;   ///< one sentence
};

/// The table entry of an enum value; nullptr for a value not in its table. Works for every enum
/// whose header defines `enum_entries(E)`.
template <class E, class = decltype(enum_entries(E{}))>
const EnumEntry<E>* enum_entry(E value) {
  for (const auto& e : enum_entries(E{}))
    if (e.value == value) return &e;
  return nullptr;
}

/// Name of an enum value as written in JSON ("?" for a value not in its table).
template <class E, class = decltype(enum_entries(E{}))>
const char* to_string(E value) {
  const EnumEntry<E>* e = enum_entry(value);
  return e ? e->name : "?";
}

/// The sentence describing an enum value ("" for a value not in its table).
template <class E, class = decltype(enum_entries(E{}))>
const char* enum_doc(E value) {
  const EnumEntry<E>* e = enum_entry(value);
  return e ? e->doc : "";
}

/// Whether an enum's table has one entry per value from the first to `last`, in order: for a
/// static_assert beside the table, naming the enum's last value (a value added before it without
/// an entry does not compile).
template <class E, std::size_t N>
constexpr bool covers_every_value(const EnumEntry<E> (&table)[N], E last) {
  if (N != static_cast<std::size_t>(last) + 1) return false;
  for (std::size_t i = 0; i < N; ++i)
    if (static_cast<std::size_t>(table[i].value) != i) return false;
  return true;
}

/// The enum value named `name`, if any.
template <class E>
std::optional<E> enum_from_string(const std::string& name) {
  for (const auto& e : enum_entries(E{}))
    if (name == e.name) return e.value;
  return std::nullopt;
}

/// The names of an enum's values, quoted and comma-separated, for messages.
template <class E>
std::string enum_name_list() {
  std::string out;
  for (const auto& e : enum_entries(E{}))
    out += (out.empty() ? "\"" : ", \"") + std::string(e.name) + "\"";
  return out;
}

namespace detail {
template <class T>
struct IsVector : std::false_type {};
template <class T, class A>
struct IsVector<std::vector<T, A>> : std::true_type {};
}  // namespace detail

/// Whether a parameter table has cross-field rules: a static `check(const P&, Checks&)` that calls
/// `checks.require(ok, key, message)` for each.
template <class P, class C, class = void>
struct HasCheck : std::false_type {};
template <class P, class C>
struct HasCheck<P, C, std::void_t<decltype(P::check(std::declval<const P&>(), std::declval<C&>()))>>
    : std::true_type {};

/// A visitor that accepts any field, for detecting parameter tables.
struct AnyFieldVisitor {
  template <class T, class P>
  void operator()(T P::*, const FieldInfo&) const {}
};

/// Whether a type is a parameter table (a struct with a static `fields(visitor)`).
template <class P, class = void>
struct HasFields : std::false_type {};
template <class P>
struct HasFields<P, std::void_t<decltype(P::fields(AnyFieldVisitor{}))>> : std::true_type {};

}  // namespace pagor
