#include "json_objects.hpp"

#include <cmath>
#include <limits>

#include "pagor/errors.hpp"

namespace pagor::python {

py::object to_python(const nlohmann::json& value) {
  using T = nlohmann::json::value_t;
  switch (value.type()) {
    case T::null:
    case T::discarded:
      return py::none();
    case T::boolean:
      return py::bool_(value.get<bool>());
    case T::number_integer:
      return py::int_(value.get<std::int64_t>());
    case T::number_unsigned:
      return py::int_(value.get<std::uint64_t>());
    case T::number_float:
      return py::float_(value.get<double>());
    case T::string: {
      // A report may hold bytes that are not UTF-8 (a file's name): replaced, never thrown on.
      const std::string& text = value.get_ref<const std::string&>();
      return py::reinterpret_steal<py::str>(
          PyUnicode_DecodeUTF8(text.data(), static_cast<py::ssize_t>(text.size()), "replace"));
    }
    case T::array: {
      py::list out;
      for (const auto& item : value) out.append(to_python(item));
      return std::move(out);
    }
    case T::object: {
      py::dict out;
      for (const auto& [key, item] : value.items()) out[py::str(key)] = to_python(item);
      return std::move(out);
    }
    case T::binary:
      break;
  }
  throw py::value_error("unexpected binary value in a JSON document");
}

namespace {

[[noreturn]] void fail(const std::string& origin, const std::string& path,
                       const std::string& what) {
  throw py::value_error(origin + ": " + (path.empty() ? std::string("the document") : path) + ": " +
                        what);
}

// A str as UTF-8; one that cannot be (lone surrogates: bytes decoded with surrogateescape) is a
// ValueError naming the key path.
std::string utf8(const py::handle& text, const std::string& origin, const std::string& path,
                 const char* what) {
  Py_ssize_t size = 0;
  const char* data = PyUnicode_AsUTF8AndSize(text.ptr(), &size);
  if (data == nullptr) {
    PyErr_Clear();
    fail(origin, path,
         std::string(what) + " " +
             std::string(py::reinterpret_steal<py::str>(PyObject_ASCII(text.ptr()))) +
             " is not valid UTF-8 text");
  }
  return std::string(data, static_cast<std::size_t>(size));
}

}  // namespace

nlohmann::json from_python(const py::handle& object, const std::string& origin,
                           const std::string& path, int depth) {
  if (depth > kMaxNesting)
    fail(origin, path, "nested deeper than " + std::to_string(kMaxNesting) + " levels");
  if (object.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(object)) return object.cast<bool>();
  if (py::isinstance<py::int_>(object) ||
      (!py::isinstance<py::float_>(object) && PyIndex_Check(object.ptr()))) {  // numpy integers
    const py::int_ i = py::reinterpret_steal<py::int_>(PyNumber_Index(object.ptr()));
    if (i >= py::int_(std::numeric_limits<std::int64_t>::min()) &&
        i <= py::int_(std::numeric_limits<std::int64_t>::max()))
      return i.cast<std::int64_t>();
    fail(origin, path, std::string(py::str(py::handle(i))) + " does not fit a 64-bit integer");
  }
  if (py::isinstance<py::float_>(object)) {
    const double v = object.cast<double>();
    if (!std::isfinite(v))
      fail(origin, path, std::string(py::str(object)) + " is not a finite number");
    return v;
  }
  if (py::isinstance<py::str>(object)) return utf8(object, origin, path, "the string");
  if (py::isinstance<py::dict>(object)) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [key, item] : py::reinterpret_borrow<py::dict>(object)) {
      if (!py::isinstance<py::str>(key))
        fail(origin, path, "keys must be strings, got " + std::string(py::repr(key)));
      const std::string name = utf8(key, origin, path, "the key");
      out[name] = from_python(item, origin, path.empty() ? name : path + "." + name, depth + 1);
    }
    return out;
  }
  if (py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object)) {
    nlohmann::json out = nlohmann::json::array();
    std::size_t index = 0;
    for (const auto& item : object)
      out.push_back(
          from_python(item, origin, path + "[" + std::to_string(index++) + "]", depth + 1));
    return out;
  }
  fail(origin, path,
       "a value of type " + std::string(py::str(py::type::handle_of(object).attr("__name__"))) +
           " cannot be a JSON value (use dict, list, str, int, float, bool or None)");
}

Config config_from_python(const py::handle& config) {
  if (config.is_none()) return default_config();
  if (!py::isinstance<py::dict>(config))
    throw py::type_error("config: expected a dict (the JSON configuration's keys) or None, got " +
                         std::string(py::str(py::type::handle_of(config).attr("__name__"))));
  // The core's parser names the key path of an unknown key, a wrong type or a value out of range
  // (ConfigError, raised as pagor.Error, a ValueError).
  return parse_config(from_python(config, "config").dump(), "config");
}

py::dict config_to_python(const Config& config) {
  return to_python(nlohmann::json::parse(config_to_json(config)));
}

}  // namespace pagor::python
