#include "common/config_args.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "pagor/errors.hpp"
#include "pagor/indoor/floor_plan.hpp"
#include "pagor/io/file_input.hpp"

namespace pagor::cli {

std::string preset_of(const std::string& config_json, const std::string& fallback) {
  const auto j = nlohmann::json::parse(config_json, nullptr, false);
  if (j.is_object() && j.contains("preset") && j["preset"].is_string()) {
    const std::string name = j["preset"].get<std::string>();
    const auto names = preset_names();
    if (std::find(names.begin(), names.end(), name) != names.end()) return name;
  }
  return fallback;
}

ChosenConfig config_from_args(const Args& args) {
  ChosenConfig c{Config{}, args.get("preset", "default")};
  if (!args.has("config")) {
    c.config = preset_config(c.preset);
    return c;
  }
  const std::string path = args.get("config");
  const std::string text = read_file(path, "config file", kMaxTextFileBytes);
  c.config = parse_config(text, path, c.preset);
  c.preset = preset_of(text, c.preset);  // a file's own preset wins over --preset (parse_config)
  return c;
}

ChosenConfig config_for_targets(const Args& args, const std::vector<std::string>& targets) {
  const auto plans = static_cast<std::size_t>(std::count_if(
      targets.begin(), targets.end(), [](const std::string& t) { return is_floor_plan_path(t); }));
  if (args.has("preset") || args.has("config") || plans == 0) return config_from_args(args);
  if (plans < targets.size())
    throw UsageError(std::to_string(plans) + " of the " + std::to_string(targets.size()) +
                     " targets are floor plans: choose the configuration with --preset or "
                     "--config (indoor for the plans), or run the plans as a set of their own");
  std::printf("preset: indoor (the target is a floor plan; --preset or --config to choose)\n");
  return {preset_config("indoor"), "indoor"};
}

std::string preset_list() {
  std::string names;
  for (const std::string& n : preset_names()) names += (names.empty() ? "" : ", ") + n;
  return names;
}

std::vector<Option> config_options_for(const std::string& default_preset) {
  return {{"config", 1, "FILE", "configuration JSON (absent keys: the preset's values)"},
          {"preset", 1, "NAME",
           "base configuration: " + preset_list() + " (default " + default_preset +
               "; paper: the published one)"}};
}

}  // namespace pagor::cli
