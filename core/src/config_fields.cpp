// Parameters by key path, generated from the parameter tables: the catalog the studio's editor,
// sweeps and the Python bindings read and write a configuration through.

#include <cmath>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "pagor/config.hpp"
#include "pagor/errors.hpp"

namespace pagor {
namespace {

template <class T>
struct IsTableList : std::false_type {};
template <class E>
struct IsTableList<std::vector<E>> : HasFields<E> {};

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

// Calls f(path, info, value&) for every leaf parameter under `x` (a table, a list of tables or a
// value); `T` may be const.
template <class T, class F>
void walk(T& x, const std::string& path, const FieldInfo& info, F& f) {
  using U = std::remove_const_t<T>;
  if constexpr (HasFields<U>::value) {
    U::fields(
        [&](auto member, const FieldInfo& fi) { walk(x.*member, join(path, fi.key), fi, f); });
  } else if constexpr (IsTableList<U>::value) {
    for (std::size_t i = 0; i < x.size(); ++i)
      walk(x[i], path + "[" + std::to_string(i) + "]", info, f);
  } else {
    f(path, info, x);
  }
}

template <class C, class F>
void walk_config(C& config, F&& f) {
  Config::sections([&](auto member, const FieldInfo& fi) { walk(config.*member, fi.key, fi, f); });
}

template <class T>
constexpr bool kNumeric = std::is_arithmetic_v<T>;  // bool included

// "landmarks.classes[2].voxel_size" -> "/landmarks/classes/2/voxel_size"
nlohmann::json::json_pointer pointer_of(const std::string& path) {
  std::string p = "/";
  for (char c : path) {
    if (c == '.' || c == '[')
      p += '/';
    else if (c != ']')
      p += c;
  }
  return nlohmann::json::json_pointer(p);
}

[[noreturn]] void unknown(const std::string& path) {
  throw ConfigError("config: " + path + ": no such parameter");
}

}  // namespace

std::vector<ConfigField> config_fields(const Config& config) {
  std::vector<ConfigField> out;
  walk_config(config, [&](const std::string& path, const FieldInfo& info, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    ConfigField f{path, info, FieldKind::other, {}};
    if constexpr (std::is_same_v<T, bool>) {
      f.kind = FieldKind::flag;
    } else if constexpr (std::is_enum_v<T>) {
      f.kind = FieldKind::choice;
      for (const auto& e : enum_entries(T{})) f.choices.push_back(e.name);
    } else if constexpr (std::is_floating_point_v<T>) {
      f.kind = FieldKind::number;
    } else if constexpr (std::is_integral_v<T>) {
      f.kind = FieldKind::integer;
    } else if constexpr (std::is_same_v<T, std::string>) {
      f.kind = FieldKind::text;
    } else if constexpr (std::is_same_v<T, std::vector<double>>) {
      f.kind = FieldKind::numbers;
    }
    out.push_back(std::move(f));
  });
  return out;
}

std::string field_json(const Config& config, const std::string& path) {
  const nlohmann::json j = nlohmann::json::parse(config_to_json(config, -1));
  const auto ptr = pointer_of(path);
  if (!j.contains(ptr)) unknown(path);
  return j.at(ptr).dump();
}

void set_field_json(Config& config, const std::string& path, const std::string& json_text) {
  set_fields_json(config, {{path, json_text}});
}

void set_fields_json(Config& config,
                     const std::vector<std::pair<std::string, std::string>>& values) {
  nlohmann::json j = nlohmann::json::parse(config_to_json(config, -1));
  for (const auto& [path, json_text] : values) {
    const auto ptr = pointer_of(path);
    if (!j.contains(ptr)) unknown(path);
    nlohmann::json value;
    try {
      value = nlohmann::json::parse(json_text);
    } catch (const nlohmann::json::exception&) {
      throw ConfigError("config: " + path + ": not JSON: " + json_text.substr(0, 60));
    }
    j[ptr] = std::move(value);
  }
  config = parse_config(j.dump(), "config");  // every key present: the preset adds nothing
}

std::optional<double> field_number(const Config& config, const std::string& path) {
  std::optional<double> out;
  walk_config(config, [&](const std::string& p, const FieldInfo&, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    if constexpr (kNumeric<T>)
      if (p == path) out = static_cast<double>(value);
  });
  return out;
}

void set_field_number(Config& config, const std::string& path, double value) {
  Config changed = config;
  bool found = false;
  walk_config(changed, [&](const std::string& p, const FieldInfo&, auto& field) {
    using T = std::decay_t<decltype(field)>;
    if constexpr (kNumeric<T>) {
      if (p != path) return;
      found = true;
      if constexpr (std::is_same_v<T, bool>) {
        field = value != 0;
      } else if constexpr (std::is_integral_v<T>) {
        const double r = std::round(value);
        // Bounds that doubles hold exactly: [min, -min) signed, [0, max + 1) unsigned.
        const double lo = static_cast<double>(std::numeric_limits<T>::min());
        const double hi =
            std::is_signed_v<T> ? -lo : static_cast<double>(std::numeric_limits<T>::max()) + 1.0;
        if (!(r >= lo && r < hi))
          throw ConfigError("config: " + path + ": " + number_text(value) +
                            " is not an integer "
                            "this parameter can hold");
        field = static_cast<T>(r);
      } else {
        if (!std::isfinite(value))
          throw ConfigError("config: " + path + ": " + number_text(value) + " is not finite");
        field = value;
      }
    }
  });
  if (!found) unknown(path);
  validate(changed);
  config = std::move(changed);
}

}  // namespace pagor
