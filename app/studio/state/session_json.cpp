#include "state/session_json.hpp"

#include "pagor/errors.hpp"
#include "widgets/number_format.hpp"

namespace pagor::studio::session_json {

std::string key_path(const std::string& where, const char* key) {
  return where + "." + key;
}

const json* find(const json& j, const char* key) {
  const auto it = j.find(key);
  return it == j.end() || it->is_null() ? nullptr : &*it;
}

std::string get_string(const json& j, const char* key, const std::string& where,
                       const std::string& fallback) {
  const json* v = find(j, key);
  if (!v) return fallback;
  if (!v->is_string())
    throw InputError(key_path(where, key) + ": expected a string, got " + v->dump());
  return v->get<std::string>();
}

bool get_bool(const json& j, const char* key, const std::string& where, bool fallback) {
  const json* v = find(j, key);
  if (!v) return fallback;
  if (!v->is_boolean())
    throw InputError(key_path(where, key) + ": expected true or false, got " + v->dump());
  return v->get<bool>();
}

// An integer in [lo, hi]; a float or a value out of range is an error, never converted.
long long integer_value(const json& v, const std::string& path, long long lo, long long hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!v.is_number_integer())
    throw InputError(path + ": expected an integer in " + range + ", got " + v.dump());
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(hi))
    throw InputError(path + ": " + v.dump() + " is outside " + range);
  const long long x =
      v.is_number_unsigned() ? static_cast<long long>(v.get<std::uint64_t>()) : v.get<long long>();
  if (x < lo || x > hi) throw InputError(path + ": " + v.dump() + " is outside " + range);
  return x;
}

int get_int(const json& j, const char* key, const std::string& where, int fallback, int lo,
            int hi) {
  const json* v = find(j, key);
  return v ? static_cast<int>(integer_value(*v, key_path(where, key), lo, hi)) : fallback;
}

float get_float(const json& j, const char* key, const std::string& where, float fallback, float lo,
                float hi) {
  const json* v = find(j, key);
  if (!v) return fallback;
  const std::string path = key_path(where, key);
  if (!v->is_number()) throw InputError(path + ": expected a number, got " + v->dump());
  const double x = v->get<double>();
  if (!(x >= lo && x <= hi))
    throw InputError(path + ": " + v->dump() + " is outside [" + json(lo).dump() + ", " +
                     json(hi).dump() + "]");
  return static_cast<float>(x);
}

void reject_unknown(const json& j, const std::string& where,
                    std::initializer_list<const char*> known) {
  for (const auto& item : j.items()) {
    bool ok = false;
    for (const char* k : known) ok = ok || item.key() == k;
    if (!ok) throw InputError(where + "." + item.key() + ": unknown key");
  }
}

// A float as the double its shortest decimal names, for writing.
json number(float f) {
  return shortest(f);
}

// One of `names` (their index), naming the file and key when it is none of them.
int get_choice(const json& j, const char* key, const std::string& where,
               const std::vector<std::string>& names) {
  const std::string value = get_string(j, key, where, names.front());
  const auto it = std::find(names.begin(), names.end(), value);
  if (it != names.end()) return static_cast<int>(it - names.begin());
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "\"" : ", \"") + n + "\"";
  throw InputError(key_path(where, key) + ": expected one of " + list + ", got \"" + value + "\"");
}

}  // namespace pagor::studio::session_json
