// Checking a configuration and writing its reference, both generated from the parameter tables
// (util/fields.hpp): each number against its field's range, each table's cross-field rules, and
// the class names against the label scheme.

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>
#include <type_traits>

#include "pagor/config.hpp"
#include "pagor/errors.hpp"

namespace pagor {
namespace {

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

// The unit as shown after a value: " [m]", or nothing.
std::string unit_suffix(const FieldInfo& f) {
  if (std::string(f.unit) == "trim") return " [m for the difference TRIM, unitless for the ratio]";
  return *f.unit ? std::string(" [") + f.unit + "]" : std::string();
}

std::string allowed_text(const FieldInfo& f) {
  std::string s = f.range.text();
  if (!std::isnan(f.off)) s += " or " + number_text(f.off) + " (off)";
  return s;
}

// Reports a broken cross-field rule of a table, at the table's path.
struct Checks {
  const std::string& origin;
  std::string path;
  void require(bool ok, const std::string& key, const std::string& what) const {
    if (!ok) throw ConfigError(origin + ": " + join(path, key) + ": " + what);
  }
};

template <class P>
void check_table(const std::string& origin, const std::string& path, const P& p);

template <class T>
void check_value(const std::string& origin, const std::string& path, const FieldInfo& f,
                 const T& x) {
  if constexpr (HasFields<T>::value) {
    check_table(origin, path, x);
  } else if constexpr (detail::IsVector<T>::value) {
    for (std::size_t i = 0; i < x.size(); ++i)
      check_value(origin, path + "[" + std::to_string(i) + "]", f, x[i]);
  } else if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
    const double v = static_cast<double>(x);
    if (!f.range.contains(v) && !(v == f.off))
      throw ConfigError(origin + ": " + path + ": " + number_text(v) + " is outside " +
                        allowed_text(f) + unit_suffix(f));
  }
}

template <class P>
void check_table(const std::string& origin, const std::string& path, const P& p) {
  P::fields([&](auto member, const FieldInfo& f) {
    check_value(origin, join(path, f.key), f, p.*member);
  });
  if constexpr (HasCheck<P, const Checks>::value) {
    const Checks checks{origin, path};
    P::check(p, checks);
  }
}

// ---- the reference ----------------------------------------------------------------------------

template <class T>
std::string allowed_of(const FieldInfo& f) {
  if constexpr (std::is_enum_v<T>) {
    return enum_name_list<T>();
  } else if constexpr (std::is_same_v<T, LabelScheme>) {
    std::string names;
    for (const auto& n : builtin_label_scheme_names()) names += "\"" + n + "\", ";
    return names + "or {\"name\": ..., \"classes\": {\"car\": [10], ...}}";
  } else if constexpr (std::is_same_v<T, bool>) {
    return "true, false";
  } else if constexpr (std::is_same_v<T, std::string>) {
    return "text";
  } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    return "list of class names";
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    return "list of numbers in " + allowed_text(f);
  } else if constexpr (std::is_floating_point_v<T>) {
    return allowed_text(f);
  } else if constexpr (std::is_integral_v<T>) {
    if (!std::isfinite(f.range.min) && !std::isfinite(f.range.max))
      return std::is_unsigned_v<T> ? "integer >= 0" : "integer";
    return "integer in " + allowed_text(f);
  } else {
    return "";
  }
}

// A list of parameter tables (landmarks.classes).
template <class T>
struct IsTableList : std::false_type {};
template <class E>
struct IsTableList<std::vector<E>> : HasFields<E> {};

struct ReferenceWriter {
  std::string out;

  void row(const std::string& path, const std::string& value, const std::string& allowed,
           const FieldInfo& f) {
    std::string unit = f.unit;
    if (unit == "trim") unit = "m (difference) or none (ratio)";
    out += "| `" + path + "` | " + value + " | " + allowed + " | " + unit + " | " + f.doc + " |\n";
  }

  template <class T>
  void field(const std::string& path, const FieldInfo& f, const T& value,
             const nlohmann::json& encoded) {
    if constexpr (HasFields<T>::value) {
      table(path, value, encoded);
    } else if constexpr (IsTableList<T>::value) {
      std::string names;
      for (const auto& e : encoded) names += (names.empty() ? "" : ", ") + e.value("name", "");
      row(path, std::to_string(value.size()) + " entries (" + names + ")", "list", f);
      using E = typename T::value_type;
      table(path + "[]", E{}, nlohmann::json::parse(config_entry_json(E{})));
    } else {
      std::string text = encoded.dump();
      row(path, "`" + text + "`", allowed_of<T>(f), f);
    }
  }

  template <class P>
  void table(const std::string& path, const P& p, const nlohmann::json& encoded) {
    P::fields([&](auto member, const FieldInfo& f) {
      field(join(path, f.key), f, p.*member, encoded.at(f.key));
    });
  }

  template <class E>
  static std::string config_entry_json(const E& e) {
    nlohmann::json j = nlohmann::json::object();
    E::fields([&](auto member, const FieldInfo& f) {
      using T = std::decay_t<decltype(e.*member)>;
      if constexpr (std::is_enum_v<T>)
        j[f.key] = to_string(e.*member);
      else
        j[f.key] = e.*member;
    });
    return j.dump();
  }
};

}  // namespace

void validate(const Config& c, const std::string& origin) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < c.landmarks.classes.size(); ++i) {
    const ClassParams& p = c.landmarks.classes[i];
    const std::string path = "landmarks.classes[" + std::to_string(i) + "].name";
    if (c.label_scheme.find(p.name) < 0)
      throw ConfigError(origin + ": " + path + ": class '" + p.name + "' is not in label scheme '" +
                        c.label_scheme.name + "' (it has: " + c.label_scheme.class_list() + ")");
    if (!names.insert(p.name).second)
      throw ConfigError(origin + ": " + path + ": class '" + p.name + "' listed twice");
  }
  Config::sections(
      [&](auto member, const FieldInfo& f) { check_value(origin, f.key, f, c.*member); });
}

std::string config_reference_markdown() {
  const Config defaults = default_config();
  const nlohmann::json encoded = nlohmann::json::parse(config_to_json(defaults, -1));
  ReferenceWriter w;
  w.out =
      "# Configuration reference\n\nGenerated from the parameter tables by `pagor config "
      "--describe`; the defaults are the `default` preset's.\n";
  Config::sections([&](auto member, const FieldInfo& f) {
    w.out += std::string("\n## `") + f.key + "`: " + f.doc + "\n\n";
    w.out += "| key | default | allowed | unit | what it does |\n| --- | --- | --- | --- | --- |\n";
    w.field(f.key, f, defaults.*member, encoded.at(f.key));
  });
  return w.out;
}

}  // namespace pagor
