#include "pagor/registration.hpp"

#include <cmath>
#include <cstdio>

#include "pagor/errors.hpp"
#include "pagor/io/clouds.hpp"

namespace pagor {
namespace {

// The file's inlier flags speak of the matcher's correspondences, which follow the landmark ones
// when fused: the positions in the file of the matcher's among `indices` (into the pipeline's).
std::vector<int> file_indices(const CorrespondenceSet& set, const std::vector<int>& indices) {
  const int count = static_cast<int>(set.items.size());
  const int first = count - static_cast<int>(set.matches);
  std::vector<int> out;
  for (int i : indices)
    if (i >= first && i < count) out.push_back(i - first);
  return out;
}

LevelSummary level_summary(const Pipeline& p, std::size_t l) {
  const PyramidGraph& g = p.graph();
  const CliqueResult& c = p.cliques()[l];
  LevelSummary s;
  s.epsilon = g.thresholds[l];
  s.vertices = g.active_vertices(static_cast<int>(l));
  s.edges = g.edges_at_level[l];
  s.clique = c.vertices;
  s.clique_proven = c.proven;
  s.clique_number_bound = c.clique_number_bound;
  s.clique_budget = c.budget;
  s.clique_start = c.start;
  s.clique_time_ms = c.time_ms;
  s.clique_gradient_steps = c.gradient_steps;
  s.clique_penalty_updates = c.penalty_updates;
  s.pose = p.poses()[l];
  if (s.pose.valid)
    s.pose.T_target_source =
        to_file_frames(s.pose.T_target_source, p.source().origin, p.target().origin);
  const VerificationResult& v = p.verification();
  s.score_D = l < v.scores.size() ? v.scores[l] : HUGE_VAL;
  if (l < v.support.size()) {  // selected without clouds
    s.support = v.support[l];
    s.support_score = v.support_scores[l];
  }
  if (l < p.level_errors().size()) s.error = p.level_errors()[l];
  return s;
}

void add_front_end(const Pipeline& p, Registration& r) {
  const LandmarkSet& sl = p.source_landmarks();
  const LandmarkSet& tl = p.target_landmarks();
  const CorrespondenceSet& corr = p.correspondences();
  for (std::size_t c = 0; c < sl.classes.size(); ++c) {
    ClassCount count{sl.classes[c].name, sl.classes[c].landmarks, 0, 0};
    if (c < tl.classes.size()) count.target = tl.classes[c].landmarks;
    if (c < corr.per_class.size()) count.correspondences = corr.per_class[c];
    r.classes.push_back(count);
  }
  r.source_labels = sl.labels;
  r.target_labels = tl.labels;
  r.correspondences = corr.items.size();
  r.correspondence_candidates = corr.candidates;
  r.correspondences_capped = corr.capped;
  r.origin_all = count_by_origin(corr.items);
  if (r.selected_level >= 0) {
    const auto sel = static_cast<std::size_t>(r.selected_level);
    r.origin_clique = count_by_origin(corr.items, p.cliques()[sel].vertices);
    r.origin_inliers = count_by_origin(corr.items, p.poses()[sel].inliers);
  }
}

void add_matches_file(const Pipeline& p, const MatchesFileInfo& file, Registration& r) {
  r.matches_file = file;
  if (file.inliers.empty()) return;
  for (std::size_t l = 0; l < r.levels.size(); ++l)
    r.levels[l].file_inliers =
        inlier_quality(file_indices(p.correspondences(), p.cliques()[l].vertices), file.inliers);
}

}  // namespace

std::string test_text(const AcceptanceTest& t) {
  if (!t.applies) return t.name + ": not taken";
  const bool count = t.name == "inliers";
  char buf[160];
  std::snprintf(buf, sizeof(buf), count ? "%s %.0f (at %s %.0f%s%s)" : "%s %.3g (at %s %.3g%s%s)",
                t.name.c_str(), t.value, t.at_most ? "most" : "least", t.threshold,
                t.unit.empty() ? "" : " ", t.unit.c_str());
  return std::string(buf) + (t.passed ? "" : ": FAILED");
}

const char* to_string(SelectedBy by) {
  return by == SelectedBy::score_D ? "score_D" : "without_clouds";
}

Registration make_registration(const Pipeline& p, const RegistrationContext& context) {
  Registration r;
  r.source_name = context.source_name;
  r.target_name = context.target_name;
  const auto in_files = [&](const Transform& T) {
    return to_file_frames(T, p.source().origin, p.target().origin);
  };
  r.selected_level = p.selected_level();
  if (const auto T = p.selected_transform()) r.T_target_source = in_files(*T);
  r.selected_by = p.has_clouds() ? SelectedBy::score_D : SelectedBy::without_clouds;
  for (std::size_t l = 0; l < p.cliques().size(); ++l) r.levels.push_back(level_summary(p, l));
  r.acceptance = p.acceptance();
  if (!r.acceptance.alternative.description.empty())
    r.acceptance.alternative.T_target_source = in_files(r.acceptance.alternative.T_target_source);
  if (r.acceptance.adopted.applied)
    r.acceptance.adopted.T_target_source = in_files(r.acceptance.adopted.T_target_source);
  r.refinement = p.refinement();
  r.pose_model_configured = p.config().gnc.model;
  r.pose_model_used = p.gnc_params().model;
  r.ground_planes = p.ground_planes();
  if (p.ground_truth()) {
    r.T_target_source_gt = in_files(*p.ground_truth());
    r.error = p.selected_error();
    r.unrefined_error = p.unrefined_error();
    r.any_level_succeeds = p.upper_bound_success();
    if (context.diagnose) r.diagnosis = diagnose(p);
  }
  add_front_end(p, r);
  if (context.matches_file) add_matches_file(p, *context.matches_file, r);
  for (int s = 0; s < kStageCount; ++s) {
    r.stage_ms[static_cast<std::size_t>(s)] = p.time_ms(static_cast<Stage>(s));
    r.total_ms += p.time_ms(static_cast<Stage>(s));
  }
  r.verification_points = p.verifier() ? p.verifier()->source_points().size() : 0;
  r.warnings = p.warnings();
  r.pair_time_budget_hit = p.pair_time_budget_hit();
  r.config = p.config();
  return r;
}

namespace {

void check_not_empty(const PointCloud& source, const PointCloud& target) {
  if (source.empty()) throw InputError("source: the cloud has no points");
  if (target.empty()) throw InputError("target: the cloud has no points");
}

// Runs a pipeline given its inputs; the ground truth comes in the frames of the points as given,
// the pipeline's clouds may have been moved to frames near their points (a cloud's origin).
Registration run(Pipeline& pipeline, const RegisterOptions& options) {
  std::optional<Transform> truth = options.ground_truth;
  if (truth && pipeline.has_clouds())
    truth = to_cloud_frames(*truth, pipeline.source().origin, pipeline.target().origin);
  pipeline.set_ground_truth(truth);
  pipeline.run(options.progress, options.cancel);
  RegistrationContext context;
  context.source_name = options.source_name;
  context.target_name = options.target_name;
  context.diagnose = options.diagnose;
  return make_registration(pipeline, context);
}

}  // namespace

Registration register_clouds(PointCloud source, PointCloud target, const Config& config,
                             const RegisterOptions& options) {
  check_not_empty(source, target);
  Pipeline pipeline(config, options.threads);
  pipeline.set_input(std::move(source), std::move(target), options.label_scheme);
  return run(pipeline, options);
}

Registration register_correspondences(std::vector<Correspondence> matches, const Config& config,
                                      const RegisterOptions& options) {
  Pipeline pipeline(config, options.threads);
  pipeline.set_matches(std::move(matches));
  return run(pipeline, options);
}

Registration register_correspondences(std::vector<Correspondence> matches, PointCloud source,
                                      PointCloud target, const Config& config,
                                      const RegisterOptions& options) {
  check_not_empty(source, target);
  Pipeline pipeline(config, options.threads);
  pipeline.set_matches(std::move(matches));
  pipeline.set_input(std::move(source), std::move(target), options.label_scheme);
  return run(pipeline, options);
}

}  // namespace pagor
