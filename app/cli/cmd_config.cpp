// pagor config: the configuration document: the defaults, a preset, a checked file, or the
// reference of every parameter (generated from the parameter tables).

#include <cstdio>

#include "command.hpp"

namespace pagor::cli {

std::vector<Option> config_options() {
  return {
      {"print-default", 0, "", "print the full default configuration as JSON"},
      {"preset", 1, "NAME", "print a preset (" + preset_list() + ") as JSON"},
      {"check", 1, "FILE", "validate a configuration file and print it with defaults filled in"},
      {"describe", 0, "",
       "print the reference of every parameter (key, default, allowed values, unit, meaning) "
       "as Markdown"}};
}

int run_config(const Args& args) {
  if (args.has("print-default") + args.has("check") + args.has("preset") + args.has("describe") !=
      1)
    throw UsageError("give one of --print-default, --preset NAME, --check FILE or --describe");
  if (args.has("describe")) {
    std::printf("%s", config_reference_markdown().c_str());
    return 0;
  }
  const Config config = args.has("check")    ? load_config(args.get("check"))
                        : args.has("preset") ? preset_config(args.get("preset"))
                                             : default_config();
  std::printf("%s\n", config_to_json(config).c_str());
  return 0;
}

}  // namespace pagor::cli
