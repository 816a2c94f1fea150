// pagor register: one registration, with a per-level summary and a JSON result.

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "command.hpp"
#include "common/outputs.hpp"
#include "pagor/errors.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/report.hpp"
#include "pagor/verify/diagnosis.hpp"
#include "pagor/verify/evaluation.hpp"

namespace pagor::cli {
namespace {

std::string pose_text(const Transform& T) {
  const Eigen::Vector3d a = yaw_pitch_roll_deg(T.block<3, 3>(0, 0));
  char buf[160];
  std::snprintf(buf, sizeof(buf), "t = (%.2f, %.2f, %.2f) m, yaw %.2f, pitch %.2f, roll %.2f deg",
                T(0, 3), T(1, 3), T(2, 3), a[0], a[1], a[2]);
  return buf;
}

}  // namespace

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

void print_registration(const Pipeline& p) {
  const auto& sl = p.source_landmarks();
  const auto& tl = p.target_landmarks();
  std::printf("labels: source %s, target %s\n", labels_text(sl.labels).c_str(),
              labels_text(tl.labels).c_str());
  std::printf("landmarks:");
  for (std::size_t c = 0; c < sl.classes.size(); ++c)
    std::printf(" %s %zu/%zu", sl.classes[c].name.c_str(), sl.classes[c].landmarks,
                tl.classes[c].landmarks);
  std::printf("  (source/target)\n");
  const auto& corr = p.correspondences();
  std::printf(
      "correspondences: %zu%s\n", corr.items.size(),
      corr.capped ? (" (capped from " + std::to_string(corr.candidates) + ")").c_str() : "");

  const bool gt = p.ground_truth().has_value();
  std::printf("\n  %-5s %-8s %8s %9s %7s %8s %13s", "level", "epsilon", "vertices", "edges",
              "clique", "inliers", "score D [m]");
  if (gt) std::printf(" %10s %11s %4s", "t err [m]", "r err [deg]", "ok");
  std::printf("\n");
  const auto& g = p.graph();
  for (std::size_t l = 0; l < p.cliques().size(); ++l) {
    const bool sel = static_cast<int>(l) == p.selected_level();
    const double D = p.verification().scores[l];
    std::printf("%s %-5zu %-8.3f %8zu %9zu %7zu %8zu ", sel ? "*" : " ", l, g.thresholds[l],
                g.active_vertices(static_cast<int>(l)), g.edges_at_level[l],
                p.cliques()[l].vertices.size(), p.poses()[l].inliers.size());
    if (std::isfinite(D))
      std::printf("%13.1f", D);
    else
      std::printf("%13s", "invalid");
    if (gt && l < p.level_errors().size() && p.level_errors()[l]) {
      const auto& e = *p.level_errors()[l];
      std::printf(" %10.2f %11.2f %4s", e.translation, e.rotation_deg, e.success ? "yes" : "no");
    }
    std::printf("\n");
  }
  print_clique_search(p);
  std::printf("  (* selected: lowest D; D = sum of min(distance, %.2f m) over %zu source points)\n",
              p.config().verification.mu, p.verifier() ? p.verifier()->source_points().size() : 0u);

  if (const auto T = p.selected_transform()) {  // as the files have it, like the JSON
    std::printf("\nselected level %d: %s\n", p.selected_level(),
                pose_text(to_file_frames(*T, p.source().origin, p.target().origin)).c_str());
  } else {
    std::printf("\nno valid candidate on any level\n");
  }
  const RefinementResult& r = p.refinement();
  if (r.ran && r.applied)
    std::printf("refinement: applied, D %.1f -> %.1f m, moved %.2f m / %.2f deg in %d iterations\n",
                r.score_before, r.score_after, r.correction_translation, r.correction_rotation,
                r.iterations);
  else if (r.ran)
    std::printf("refinement: not applied (%s)\n", r.reason.c_str());
  const Acceptance& a = p.acceptance();
  if (p.selected_level() >= 0)
    std::printf(
        "verdict: %s (aligned %.0f %% of points within %.2f m, %d inliers, D margin %.3f, "
        "sharpness %.2f)%s%s\n",
        a.accepted ? "ACCEPTED" : "REJECTED", 100.0 * a.overlap,
        p.config().acceptance.inlier_distance, a.inliers, a.margin, a.sharpness,
        a.accepted ? "" : ": ", a.reason.c_str());
  if (gt) {
    if (const auto before = p.unrefined_error(); before && r.applied)
      std::printf(
          "ground truth before refinement: translation error %.2f m, rotation error %.2f deg\n",
          before->translation, before->rotation_deg);
    if (const auto e = p.selected_error())
      std::printf(
          "ground truth: translation error %.2f m, rotation error %.2f deg -> %s "
          "(criterion %g m / %g deg); upper bound: %s\n",
          e->translation, e->rotation_deg, e->success ? "SUCCESS" : "FAILURE",
          p.config().evaluation.max_translation_error, p.config().evaluation.max_rotation_error,
          p.upper_bound_success() ? "yes" : "no");
    else
      std::printf("ground truth: FAILURE (no pose); upper bound: %s\n",
                  p.upper_bound_success() ? "yes" : "no");
  }
  double total = 0;
  std::printf("times [ms]:");
  const Stage shown[] = {
      Stage::landmarks, Stage::correspondences,   Stage::graph,        Stage::clique,
      Stage::gnc,       Stage::verification_prep, Stage::verification, Stage::refinement};
  for (Stage s : shown) {
    std::printf(" %s %.1f", stage_name(s), p.time_ms(s));
    total += p.time_ms(s);
  }
  std::printf(" | total %.1f\n", total);
}

std::vector<Option> register_options() {
  std::vector<Option> o = pair_options();
  o.push_back({"config", 1, "FILE", "configuration JSON (absent keys: the preset's values)"});
  o.push_back(
      {"preset", 1, "NAME", "base configuration: default, paper (the published one) or indoor"});
  o.push_back({"json", 1, "OUT", "write the result as JSON (schema pagor.register/1)"});
  o.push_back({"threads", 1, "N", "threads for graph construction and verification (default 1)"});
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
  const Config config = config_from_args(args);
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
  for (std::string w : pipeline.warnings()) {  // name the file a cloud's warning is about
    for (const auto& [side, name] :
         {std::pair{"source: ", pair.source_name}, std::pair{"target: ", pair.target_name}})
      if (w.rfind(side, 0) == 0) w = name + ": " + w.substr(std::string(side).size());
    warn(w);
  }
  print_registration(pipeline);
  const std::optional<Diagnosis> diagnosis = diagnose(pipeline);
  if (diagnosis)
    std::printf("diagnosis: %s: %s\n", verdict_sentence(diagnosis->verdict),
                diagnosis->explanation.c_str());
  if (args.has("json")) {
    write_text_file(
        args.get("json"),
        registration_report_json(pipeline, pair.source_name, pair.target_name, diagnosis) + "\n");
    std::printf("wrote %s\n", args.get("json").c_str());
  }
  return 0;
}

}  // namespace pagor::cli
