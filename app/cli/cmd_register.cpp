// pagor register: one registration, with a per-level summary and a JSON result.

#include <chrono>
#include <cstdio>

#include "command.hpp"
#include "common/outputs.hpp"
#include "pagor/errors.hpp"
#include "pagor/pipeline.hpp"

namespace pagor::cli {

std::string labels_text(const LabelReading& r) {
  std::string s = r.scheme.name;
  if (r.scheme.ignores_labels())
    return s + " (" + (r.detection.reason.empty() ? "not used" : r.detection.reason) + ")";
  if (r.automatic) {
    char buf[64];
    std::snprintf(buf, sizeof(buf), " (detected; %.1f nats a point over %s)", r.detection.margin,
                  r.detection.runner_up.c_str());
    return s + buf;
  }
  return s + (r.mismatch.empty() ? " (configured)" : " (configured; does not fit)");
}

std::vector<Option> register_options() {
  std::vector<Option> o = pair_options();
  for (Option& c : config_options_for("default, indoor when the target is a floor plan"))
    o.push_back(std::move(c));
  o.push_back({"json", 1, "OUT", "write the result as JSON (schema pagor.register/1)"});
  o.push_back(threads_option());
  o.push_back({"verbose", 0, "",
               "list every warning (by default the benign ones, such as a class with a few points "
               "but no landmark, are summed up in one line)"});
  o.push_back({"correspondences", 1, "FILE",
               "register these correspondences (px py pz qx qy qz [weight [inlier 0/1]] per "
               "line) instead of extracting landmarks; clouds, if given, only verify"});
  o.push_back({"fuse", 0, "",
               "with --correspondences and clouds: the clouds' landmark correspondences join the "
               "file's in one pyramid (sets correspondences.fuse_matches)"});
  return o;
}

int run_register(const Args& args) {
  if (args.has("json")) check_outputs({{"--json", args.get("json")}}, option_inputs(args));
  const Config config =
      config_for_targets(args, args.has("target") ? std::vector<std::string>{args.get("target")}
                                                  : std::vector<std::string>{})
          .config;
  if (args.has("correspondences")) return run_register_correspondences(args, config);
  const auto chosen = pair_source_from_args(args);
  if (!chosen)
    throw UsageError(
        "choose one input: --source S --target T, --kitti-root DIR --pair S T, or --synthetic "
        "SEED");
  const PairSource& src = *chosen;
  std::printf("pair: %s\n", describe(src).c_str());
  const auto t0 = std::chrono::steady_clock::now();
  LoadedPair pair = load_pair(src, config.indoor);
  for (const auto& w : pair.source.warnings) warn(w);
  for (const auto& w : pair.target.warnings) warn(w);
  std::printf(
      "loaded %zu + %zu points in %.1f ms\n", pair.source.cloud.size(), pair.target.cloud.size(),
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());

  Pipeline pipeline(config, args.get_int("threads", 1));
  pipeline.set_input(std::move(pair.source.cloud), std::move(pair.target.cloud));
  pipeline.set_ground_truth(pair.T_target_source_gt);
  with_config_origin(args, [&] { pipeline.run(); });
  std::vector<std::string> warnings;
  for (std::string w : pipeline.warnings()) {  // name the file a cloud's warning is about
    for (const auto& [side, name] :
         {std::pair{"source: ", pair.source_name}, std::pair{"target: ", pair.target_name}})
      if (w.rfind(side, 0) == 0) w = name + ": " + w.substr(std::string(side).size());
    warnings.push_back(std::move(w));
  }
  warn_all(warnings, args.has("verbose"));
  RegistrationContext context;
  context.source_name = pair.source_name;
  context.target_name = pair.target_name;
  report_registration(args, pipeline, context);
  return 0;
}

}  // namespace pagor::cli
