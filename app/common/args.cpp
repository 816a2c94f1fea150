#include "common/args.hpp"

#include <cstdlib>

namespace pagor::cli {

std::vector<Option> joined(std::vector<Option> first,
                           std::initializer_list<std::vector<Option>> more) {
  for (const std::vector<Option>& group : more)
    first.insert(first.end(), group.begin(), group.end());
  return first;
}

int parse_int(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v < -2147483647L || v > 2147483647L)
    throw UsageError(what + ": expected an integer, got '" + text + "'");
  return static_cast<int>(v);
}

Args::Args(const std::vector<std::string>& argv, const std::vector<Option>& options) {
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& word = argv[i];
    if (word.rfind("--", 0) != 0) throw UsageError("unexpected argument '" + word + "'");
    const std::string name = word.substr(2);
    const Option* opt = nullptr;
    for (const auto& o : options)
      if (o.name == name) opt = &o;
    if (!opt) throw UsageError("unknown option '" + word + "' (see --help)");
    if (values_.count(name)) throw UsageError("option '" + word + "' given twice");
    std::vector<std::string> vals;
    for (int k = 0; k < opt->values; ++k) {
      if (i + 1 >= argv.size() || argv[i + 1].rfind("--", 0) == 0)
        throw UsageError("option '" + word + "' needs " + std::to_string(opt->values) +
                         " value(s): " + word + " " + opt->meta);
      vals.push_back(argv[++i]);
    }
    values_[name] = std::move(vals);
  }
}

std::string Args::get(const std::string& name, const std::string& fallback) const {
  const auto it = values_.find(name);
  return it == values_.end() || it->second.empty() ? fallback : it->second.front();
}

const std::vector<std::string>& Args::all(const std::string& name) const {
  static const std::vector<std::string> kEmpty;
  const auto it = values_.find(name);
  return it == values_.end() ? kEmpty : it->second;
}

int Args::get_int(const std::string& name, int fallback) const {
  return has(name) ? parse_int(get(name), "--" + name) : fallback;
}

std::string format_options(const std::vector<Option>& options) {
  std::string out;
  for (const auto& o : options) {
    std::string left = "  --" + o.name + (o.meta.empty() ? "" : " " + o.meta);
    if (left.size() < 34)
      left.resize(34, ' ');
    else
      left += "\n" + std::string(34, ' ');
    out += left + o.help + "\n";
  }
  return out;
}

}  // namespace pagor::cli
