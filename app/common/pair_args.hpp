#pragma once
/// \file pair_args.hpp
/// The options that select a registration pair, shared by `pagor` and `pagor-studio`.

#include <optional>
#include <string>
#include <vector>

#include "common/args.hpp"
#include "pagor/eval/dataset.hpp"
#include "pagor/eval/pair_set.hpp"

namespace pagor::cli {

/// `--kitti-root DIR`; `beside` says how it goes with the other inputs ("instead of --source").
Option kitti_root_option(const std::string& beside);
/// `--sequence SEQ`, with kitti-root: the sequence (sequence_from_args).
Option sequence_option();
/// The sequence `--sequence` names; 00 when none does.
std::string sequence_from_args(const Args& args);

/// `--source/--target` (+ labels), `--kitti-root/--sequence/--pair`, or `--synthetic`.
std::vector<Option> pair_options();

/// The pair those options select; nullopt when none is given. Throws UsageError for two inputs at
/// once or an incomplete one.
std::optional<PairSource> pair_source_from_args(const Args& args);

/// `--manifest`, `--kitti-root`, `--sequence`, `--pairs`: the options pair_set_from_args reads.
std::vector<Option> pair_set_options();

/// `--manifest FILE`, or `--kitti-root DIR --pairs FILE [--sequence SEQ]`: the set of pairs a
/// `command` runs. Throws UsageError for both or neither.
PairSet pair_set_from_args(const Args& args, const std::string& command);

/// Each pair's target file, "" for a pair that is not files (a KITTI frame): what
/// config_for_targets (config_args.hpp) chooses a set's preset from.
std::vector<std::string> pair_targets(const PairSet& set);

}  // namespace pagor::cli
