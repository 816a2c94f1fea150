// pagor register --correspondences FILE: the back end on any matcher's correspondences, through
// the Pipeline (set_matches). Graph -> clique -> pose per level; with clouds also verification,
// refinement and acceptance, and with --fuse the clouds' landmark correspondences beside the
// matcher's in one pyramid (correspondences.fuse_matches), counted per origin; with --ground-truth
// the errors per level and of the selection; with ground-truth inlier flags in the file each
// level's precision and recall. The JSON result is the main report (pagor.register/1) with the
// file's details under `correspondences`.

#include <cstdio>

#include "command.hpp"
#include "pagor/io/correspondence_file.hpp"
#include "pagor/pipeline.hpp"

namespace pagor::cli {

int run_register_correspondences(const Args& args, Config config) {
  if (args.has("fuse")) {
    if (!pair_source_from_args(args))
      throw UsageError(
          "--fuse needs the clouds (--source S --target T or --kitti-root DIR --pair "
          "S T): their landmarks join the matcher's correspondences");
    config.correspondences.fuse_matches = true;
  }
  const std::string file = args.get("correspondences");
  CorrespondenceFile input = read_correspondence_file(file);
  std::printf("correspondences: %zu from %s%s%s\n", input.items.size(), file.c_str(),
              input.weights.empty() ? "" : " (weighted)",
              input.inlier.empty() ? "" : " (with inlier flags)");
  Pipeline pipeline(config, args.get_int("threads", 1));
  pipeline.set_matches(input.items);
  std::string source_name = file, target_name = file;
  if (const auto src = pair_source_from_args(args)) {
    LoadedPair pair = load_pair(*src, config.indoor);
    for (const auto& w : pair.source.warnings) warn(w);
    for (const auto& w : pair.target.warnings) warn(w);
    std::printf("clouds for verification: %s\n", describe(*src).c_str());
    pipeline.set_input(std::move(pair.source.cloud), std::move(pair.target.cloud));
    pipeline.set_ground_truth(pair.T_target_source_gt);
    source_name = pair.source_name;
    target_name = pair.target_name;
  } else if (args.has("ground-truth")) {
    pipeline.set_ground_truth(read_transform_file(args.get("ground-truth")));
  }
  with_config_origin(args, [&] { pipeline.run(); });
  warn_all(pipeline.warnings(), args.has("verbose"));
  RegistrationContext context;
  context.source_name = source_name;
  context.target_name = target_name;
  context.matches_file = MatchesFileInfo{file, !input.weights.empty(), input.inlier};
  report_registration(args, pipeline, context);
  return 0;
}

}  // namespace pagor::cli
