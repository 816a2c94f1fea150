// pagor register --correspondences FILE: the back end on any matcher's correspondences.
// Graph -> clique -> pose per level, verification when clouds are given too, and precision/recall
// of each level's clique when the file carries ground-truth inlier flags.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>

#include "command.hpp"
#include "pagor/io/correspondence_file.hpp"
#include "pagor/graph/densest_clique.hpp"
#include "pagor/verify/evaluation.hpp"
#include "pagor/pose/gnc.hpp"
#include "pagor/graph/pyramid_graph.hpp"
#include "pagor/verify/verification.hpp"

namespace pagor::cli {
namespace {

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

json matrix_json(const Transform& T) {
  json rows = json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({T(r, 0), T(r, 1), T(r, 2), T(r, 3)});
  return rows;
}

// Everything one run produces, in level order.
struct Run {
  CorrespondenceFile input;
  PyramidGraph graph;
  std::vector<CliqueResult> cliques;
  std::vector<PoseEstimate> poses;
  std::optional<VerificationResult> verification;
  std::optional<Transform> ground_truth;
  int selected = -1;
  double graph_ms = 0, clique_ms = 0, gnc_ms = 0, verification_ms = 0;
};

// Without clouds there is no D: the level whose pose keeps the most inliers is selected.
int select_by_inliers(const std::vector<PoseEstimate>& poses) {
  int best = -1;
  for (std::size_t l = 0; l < poses.size(); ++l)
    if (poses[l].valid && (best < 0 || poses[l].inliers.size() >
                                           poses[static_cast<std::size_t>(best)].inliers.size()))
      best = static_cast<int>(l);
  return best;
}

void print_run(const Run& r, const Config& config) {
  const bool flags = !r.input.inlier.empty();
  std::printf("\n  %-5s %-8s %8s %9s %7s %8s", "level", "epsilon", "vertices", "edges", "clique",
              "inliers");
  if (flags) std::printf(" %9s %7s", "precision", "recall");
  if (r.verification) std::printf(" %13s", "score D [m]");
  if (r.ground_truth) std::printf(" %10s %11s %4s", "t err [m]", "r err [deg]", "ok");
  std::printf("\n");
  for (std::size_t l = 0; l < r.cliques.size(); ++l) {
    std::printf("%s %-5zu %-8.3f %8zu %9zu %7zu %8zu ",
                static_cast<int>(l) == r.selected ? "*" : " ", l, r.graph.thresholds[l],
                r.graph.active_vertices(static_cast<int>(l)), r.graph.edges_at_level[l],
                r.cliques[l].vertices.size(), r.poses[l].inliers.size());
    if (flags) {
      const InlierQuality q = inlier_quality(r.cliques[l].vertices, r.input.inlier);
      std::printf(" %9.3f %7.3f", q.precision, q.recall);
    }
    if (r.verification) {
      const double D = r.verification->scores[l];
      if (std::isfinite(D))
        std::printf(" %13.1f", D);
      else
        std::printf(" %13s", "invalid");
    }
    if (r.ground_truth && r.poses[l].valid) {
      const PoseError e =
          pose_error(r.poses[l].T_target_source, *r.ground_truth, config.evaluation);
      std::printf(" %10.2f %11.2f %4s", e.translation, e.rotation_deg, e.success ? "yes" : "no");
    }
    std::printf("\n");
  }
  std::printf("  (* selected: %s)\n", r.verification ? "lowest D on the clouds"
                                                     : "most GNC inliers; no clouds to verify on");
  std::printf("times [ms]: graph %.1f clique %.1f gnc %.1f verification %.1f\n", r.graph_ms,
              r.clique_ms, r.gnc_ms, r.verification_ms);
}

json run_json(const Run& r, const std::string& file, const Config& config) {
  json levels = json::array();
  for (std::size_t l = 0; l < r.cliques.size(); ++l) {
    const auto& pose = r.poses[l];
    json level = {{"level", l},
                  {"epsilon", r.graph.thresholds[l]},
                  {"vertices", r.graph.active_vertices(static_cast<int>(l))},
                  {"edges", r.graph.edges_at_level[l]},
                  {"clique_size", r.cliques[l].vertices.size()},
                  {"clique", r.cliques[l].vertices},
                  {"clique_time_ms", r.cliques[l].time_ms},
                  {"pose_valid", pose.valid},
                  {"inliers", pose.inliers.size()},
                  {"T_target_source", pose.valid ? matrix_json(pose.T_target_source) : json()}};
    if (!r.input.inlier.empty()) {
      const InlierQuality q = inlier_quality(r.cliques[l].vertices, r.input.inlier);
      level["precision"] = q.precision;
      level["recall"] = q.recall;
      level["true_inliers"] = q.true_inliers;
    }
    if (r.verification) {
      const double D = r.verification->scores[l];
      level["score_D"] = std::isfinite(D) ? json(D) : json();
    }
    if (r.ground_truth && pose.valid) {
      const PoseError e = pose_error(pose.T_target_source, *r.ground_truth, config.evaluation);
      level["translation_error_m"] = e.translation;
      level["rotation_error_deg"] = e.rotation_deg;
      level["success"] = e.success;
    }
    levels.push_back(level);
  }
  std::size_t flagged = 0;
  for (char f : r.input.inlier) flagged += f != 0;
  const json selected =
      r.selected >= 0 ? matrix_json(r.poses[static_cast<std::size_t>(r.selected)].T_target_source)
                      : json();
  return {{"schema", "pagor.register-correspondences/1"},
          {"correspondences",
           {{"file", file},
            {"count", r.input.items.size()},
            {"weights", !r.input.weights.empty()},
            {"inlier_flags", !r.input.inlier.empty()},
            {"flagged_inliers", r.input.inlier.empty() ? json() : json(flagged)}}},
          {"T_target_source", selected},
          {"selected_level", r.selected >= 0 ? json(r.selected) : json()},
          {"selected_by", r.verification ? "score_D" : "inliers"},
          {"levels", levels},
          {"ground_truth", r.ground_truth ? matrix_json(*r.ground_truth) : json()},
          {"timings_ms",
           {{"graph", r.graph_ms},
            {"clique", r.clique_ms},
            {"gnc", r.gnc_ms},
            {"verification", r.verification_ms}}},
          {"config", json::parse(config_to_json(config))}};
}

}  // namespace

int run_register_correspondences(const Args& args, const Config& config) {
  Run r;
  const std::string file = args.get("correspondences");
  r.input = read_correspondence_file(file);
  std::printf("correspondences: %zu from %s%s%s\n", r.input.items.size(), file.c_str(),
              r.input.weights.empty() ? "" : " (weighted)",
              r.input.inlier.empty() ? "" : " (with inlier flags)");
  std::optional<LoadedPair> pair;
  if (const auto src = pair_source_from_args(args)) {
    pair = load_pair(*src, config.indoor);
    for (const auto& w : pair->source.warnings) warn(w);
    for (const auto& w : pair->target.warnings) warn(w);
    r.ground_truth = pair->T_target_source_gt;
    std::printf("clouds for verification: %s\n", describe(*src).c_str());
  }
  auto t0 = Clock::now();
  r.graph = build_pyramid_graph(r.input.items, config.graph, args.get_int("threads", 1));
  r.graph_ms = ms_since(t0);
  t0 = Clock::now();
  r.cliques = solve_pyramid(r.graph, config.clique);
  r.clique_ms = ms_since(t0);
  t0 = Clock::now();
  for (const CliqueResult& c : r.cliques) {
    std::vector<Eigen::Vector3d> p, q;
    for (int v : c.vertices) {
      p.push_back(r.input.items[static_cast<std::size_t>(v)].p);
      q.push_back(r.input.items[static_cast<std::size_t>(v)].q);
    }
    PoseEstimate e = estimate_pose_gnc(p, q, config.gnc);
    for (int& i : e.inliers) i = c.vertices[static_cast<std::size_t>(i)];
    r.poses.push_back(std::move(e));
  }
  r.gnc_ms = ms_since(t0);
  if (pair) {
    t0 = Clock::now();
    const Verifier verifier(pair->source.cloud, pair->target.cloud, config.verification.voxel_size);
    r.verification =
        verify_candidates(verifier, r.poses, config.verification, args.get_int("threads", 1));
    r.verification_ms = ms_since(t0);
    r.selected = r.verification->selected;
  } else {
    r.selected = select_by_inliers(r.poses);
  }
  print_run(r, config);
  if (r.selected >= 0) {
    const Transform& T = r.poses[static_cast<std::size_t>(r.selected)].T_target_source;
    std::printf("\nselected level %d: t = (%.3f, %.3f, %.3f) m\n", r.selected, T(0, 3), T(1, 3),
                T(2, 3));
  } else {
    std::printf("\nno valid pose on any level\n");
  }
  if (args.has("json")) {
    write_text_file(
        args.get("json"),
        run_json(r, file, config).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) +
            "\n");
    std::printf("wrote %s\n", args.get("json").c_str());
  }
  return 0;
}

}  // namespace pagor::cli
