#pragma once
/// \file outputs.hpp
/// An output never overwrites an input: before anything runs, each file a command would write is
/// compared with the files it reads (by identity: `./a.pcd`, `a.pcd` and a symbolic link to it are
/// the same file) and with the other outputs.

#include <string>
#include <vector>

#include "common/args.hpp"
#include "pagor/eval/pair_set.hpp"

namespace pagor::cli {

/// A file and what names it ("--json", "--source", "pair 03's ground truth").
struct NamedPath {
  std::string what;
  std::string path;
};

/// The files the usual input options of `args` name (--source, --target, their labels,
/// --ground-truth, --config, --correspondences, --manifest, --pairs, --session), those present.
std::vector<NamedPath> option_inputs(const Args& args);

/// Every file the pairs of `set` read (clouds, labels, ground truths, plans; a KITTI pair's
/// scans, labels, poses.txt and calib.txt).
std::vector<NamedPath> set_inputs(const PairSet& set);

/// Throws UsageError naming both when an output is the same file as an input or as another
/// output. Outputs that do not exist yet cannot be inputs; two of them are compared by path.
void check_outputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

}  // namespace pagor::cli
