// pagor register --correspondences FILE: the back end on any matcher's correspondences, through
// the Pipeline (set_matches). Graph -> clique -> pose per level; with clouds also verification,
// refinement and acceptance, and with --fuse the clouds' landmark correspondences beside the
// matcher's in one pyramid (correspondences.fuse_matches), counted per origin; with --ground-truth
// the errors per level and of the selection; with ground-truth inlier flags in the file each
// level's precision and recall. The JSON result is the main report (pagor.register/1) with the
// file's details under `correspondences`.

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>

#include "command.hpp"
#include "pagor/io/correspondence_file.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/report.hpp"
#include "pagor/verify/diagnosis.hpp"

namespace pagor::cli {
namespace {

using json = nlohmann::json;

// The file's inlier flags speak of the matcher's correspondences, which follow the landmark ones
// when fused: the positions in the file of the matcher's among `indices` (into the pipeline's).
std::vector<int> file_indices(const Pipeline& p, const std::vector<int>& indices) {
  const auto& items = p.correspondences().items;
  const int first = static_cast<int>(items.size() - p.correspondences().matches);
  std::vector<int> out;
  for (int i : indices)
    if (i >= first && i < static_cast<int>(items.size())) out.push_back(i - first);
  return out;
}

// Per origin: the correspondences, and of the selected level's clique how many (and, with a
// diagnosis, how many true ones) come from each.
void print_origins(const Pipeline& p, const std::optional<Diagnosis>& diagnosis) {
  const OriginCounts all = count_by_origin(p.correspondences().items);
  std::printf("\ncorrespondences by origin: landmark %zu, matcher %zu\n", all.landmark,
              all.matcher);
  const int sel = p.selected_level();
  if (sel < 0) return;
  const OriginCounts clique = count_by_origin(p.correspondences().items,
                                              p.cliques()[static_cast<std::size_t>(sel)].vertices);
  std::printf("selected clique by origin: landmark %zu, matcher %zu", clique.landmark,
              clique.matcher);
  if (diagnosis && sel < static_cast<int>(diagnosis->levels.size())) {
    const OriginCounts& t = diagnosis->levels[static_cast<std::size_t>(sel)].clique_true_origin;
    std::printf(" (true: landmark %zu, matcher %zu)", t.landmark, t.matcher);
  }
  std::printf("\n");
}

void print_levels(const Pipeline& p, const CorrespondenceFile& input) {
  const bool flags = !input.inlier.empty();
  const bool scored = p.has_clouds();
  const bool gt = p.ground_truth().has_value();
  std::printf("\n  %-5s %-8s %8s %9s %7s %8s", "level", "epsilon", "vertices", "edges", "clique",
              "inliers");
  if (flags) std::printf(" %9s %7s", "precision", "recall");
  if (scored)
    std::printf(" %13s", "score D [m]");
  else
    std::printf(" %8s %10s", "support", "S [m]");
  if (gt) std::printf(" %10s %11s %4s", "t err [m]", "r err [deg]", "ok");
  std::printf("\n");
  const PyramidGraph& g = p.graph();
  for (std::size_t l = 0; l < p.cliques().size(); ++l) {
    std::printf("%s %-5zu %-8.3f %8zu %9zu %7zu %8zu ",
                static_cast<int>(l) == p.selected_level() ? "*" : " ", l, g.thresholds[l],
                g.active_vertices(static_cast<int>(l)), g.edges_at_level[l],
                p.cliques()[l].vertices.size(), p.poses()[l].inliers.size());
    if (flags) {
      const InlierQuality q =
          inlier_quality(file_indices(p, p.cliques()[l].vertices), input.inlier);
      std::printf(" %9.3f %7.3f", q.precision, q.recall);
    }
    const VerificationResult& v = p.verification();
    const double D = scored ? v.scores[l] : v.support_scores[l];
    if (scored && std::isfinite(D))
      std::printf(" %13.1f", D);
    else if (scored)
      std::printf(" %13s", "invalid");
    else if (std::isfinite(D))
      std::printf(" %8d %10.1f", v.support[l], D);
    else
      std::printf(" %8s %10s", "-", "invalid");
    if (gt && l < p.level_errors().size() && p.level_errors()[l]) {
      const PoseError& e = *p.level_errors()[l];
      std::printf(" %10.2f %11.2f %4s", e.translation, e.rotation_deg, e.success ? "yes" : "no");
    }
    std::printf("\n");
  }
  print_clique_search(p);
  std::printf("  (* selected: %s)\n",
              scored ? "lowest D on the clouds"
                     : "lowest S = sum of min(residual, noise bound) over all correspondences; "
                       "support: those within the bound (no clouds to verify on)");
}

void print_outcome(const Pipeline& p) {
  if (const auto T = p.selected_transform())
    std::printf("\nselected level %d: t = (%.3f, %.3f, %.3f) m\n", p.selected_level(), (*T)(0, 3),
                (*T)(1, 3), (*T)(2, 3));
  else
    std::printf("\nno valid pose on any level\n");
  const Acceptance& a = p.acceptance();
  if (!a.verified)
    std::printf("verdict: not verified (%s)\n", a.reason.c_str());
  else if (p.selected_level() >= 0)
    std::printf("verdict: %s (aligned %.0f %% of points, %d inliers, D margin %.3f)%s%s\n",
                a.accepted ? "ACCEPTED" : "REJECTED", 100.0 * a.overlap, a.inliers, a.margin,
                a.accepted ? "" : ": ", a.reason.c_str());
  if (p.ground_truth()) {
    if (const auto e = p.selected_error())
      std::printf(
          "ground truth: translation error %.2f m, rotation error %.2f deg -> %s; upper bound: "
          "%s\n",
          e->translation, e->rotation_deg, e->success ? "SUCCESS" : "FAILURE",
          p.upper_bound_success() ? "yes" : "no");
    else
      std::printf("ground truth: FAILURE (no pose); upper bound: %s\n",
                  p.upper_bound_success() ? "yes" : "no");
  }
  std::printf("times [ms]: graph %.1f clique %.1f gnc %.1f verification %.1f\n",
              p.time_ms(Stage::graph), p.time_ms(Stage::clique), p.time_ms(Stage::gnc),
              p.time_ms(Stage::verification_prep) + p.time_ms(Stage::verification));
}

// The main report plus what only the file knows: its name, weights and inlier flags (each
// level's precision and recall against them).
json report_json(const Pipeline& p, const CorrespondenceFile& input, const std::string& file,
                 const std::string& source_name, const std::string& target_name,
                 const std::optional<Diagnosis>& diagnosis) {
  json report = json::parse(registration_report_json(p, source_name, target_name));
  std::size_t flagged = 0;
  for (char f : input.inlier) flagged += f != 0;
  json& c = report["correspondences"];
  c["file"] = file;
  c["weights"] = !input.weights.empty();
  c["inlier_flags"] = !input.inlier.empty();
  c["flagged_inliers"] = input.inlier.empty() ? json() : json(flagged);
  if (!input.inlier.empty())
    for (std::size_t l = 0; l < p.cliques().size(); ++l) {
      const InlierQuality q =
          inlier_quality(file_indices(p, p.cliques()[l].vertices), input.inlier);
      json& level = report["levels"][l];
      level["precision"] = q.precision;
      level["recall"] = q.recall;
      level["true_inliers"] = q.true_inliers;
    }
  report["diagnosis"] = diagnosis ? json::parse(diagnosis_json(*diagnosis)) : json();
  return report;
}

}  // namespace

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
  for (const std::string& w : pipeline.warnings()) warn(w);
  print_levels(pipeline, input);
  print_outcome(pipeline);
  const std::optional<Diagnosis> diagnosis = diagnose(pipeline);
  print_origins(pipeline, diagnosis);
  if (diagnosis)
    std::printf("diagnosis: %s: %s\n", verdict_sentence(diagnosis->verdict),
                diagnosis->explanation.c_str());
  if (args.has("json")) {
    const json report = report_json(pipeline, input, file, source_name, target_name, diagnosis);
    write_text_file(args.get("json"),
                    report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    std::printf("wrote %s\n", args.get("json").c_str());
  }
  return 0;
}

}  // namespace pagor::cli
