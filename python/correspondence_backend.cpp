#include "correspondence_backend.hpp"

#include <chrono>

#include "pagor/errors.hpp"
#include "pagor/graph/densest_clique.hpp"
#include "pagor/graph/pyramid_graph.hpp"
#include "pagor/pose/gnc.hpp"
#include "pagor/util/work_budget.hpp"

namespace pagor::python {
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

// Without clouds there is no D: the level whose pose keeps the most inliers is selected.
int select_by_inliers(const std::vector<PoseEstimate>& poses) {
  int best = -1;
  for (std::size_t l = 0; l < poses.size(); ++l)
    if (poses[l].valid && (best < 0 || poses[l].inliers.size() >
                                           poses[static_cast<std::size_t>(best)].inliers.size()))
      best = static_cast<int>(l);
  return best;
}

}  // namespace

json solve_correspondences(const std::vector<Correspondence>& items,
                           const std::vector<double>& weights, const Config& config, int threads) {
  if (items.size() > kMaxGraphCorrespondences)
    throw InputError("correspondences: " + std::to_string(items.size()) +
                     " correspondences are more than the consistency graph takes (" +
                     std::to_string(kMaxGraphCorrespondences) + ")");
  auto t0 = Clock::now();
  const PyramidGraph graph = build_pyramid_graph(items, config.graph, threads);
  const double graph_ms = ms_since(t0);
  t0 = Clock::now();
  const std::vector<CliqueResult> cliques = solve_pyramid(graph, config.clique);
  const double clique_ms = ms_since(t0);
  t0 = Clock::now();
  std::vector<PoseEstimate> poses;
  for (const CliqueResult& c : cliques) {
    std::vector<Eigen::Vector3d> p, q;
    for (int v : c.vertices) {
      p.push_back(items[static_cast<std::size_t>(v)].p);
      q.push_back(items[static_cast<std::size_t>(v)].q);
    }
    PoseEstimate e = estimate_pose_gnc(p, q, config.gnc);
    for (int& i : e.inliers) i = c.vertices[static_cast<std::size_t>(i)];
    poses.push_back(std::move(e));
  }
  const double gnc_ms = ms_since(t0);
  const int selected = select_by_inliers(poses);

  json levels = json::array();
  for (std::size_t l = 0; l < cliques.size(); ++l) {
    const PoseEstimate& pose = poses[l];
    levels.push_back(
        {{"level", l},
         {"epsilon", graph.thresholds[l]},
         {"vertices", graph.active_vertices(static_cast<int>(l))},
         {"edges", graph.edges_at_level[l]},
         {"clique_size", cliques[l].vertices.size()},
         {"clique", cliques[l].vertices},
         {"clique_time_ms", cliques[l].time_ms},
         {"pose_valid", pose.valid},
         {"inliers", pose.inliers.size()},
         {"T_target_source", pose.valid ? matrix_json(pose.T_target_source) : json()}});
  }
  return {{"schema", "pagor.register-correspondences/1"},
          {"correspondences",
           {{"file", nullptr},
            {"count", items.size()},
            {"weights", !weights.empty()},
            {"inlier_flags", false},
            {"flagged_inliers", nullptr}}},
          {"T_target_source",
           selected >= 0 ? matrix_json(poses[static_cast<std::size_t>(selected)].T_target_source)
                         : json()},
          {"selected_level", selected >= 0 ? json(selected) : json()},
          {"selected_by", "inliers"},
          {"levels", levels},
          {"ground_truth", nullptr},
          {"timings_ms",
           {{"graph", graph_ms}, {"clique", clique_ms}, {"gnc", gnc_ms}, {"verification", 0.0}}},
          {"config", json::parse(config_to_json(config))}};
}

}  // namespace pagor::python
