#pragma once
/// \file session_json.hpp
/// Typed readers of the session file: each names the file and key path of a wrong value and
/// never converts a value out of its range (state/session.cpp and session_bench.cpp).

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pagor::studio::session_json {

using json = nlohmann::json;

/// "where.key"
std::string key_path(const std::string& where, const char* key);
/// The member `key`, null when absent or null.
const json* find(const json& j, const char* key);
/// A string member, `fallback` when absent; InputError for another type.
std::string get_string(const json& j, const char* key, const std::string& where,
                       const std::string& fallback);
/// A boolean member, `fallback` when absent.
bool get_bool(const json& j, const char* key, const std::string& where, bool fallback);
/// An integer in [lo, hi]; a float or a value out of range is an InputError, never converted.
long long integer_value(const json& v, const std::string& path, long long lo, long long hi);
/// An integer member in [lo, hi], `fallback` when absent.
int get_int(const json& j, const char* key, const std::string& where, int fallback, int lo, int hi);
/// A number member in [lo, hi], `fallback` when absent.
float get_float(const json& j, const char* key, const std::string& where, float fallback, float lo,
                float hi);
/// InputError naming the first member not in `known`.
void reject_unknown(const json& j, const std::string& where,
                    std::initializer_list<const char*> known);
/// One of `names` (its index), naming the file and key when it is none of them.
int get_choice(const json& j, const char* key, const std::string& where,
               const std::vector<std::string>& names);
/// A float as the double its shortest decimal names, for writing.
json number(float f);

}  // namespace pagor::studio::session_json

namespace pagor::studio {

struct AppState;
struct SessionState;

/// The benchmark view's part of a session (session_bench.cpp): written, and read back with the
/// same checks as the rest.
nlohmann::json bench_json(const SessionState& s);
void read_bench(const nlohmann::json& j, const std::string& where, AppState& s);

}  // namespace pagor::studio
