#include "common/pair_args.hpp"

namespace pagor::cli {

Option kitti_root_option(const std::string& beside) {
  return {"kitti-root", 1, "DIR", "KITTI root holding sequences/ (" + beside + ")"};
}

Option sequence_option() {
  return {"sequence", 1, "SEQ", "KITTI sequence (default 00)"};
}

std::string sequence_from_args(const Args& args) {
  return args.get("sequence", "00");
}

std::vector<Option> pair_options() {
  return {
      {"source", 1, "FILE", "source cloud (.bin, .pcd, .ply)"},
      {"target", 1, "FILE", "target cloud"},
      {"source-labels", 1, "FILE", "SemanticKITTI .label file for --source"},
      {"target-labels", 1, "FILE", "SemanticKITTI .label file for --target"},
      kitti_root_option("instead of --source/--target"),
      sequence_option(),
      {"pair", 2, "S T", "KITTI source and target frame numbers"},
      {"synthetic", 1, "SEED", "the generated scene with that seed"},
      {"ground-truth", 1, "FILE", "4x4 T_target_source (row-major) to judge the result against"},
  };
}

std::vector<Option> pair_set_options() {
  return {
      {"manifest", 1, "FILE",
       "pairs manifest: 'SOURCE TARGET [gt=FILE] [source_labels=FILE] [target_labels=FILE] "
       "[name=TEXT] [overlap=no]' per line, paths relative to it"},
      kitti_root_option("with --pairs"),
      sequence_option(),
      {"pairs", 1, "FILE", "KITTI pairs file: 'source target' frame numbers per line"},
  };
}

std::optional<PairSource> pair_source_from_args(const Args& args) {
  const int chosen = args.has("source") + args.has("kitti-root") + args.has("synthetic");
  if (chosen == 0) return std::nullopt;
  if (chosen > 1)
    throw UsageError(
        "choose one input: --source S --target T, --kitti-root DIR --pair S T, "
        "or --synthetic SEED");
  PairSource src;
  if (args.has("source")) {
    if (!args.has("target")) throw UsageError("--source needs --target");
    src.kind = PairSource::Kind::files;
    src.source = args.get("source");
    src.target = args.get("target");
    src.source_labels = args.get("source-labels");
    src.target_labels = args.get("target-labels");
  } else if (args.has("kitti-root")) {
    if (!args.has("pair")) throw UsageError("--kitti-root needs --pair S T");
    src.kind = PairSource::Kind::kitti;
    src.kitti_root = args.get("kitti-root");
    src.sequence = sequence_from_args(args);
    src.source_frame = parse_int(args.all("pair")[0], "--pair (source frame)");
    src.target_frame = parse_int(args.all("pair")[1], "--pair (target frame)");
  } else {
    src.kind = PairSource::Kind::synthetic;
    src.synthetic_seed =
        static_cast<std::uint64_t>(parse_int(args.get("synthetic"), "--synthetic"));
  }
  src.ground_truth = args.get("ground-truth");
  return src;
}

PairSet pair_set_from_args(const Args& args, const std::string& command) {
  if (args.has("manifest")) {
    if (args.has("kitti-root") || args.has("pairs"))
      throw UsageError("choose --manifest FILE or --kitti-root DIR --pairs FILE, not both");
    return read_pair_manifest(args.get("manifest"));
  }
  if (!args.has("kitti-root") || !args.has("pairs"))
    throw UsageError(command + " needs --manifest FILE, or --kitti-root DIR and --pairs FILE");
  return kitti_pair_set(args.get("kitti-root"), sequence_from_args(args), args.get("pairs"));
}

std::vector<std::string> pair_targets(const PairSet& set) {
  std::vector<std::string> targets;
  for (const PairEntry& e : set.pairs)
    targets.push_back(e.source.kind == PairSource::Kind::files ? e.source.target : "");
  return targets;
}

}  // namespace pagor::cli
