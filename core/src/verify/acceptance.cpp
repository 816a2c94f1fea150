#include "pagor/verify/acceptance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pagor/front/ground.hpp"
#include "pagor/verify/evaluation.hpp"
#include "util/parallel.hpp"
#include "verify/ambiguity.hpp"

namespace pagor {
namespace {

// max_ambiguity at or above this turns the test off (AcceptanceParams::max_ambiguity).
constexpr double kAmbiguityOff = 10.0;

std::string below(const char* what, double value, double threshold) {
  char buf[96];
  std::snprintf(buf, sizeof(buf), "%s %.3g < %.3g", what, value, threshold);
  return buf;
}

// The points the overlap counts, per point: those above the ground. A flat cloud (a floor
// projection: everything within the ground layer) is judged on all its points. A scan with little
// structure is still judged on it: judged on all its points, a street that is mostly road was
// "aligned" by any pose that lays road on road.
std::vector<char> structure_points(const std::vector<Eigen::Vector3f>& points,
                                   const AcceptanceParams& params) {
  // The ground follows the terrain (ground.hpp): on a sloped street a height layer would leave the
  // uphill road as structure, which a pose sliding along the street aligns.
  GroundParams ground_params;
  ground_params.thickness = params.ground_thickness;
  const std::vector<char> ground = ground_points(points, ground_params);
  std::size_t structure = 0;
  for (char g : ground) structure += !g;
  std::vector<char> counts(ground.size(), 1);
  if (structure >= std::max<std::size_t>(10, points.size() / 100))
    for (std::size_t i = 0; i < ground.size(); ++i) counts[i] = !ground[i];
  return counts;
}

double overlap_of(const std::vector<float>& dist, const std::vector<char>& counts, double within) {
  std::size_t close = 0, counted = 0;
  for (std::size_t i = 0; i < dist.size(); ++i) {
    if (!counts[i]) continue;
    ++counted;
    close += dist[i] <= within;
  }
  return counted ? static_cast<double>(close) / static_cast<double>(counted) : 0.0;
}

// The same pose moved by distinct_translation along each horizontal axis: a true
// alignment loses most of its overlap, one that aligns only what slides along itself (a facade, a
// hedge, the road) or what matches anything (vegetation) keeps it.
double sharpness_of(const Verifier& verifier, const Transform& T, const std::vector<char>& counts,
                    double overlap, double step, const AcceptanceParams& params, int threads) {
  std::size_t counted = 0;
  for (char c : counts) counted += c != 0;
  if (counted == 0) return 0.0;
  const Eigen::Vector2d dirs[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  std::size_t kept[4] = {0, 0, 0, 0};
  // Only the points overlap_of counts are searched (on KITTI, skipping the ground halved this).
  parallel_ranges(threads, 4, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      Transform moved = T;
      moved.block<2, 1>(0, 3) += step * dirs[k];
      kept[k] = verifier.count_within(moved, static_cast<float>(params.inlier_distance), counts);
    }
  });
  const double shifted =
      static_cast<double>(*std::max_element(kept, kept + 4)) / static_cast<double>(counted);
  return overlap > 0 ? 1.0 - shifted / overlap : 0.0;
}

// Margin to the best candidate that is a different answer, not the same pose found twice.
double margin_of(const std::vector<PoseEstimate>& candidates, const VerificationResult& v,
                 std::size_t sel, double full, const EvaluationParams& distinct) {
  double best_other = HUGE_VAL;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (i == sel || !candidates[i].valid) continue;
    if (pose_error(candidates[i].T_target_source, candidates[sel].T_target_source, distinct)
            .success)
      continue;
    best_other = std::min(best_other, v.scores[i]);
  }
  return std::isfinite(best_other) && full > 0 ? (best_other - v.scores[sel]) / full : 1.0;
}

AcceptanceTest make_test(const char* name, double value, double threshold, bool at_most,
                         const char* description) {
  AcceptanceTest t;
  t.name = name;
  t.value = value;
  t.threshold = threshold;
  t.at_most = at_most;
  t.passed = at_most ? value <= threshold : value >= threshold;
  t.description = description;
  return t;
}

// The tests but the ambiguity, in the order the reason is chosen; the reason names the first that
// failed.
void add_tests(Acceptance& a, const AcceptanceParams& params, PoseModel model, bool adopting) {
  a.tests.push_back(make_test("overlap", a.overlap, params.min_overlap, false,
                              "fraction of structure points aligned under the pose"));
  a.tests.push_back(make_test("inliers", a.inliers, params.min_inliers, false,
                              "GNC inliers of the selected candidate"));
  a.tests.push_back(make_test("sharpness", a.sharpness, params.min_sharpness, false,
                              "share of the overlap lost when the pose moves by the success "
                              "criterion's translation"));
  a.tests.push_back(make_test("margin", a.margin, params.min_margin, false,
                              "D margin to the best distinct candidate, fraction of mu * points"));
  if (adopting) {  // D preferred the pose it out-fitted; the ambiguity test judges them instead
    a.tests.back().applies = false;
    a.tests.back().passed = true;
    a.tests.back().description +=
        " (not taken for an adopted alternative: the ambiguity test compares it with every "
        "candidate on the points both poses put where the target looked)";
  }
  AcceptanceTest minimal = make_test("minimal support", a.overlap, params.minimal_support_overlap,
                                     false, "overlap asked of a pose on the minimal inliers");
  minimal.applies = a.inliers <= minimal_sample_size(model);
  minimal.passed = minimal.passed || !minimal.applies;
  a.tests.push_back(minimal);
  const char* reasons[] = {"overlap", "inliers", "sharpness", "D margin",
                           "overlap with minimal support"};
  for (std::size_t i = 0; i < a.tests.size() && a.reason.empty(); ++i)
    if (!a.tests[i].passed) a.reason = below(reasons[i], a.tests[i].value, a.tests[i].threshold);
  AcceptanceTest ambiguity =
      make_test("ambiguity", 0.0, params.max_ambiguity, true,
                "points only the best distinct alternative aligns / points only the selected "
                "pose aligns (10 added to each)");
  ambiguity.applies = false;  // until judge_ambiguity takes it
  a.tests.push_back(ambiguity);
}

std::string candidate_name(std::size_t level, const Transform& T, const Transform& selected,
                           const EvaluationParams& criterion) {
  const PoseError e = pose_error(T, selected, criterion);
  char buf[96];
  std::snprintf(buf, sizeof(buf), "level %zu's candidate (%.1f m, %.0f deg away)", level,
                e.translation, e.rotation_deg);
  return buf;
}

// Searches the distinct alternatives (ambiguity.hpp), fills the ambiguity test and rejects when
// one explains more than max_ambiguity of what the selected pose explains.
void judge_ambiguity(Acceptance& a, const Verifier& verifier,
                     const std::vector<PoseEstimate>& candidates, const VerificationResult& v,
                     const std::vector<char>& counts, const std::vector<char>* furniture, double mu,
                     const EvaluationParams& distinct, const AcceptanceParams& params, int threads,
                     const std::function<std::vector<NamedPose>()>& more) {
  const auto sel = static_cast<std::size_t>(v.selected);
  AmbiguityInput in;
  in.verifier = &verifier;
  in.counts = &counts;
  const std::vector<char> target_counts = structure_points(verifier.target_points(), params);
  in.target_counts = &target_counts;
  // A flat target (every point counted: a floor plan, a floor projection) shows all there is.
  in.target_complete =
      !target_counts.empty() &&
      std::all_of(target_counts.begin(), target_counts.end(), [](char c) { return c != 0; });
  // Against a floor plan, furniture (what stands lower than the walls: a parked car) is in no
  // plan: a pose that puts a car's side on a wall explains nothing by it, and a car park's cars
  // beside a long wall made right poses look rivalled by a shift of a column spacing. Such a
  // point on a wall or column contradicts the pose that puts it there.
  std::vector<char> structure, on_furniture;
  if (in.target_complete && furniture && furniture->size() == counts.size()) {
    structure = counts;
    on_furniture.assign(counts.size(), 0);
    for (std::size_t i = 0; i < structure.size(); ++i)
      if ((*furniture)[i]) on_furniture[i] = counts[i], structure[i] = 0;
    in.counts = &structure;
    in.furniture = &on_furniture;
  }
  in.T_selected = candidates[sel].T_target_source;
  in.mu = mu;
  in.inlier_distance = params.inlier_distance;
  in.distinct = distinct;
  in.search_range = params.ambiguity_range;
  in.threads = threads;
  const bool reuse = v.selected_distances.size() == counts.size() &&
                     v.distance_bound >= 2 * params.inlier_distance;
  if (reuse) in.selected_distances = &v.selected_distances;
  std::vector<Transform> others;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (i != sel && candidates[i].valid) {
      others.push_back(candidates[i].T_target_source);
      names.push_back(candidate_name(i, others.back(), in.T_selected, distinct));
    }
  if (more)
    for (const NamedPose& m : more()) {
      others.push_back(m.T_target_source);
      const PoseError e = pose_error(m.T_target_source, in.T_selected, distinct);
      char buf[64];
      std::snprintf(buf, sizeof(buf), "%.1f m, %.0f deg away)", e.translation, e.rotation_deg);
      names.push_back(m.name + " (" + (m.detail.empty() ? "" : m.detail + "; ") + buf);
    }
  a.alternative = find_best_alternative(in, others, names);
  a.ambiguity = a.alternative.ratio;
  AcceptanceTest& t = a.tests.back();
  t.value = a.ambiguity;
  t.applies = true;
  t.passed = a.ambiguity <= params.max_ambiguity;
  if (!t.passed && a.reason.empty()) {  // an earlier test's reason stands
    char buf[192];
    std::snprintf(buf, sizeof(buf),
                  " fits %s: it alone aligns %.2f times the points the selected pose alone "
                  "aligns (%zu points against %zu)",
                  // better: selected instead, this pose would not be rivalled by the selection
                  a.ambiguity > std::max(1.0, 1.0 / params.max_ambiguity) ? "better" : "as well",
                  a.ambiguity, a.alternative.only_alternative, a.alternative.only_selected);
    a.reason = "ambiguous: " + a.alternative.description + buf;
  }
}

}  // namespace

Acceptance judge_selection(const Verifier& verifier, const std::vector<PoseEstimate>& candidates,
                           const VerificationResult& verification,
                           const VerificationParams& verification_params,
                           const AcceptanceParams& params, PoseModel model, int threads,
                           const std::vector<char>* furniture, bool adopting,
                           const std::function<std::vector<NamedPose>()>& more_alternatives) {
  const EvaluationParams distinct = params.distinct();  // what counts as another answer
  Acceptance a;
  if (verification.selected < 0) {
    a.reason = "no valid candidate";
    return a;
  }
  const std::size_t sel = static_cast<std::size_t>(verification.selected);
  const Transform& T = candidates[sel].T_target_source;
  const std::vector<Eigen::Vector3f>& points = verifier.source_points();
  // The distances the selection's D summed serve when their bound reaches the inlier distance
  // (points beyond it are not aligned either way).
  const bool reuse = verification.selected_distances.size() == points.size() &&
                     verification.distance_bound >= params.inlier_distance;
  std::vector<float> searched;
  if (!reuse) searched = verifier.distances(T, static_cast<float>(params.inlier_distance));
  const std::vector<float>& d = reuse ? verification.selected_distances : searched;
  const std::vector<char> counts = structure_points(points, params);
  a.overlap = overlap_of(d, counts, params.inlier_distance);
  a.sharpness =
      sharpness_of(verifier, T, counts, a.overlap, distinct.max_translation_error, params, threads);
  a.inliers = static_cast<int>(candidates[sel].inliers.size());
  const double full = verification_params.mu * static_cast<double>(d.size());
  a.margin = margin_of(candidates, verification, sel, full, distinct);
  add_tests(a, params, model, adopting);
  // The ambiguity is searched for a pose every other test trusts (it costs a few dozen searches
  // of the points), and, for the alternative an adoption would take, for one that failed only
  // the D margin or the sharpness: a pose that slides a corridor's whole view onto the target's
  // has the lower D and often no margin, and the true pose, a period on, is its rival.
  bool seek = a.reason.empty();
  if (params.adopt_alternative && !adopting && !seek) {
    seek = true;
    for (const AcceptanceTest& t : a.tests)
      if (t.applies && !t.passed && t.name != "margin" && t.name != "sharpness") seek = false;
  }
  if (seek && params.max_ambiguity < kAmbiguityOff)
    judge_ambiguity(a, verifier, candidates, verification, counts, furniture,
                    verification_params.mu, distinct, params, threads, more_alternatives);
  a.accepted = a.reason.empty();
  return a;
}

}  // namespace pagor
