// The configuration document, generated from the parameter tables (util/fields.hpp): every
// section of Config::sections and every field of each Params::fields is written, read and checked
// here by type, so no section or field is named in this file.

#include <cassert>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <type_traits>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/errors.hpp"
#include "pagor/io/json_input.hpp"

namespace pagor {
namespace {

using json = nlohmann::json;

// ---- writing ----------------------------------------------------------------------------------

json encode_scheme(const LabelScheme& s) {
  for (const auto& name : builtin_label_scheme_names()) {
    if (name != s.name) continue;
    const LabelScheme b = builtin_label_scheme(name);
    bool same = b.classes.size() == s.classes.size();
    for (std::size_t i = 0; same && i < b.classes.size(); ++i)
      same = b.classes[i].name == s.classes[i].name && b.classes[i].ids == s.classes[i].ids;
    if (same) return s.name;
  }
  json classes = json::object();
  for (const auto& c : s.classes) classes[c.name] = c.ids;
  return json{{"name", s.name}, {"classes", classes}};
}

template <class T>
json encode(const T& x) {
  if constexpr (std::is_same_v<T, LabelScheme>) {
    return encode_scheme(x);
  } else if constexpr (std::is_enum_v<T>) {
    return to_string(x);
  } else if constexpr (HasFields<T>::value) {
    json j = json::object();
    T::fields([&](auto member, const FieldInfo& f) { j[f.key] = encode(x.*member); });
    return j;
  } else if constexpr (detail::IsVector<T>::value) {
    json a = json::array();
    for (const auto& e : x) a.push_back(encode(e));
    return a;
  } else {
    return json(x);  // numbers, flags, strings
  }
}

json encode_config(const Config& c) {
  json j = json::object();
  Config::sections([&](auto member, const FieldInfo& f) { j[f.key] = encode(c.*member); });
  return j;
}

// ---- reading ----------------------------------------------------------------------------------

[[noreturn]] void fail(const std::string& origin, const std::string& path,
                       const std::string& what) {
  throw ConfigError(origin + ": " + path + ": " + what);
}

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

void decode_scheme(const std::string& origin, const json& j, const std::string& path,
                   LabelScheme& s) {
  if (j.is_string()) {
    try {
      s = builtin_label_scheme(j.get<std::string>());
    } catch (const ConfigError& e) {
      fail(origin, path, e.what());
    }
    return;
  }
  if (!j.is_object())
    fail(origin, path, "expected a scheme name or an object, got " + std::string(j.type_name()));
  s = LabelScheme{};
  for (const auto& item : j.items()) {
    if (item.key() == "name") {
      if (!item.value().is_string()) fail(origin, path + ".name", "expected a string");
      s.name = item.value().get<std::string>();
    } else if (item.key() == "classes") {
      if (!item.value().is_object())
        fail(origin, path + ".classes", "expected an object {\"class\": [ids]}");
      for (const auto& c : item.value().items()) {
        SemanticClass sc{c.key(), {}};
        const std::string cpath = path + ".classes." + c.key();
        if (!c.value().is_array()) fail(origin, cpath, "expected an array of label ids");
        for (std::size_t i = 0; i < c.value().size(); ++i) {
          const std::string where = origin + ": " + cpath + "[" + std::to_string(i) + "]";
          const std::uint64_t id = json_unsigned(c.value()[i], where, 0xFFFFu);
          sc.ids.push_back(static_cast<std::uint32_t>(id));
        }
        s.classes.push_back(std::move(sc));
      }
    } else {
      fail(origin, path + "." + item.key(), "unknown key");
    }
  }
  if (s.name.empty()) fail(origin, path + ".name", "missing");
  if (s.automatic() || s.ignores_labels())
    fail(origin, path + ".name", "'" + s.name + "' is a built-in scheme; give it by name alone");
  if (s.classes.empty()) fail(origin, path + ".classes", "missing or empty");
}

template <class T>
void decode(const std::string& origin, const json& j, const std::string& path, T& x) {
  const std::string where = origin + ": " + path;
  if constexpr (std::is_same_v<T, LabelScheme>) {
    decode_scheme(origin, j, path, x);
  } else if constexpr (std::is_enum_v<T>) {
    const auto v = j.is_string() ? enum_from_string<T>(j.get<std::string>()) : std::nullopt;
    if (!v)
      fail(origin, path, "expected one of " + enum_name_list<T>() + ", got " + json_excerpt(j));
    x = *v;
  } else if constexpr (HasFields<T>::value) {
    if (!j.is_object()) fail(origin, path, "expected an object, got " + std::string(j.type_name()));
    std::set<std::string> known;
    T::fields([&](auto member, const FieldInfo& f) {
      known.insert(f.key);
      const auto it = j.find(f.key);
      if (it != j.end()) decode(origin, *it, join(path, f.key), x.*member);
    });
    for (const auto& item : j.items())
      if (!known.count(item.key())) fail(origin, join(path, item.key()), "unknown key");
  } else if constexpr (detail::IsVector<T>::value) {
    if (!j.is_array()) fail(origin, path, "expected an array, got " + std::string(j.type_name()));
    x.assign(j.size(), typename T::value_type{});
    for (std::size_t i = 0; i < j.size(); ++i)
      decode(origin, j[i], path + "[" + std::to_string(i) + "]", x[i]);
  } else if constexpr (std::is_same_v<T, bool>) {
    if (!j.is_boolean())
      fail(origin, path, "expected true or false, got " + std::string(j.type_name()));
    x = j.get<bool>();
  } else if constexpr (std::is_same_v<T, std::string>) {
    if (!j.is_string()) fail(origin, path, "expected a string, got " + std::string(j.type_name()));
    x = j.get<std::string>();
  } else if constexpr (std::is_floating_point_v<T>) {
    x = json_finite(j, where);  // finite only
  } else if constexpr (std::is_unsigned_v<T>) {
    x = static_cast<T>(json_unsigned(j, where, std::numeric_limits<T>::max()));
  } else {
    static_assert(std::is_integral_v<T>, "a field type the document cannot hold");
    x = static_cast<T>(
        json_integer(j, where, std::numeric_limits<T>::min(), std::numeric_limits<T>::max()));
  }
}

}  // namespace

Config parse_config(const std::string& json_text, const std::string& origin,
                    const std::string& base_preset) {
  const json j = parse_json_limited(json_text, origin);
  if (!j.is_object()) throw ConfigError(origin + ": expected a JSON object at the top level");
  std::string preset = base_preset;
  if (const auto it = j.find("preset"); it != j.end()) decode(origin, *it, "preset", preset);
  Config c;
  try {
    c = preset_config(preset);
  } catch (const ConfigError& e) {
    fail(origin, "preset", e.what());
  }
  std::set<std::string> known{"preset"};
  Config::sections([&](auto member, const FieldInfo& f) {
    known.insert(f.key);
    if (const auto it = j.find(f.key); it != j.end()) decode(origin, *it, f.key, c.*member);
  });
  for (const auto& item : j.items())
    if (!known.count(item.key())) fail(origin, item.key(), "unknown key");
  validate(c, origin);
  return c;
}

std::string config_to_json(const Config& config, int indent) {
  return encode_config(config).dump(indent);
}

std::string section_json(const Config& config, const std::string& section) {
  std::string out;
  bool found = false;
  Config::sections([&](auto member, const FieldInfo& f) {
    if (section != f.key) return;
    found = true;
    out = encode(config.*member).dump();
  });
  if (!found) throw ConfigError("config: no section '" + section + "'");
  return out;
}

}  // namespace pagor
