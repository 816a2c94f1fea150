#pragma once
/// \file config_args.hpp
/// The options that choose the configuration, shared by `pagor` and `pagor-studio`: one reading of
/// `--config` and `--preset`, and one rule for a floor-plan target given neither.

#include <string>
#include <vector>

#include "common/args.hpp"
#include "pagor/config.hpp"

namespace pagor::cli {

/// A configuration chosen on the command line, and the preset it starts from (the file's own
/// `preset` key, else `--preset`, else the default): what the studio's "defaults" go back to.
struct ChosenConfig {
  Config config;
  std::string preset;
};

/// The preset a configuration document names (its top-level "preset", when a known preset),
/// else `fallback`.
std::string preset_of(const std::string& config_json, const std::string& fallback = "default");

/// `--config FILE` on top of `--preset NAME` (default: the defaults).
ChosenConfig config_from_args(const Args& args);
/// The same, but with neither option given and every target a floor plan (`.json`, `.svg`), the
/// indoor preset, said on stdout: the defaults' classes (car, trunk, ...) are not the indoor label
/// scheme's. Some plans among other targets: UsageError (no preset fits both).
ChosenConfig config_for_targets(const Args& args, const std::vector<std::string>& targets);

/// The options `config_from_args` reads: `--config FILE` and `--preset NAME` (the names from
/// preset_names(); `default_preset` when absent).
std::vector<Option> config_options_for(const std::string& default_preset = "default");
/// The presets' names, "default, paper, indoor".
std::string preset_list();

}  // namespace pagor::cli
