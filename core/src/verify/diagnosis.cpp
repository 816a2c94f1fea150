#include "pagor/verify/diagnosis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

namespace pagor {
namespace {

// Maximum bipartite matching (Kuhn's augmenting paths) between source and target landmarks over
// the given correspondences: the largest set using every landmark at most once.
class Matching {
 public:
  explicit Matching(const std::vector<const Correspondence*>& edges) {
    for (const Correspondence* c : edges) adjacency_[c->source].push_back(c->target);
  }
  std::size_t size() {
    std::size_t matched = 0;
    for (const auto& entry : adjacency_) {
      visited_.clear();
      if (augment(entry.first)) ++matched;
    }
    return matched;
  }

 private:
  bool augment(int s) {
    for (int t : adjacency_[s]) {
      if (!visited_.insert({t, true}).second) continue;
      const auto owner = match_of_target_.find(t);
      if (owner == match_of_target_.end() || augment(owner->second)) {
        match_of_target_[t] = s;
        return true;
      }
    }
    return false;
  }
  std::map<int, std::vector<int>> adjacency_;
  std::map<int, int> match_of_target_;
  std::map<int, bool> visited_;
};

void diagnose_front_end(const DiagnosisInput& in, Diagnosis& d) {
  const auto& items = in.correspondences->items;
  const auto& sc = in.source_landmarks->classes;
  const auto& tc = in.target_landmarks->classes;
  // A matcher's correspondences (no class) are one more entry, "matcher", whose landmarks are
  // the keypoints they use.
  const std::size_t matcher = sc.size();
  std::vector<std::vector<const Correspondence*>> true_by_class(sc.size() + 1);
  d.classes.resize(sc.size() + 1);
  for (std::size_t c = 0; c < sc.size(); ++c) {
    d.classes[c].name = sc[c].name;
    d.classes[c].source_landmarks = sc[c].landmarks;
    d.classes[c].target_landmarks = c < tc.size() ? tc[c].landmarks : 0;
  }
  d.classes[matcher].name = "matcher";
  std::vector<int> sources, targets;
  for (const Correspondence& c : items)
    if (c.origin == CorrespondenceOrigin::matcher) {
      sources.push_back(c.source);
      targets.push_back(c.target);
    }
  for (auto* ids : {&sources, &targets}) {
    std::sort(ids->begin(), ids->end());
    ids->erase(std::unique(ids->begin(), ids->end()), ids->end());
  }
  d.classes[matcher].source_landmarks = sources.size();
  d.classes[matcher].target_landmarks = targets.size();
  for (std::size_t i = 0; i < items.size(); ++i) {
    const auto c = items[i].origin == CorrespondenceOrigin::matcher
                       ? matcher
                       : static_cast<std::size_t>(items[i].class_index);
    if (c >= d.classes.size()) continue;
    ++d.classes[c].correspondences;
    if (!d.is_true(i)) continue;
    ++d.classes[c].true_correspondences;
    true_by_class[c].push_back(&items[i]);
  }
  for (std::size_t c = 0; c < d.classes.size(); ++c) {
    d.classes[c].best_achievable = Matching(true_by_class[c]).size();
    d.true_correspondences += d.classes[c].true_correspondences;
    d.best_achievable += d.classes[c].best_achievable;
  }
  if (d.classes[matcher].correspondences == 0) d.classes.pop_back();  // landmarks only
}

// Per level: true vertices, the largest consistent set of true ones, clique precision / recall,
// GNC inliers, errors and D.
void diagnose_levels(const DiagnosisInput& in, const Transform& T_gt, const DiagnosisParams& params,
                     Diagnosis& d) {
  const PyramidGraph& g = *in.graph;
  const auto& items = in.correspondences->items;
  std::vector<Correspondence> true_items;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (d.is_true(i)) true_items.push_back(items[i]);
  // The graph restricted to the true correspondences: the same TRIM test on the same pairs.
  const PyramidGraph true_graph = build_pyramid_graph(true_items, in.config->graph);
  CliqueParams exact = in.config->clique;
  exact.exact_max_nodes = params.exact_max_nodes;
  // Bounded by nodes only: a diagnosis must not depend on how busy the machine is.
  exact.exact_time_budget_ms = 0;

  for (std::size_t l = 0; l < in.cliques->size(); ++l) {
    const int level = static_cast<int>(l);
    LevelDiagnosis ld;
    ld.epsilon = l < g.thresholds.size() ? g.thresholds[l] : 0.0;
    for (int v = 0; v < g.vertices; ++v) {
      const auto sv = static_cast<std::size_t>(v);
      bool active = false;
      for (auto e = g.offsets[sv]; e < g.offsets[sv + 1] && !active; ++e)
        active = g.level[static_cast<std::size_t>(e)] <= level;
      if (!active) continue;
      ++ld.vertices;
      ld.true_vertices += d.is_true(sv);
    }
    if (!true_items.empty() && level < true_graph.levels()) {
      const CliqueResult best = exact_max_clique(true_graph, level, exact);
      ld.consistent_true = best.vertices.size();
      ld.consistent_exact = best.proven;
    }
    const auto& clique = (*in.cliques)[l].vertices;
    ld.clique_size = clique.size();
    std::vector<int> true_members;
    for (int v : clique)
      if (d.is_true(static_cast<std::size_t>(v))) true_members.push_back(v);
    ld.clique_true = true_members.size();
    ld.clique_origin = count_by_origin(items, clique);
    ld.clique_true_origin = count_by_origin(items, true_members);
    ld.precision = clique.empty() ? 0.0 : double(ld.clique_true) / double(clique.size());
    ld.recall = ld.consistent_true == 0
                    ? 1.0
                    : std::min(1.0, double(ld.clique_true) / double(ld.consistent_true));
    if (l < in.poses->size()) {
      const PoseEstimate& pose = (*in.poses)[l];
      ld.pose_valid = pose.valid;
      ld.gnc_inliers = pose.inliers.size();
      for (int v : pose.inliers) ld.gnc_true_inliers += d.is_true(static_cast<std::size_t>(v));
      if (pose.valid) ld.error = pose_error(pose.T_target_source, T_gt, in.config->evaluation);
    }
    const auto& scores = in.verification->scores;
    ld.score = l < scores.size() ? scores[l] : HUGE_VAL;
    d.levels.push_back(ld);
  }
}

template <class... Args>
std::string format(const char* fmt, Args... args) {
  // Measured first: an alternative's description (the classes that fix it) has no set length.
  const int n = std::max(std::snprintf(nullptr, 0, fmt, args...), 0);
  std::string out(static_cast<std::size_t>(n) + 1, '\0');
  std::snprintf(out.data(), out.size(), fmt, args...);
  out.resize(static_cast<std::size_t>(n));
  return out;
}

// Labels that do not fit the scheme in use come before every stage: the landmarks were made of
// the wrong points. True (with the verdict set) when a cloud's do not.
bool judge_labels(const DiagnosisInput& in, Diagnosis& d) {
  for (const auto& [side, set] :
       {std::pair{"source", in.source_landmarks}, std::pair{"target", in.target_landmarks}}) {
    const LabelReading& r = set->labels;
    if (r.mismatch.empty()) continue;
    d.verdict = DiagnosisVerdict::label_scheme;
    d.labels_look_like = r.detection.scheme;
    d.explanation = std::string(side) + " " + r.mismatch;
    return true;
  }
  return false;
}

// The first stage at fault, in pipeline order, and the numbers behind it; `adoption_named` set
// when the sentence blames the verdict's adopted alternative.
void judge(const DiagnosisInput& in, const DiagnosisParams& params, Diagnosis& d,
           bool& adoption_named) {
  using V = DiagnosisVerdict;
  const auto n = d.levels.size();
  const auto at = [&](int l) -> const LevelDiagnosis& {
    return d.levels[static_cast<std::size_t>(l)];
  };
  int best_right = -1;  // a successful candidate with the lowest D
  for (std::size_t l = 0; l < n; ++l) {
    const auto& e = d.levels[l].error;
    if (e && e->success && (best_right < 0 || d.levels[l].score < at(best_right).score))
      best_right = static_cast<int>(l);
  }
  const auto sel = d.selected;
  if (d.selected_error && d.selected_error->success) {
    d.verdict = V::success;
    const auto& e = *d.selected_error;
    const auto& c = at(sel).error;  // the candidate before refinement
    d.explanation = format("level %d selected and right (%.2f m, %.2f deg)", sel, e.translation,
                           e.rotation_deg);
    if (in.acceptance && in.acceptance->adopted.applied)
      d.explanation = format(
          "level %d selected; the verdict's alternative, adopted in its place, is right (%.2f m, "
          "%.2f deg)",
          sel, e.translation, e.rotation_deg);
    else if (c && !c->success)
      d.explanation += format(" after refinement; its candidate was off by %.2f m, %.2f deg",
                              c->translation, c->rotation_deg);
    return;
  }
  if (judge_labels(in, d)) return;
  if (in.acceptance && in.acceptance->adopted.applied && d.selected_error && best_right >= 0) {
    // The verdict replaced the selection by its alternative, and a level's candidate was right.
    d.verdict = V::verification_wrong;
    d.at_fault_level = best_right;
    const auto& e = *d.selected_error;
    d.explanation = format(
        "the verdict adopted %s in place of level %d's pose, and it is wrong (%.2f m, %.2f deg); "
        "level %d's candidate was right",
        in.acceptance->adopted.from.c_str(), sel, e.translation, e.rotation_deg, best_right);
    adoption_named = true;
    return;
  }
  if (best_right >= 0) {
    d.verdict = V::verification_wrong;
    d.at_fault_level = best_right;
    const double selected_D = sel >= 0 ? at(sel).score : HUGE_VAL;
    if (!std::isfinite(at(best_right).score)) {  // selected without clouds: there is no D
      d.explanation =
          format("level %d was right, level %d was selected (without clouds)", best_right, sel);
      return;
    }
    d.explanation = format("level %d was right with D %.1f m, the selected one had D %.1f m",
                           best_right, at(best_right).score, selected_D) +
                    format("; the ground truth scores D %.1f m", d.gt_score) +
                    (d.score_misled ? " (D itself misled)" : "");
    return;
  }
  if (static_cast<int>(d.best_achievable) < d.min_true) {
    d.verdict = V::too_few_true;
    d.explanation = format("%zu true correspondences (%zu usable at once), %d needed",
                           d.true_correspondences, d.best_achievable, d.min_true);
    return;
  }
  std::size_t most_consistent = 0;
  int richest = -1;
  for (std::size_t l = 0; l < n; ++l)
    if (d.levels[l].consistent_true > most_consistent || richest < 0) {
      most_consistent = d.levels[l].consistent_true;
      richest = static_cast<int>(l);
    }
  if (static_cast<int>(most_consistent) < d.min_true) {
    d.verdict = V::not_consistent;
    d.explanation = format(
        "%zu usable true correspondences, at most %zu of them consistent at any epsilon, %d needed",
        d.best_achievable, most_consistent, d.min_true);
    return;
  }
  for (std::size_t l = 0; l < n; ++l)
    if (static_cast<int>(d.levels[l].clique_true) >= d.min_true &&
        d.levels[l].precision >= params.right_clique_precision) {
      d.verdict = V::pose_wrong;
      d.at_fault_level = static_cast<int>(l);
      const auto& e = d.levels[l].error;
      d.explanation =
          format("level %zu clique holds %zu true of %zu, ", l, d.levels[l].clique_true,
                 d.levels[l].clique_size) +
          (e ? format("but its pose is off by %.2f m, %.2f deg", e->translation, e->rotation_deg)
             : std::string("but it gave no pose"));
      return;
    }
  d.verdict = V::clique_missed;
  d.at_fault_level = richest;
  const auto& r = d.levels[static_cast<std::size_t>(richest)];
  d.explanation = format(
      "%zu true correspondences consistent at level %d, its clique holds %zu "
      "true of %zu",
      most_consistent, richest, r.clique_true, r.clique_size);
}

// Fused correspondences: which origin the selected clique's members and true ones come from.
void explain_origins(const DiagnosisInput& in, Diagnosis& d) {
  const OriginCounts all = count_by_origin(in.correspondences->items);
  if (all.landmark == 0 || all.matcher == 0) return;
  if (d.selected < 0 || d.selected >= static_cast<int>(d.levels.size())) return;
  const LevelDiagnosis& l = d.levels[static_cast<std::size_t>(d.selected)];
  d.explanation += format("; selected clique: %zu landmark (%zu true), %zu matcher (%zu true)",
                          l.clique_origin.landmark, l.clique_true_origin.landmark,
                          l.clique_origin.matcher, l.clique_true_origin.matcher);
}

}  // namespace

const char* verdict_name(DiagnosisVerdict v) {
  return to_string(v);
}

const char* verdict_sentence(DiagnosisVerdict v) {
  return enum_doc(v);
}

Diagnosis diagnose(const DiagnosisInput& in, const Transform& T_gt, const DiagnosisParams& params) {
  const auto t0 = std::chrono::steady_clock::now();
  Diagnosis d;
  d.residual_tolerance = params.residual_tolerance > 0
                             ? params.residual_tolerance
                             : in.config->evaluation.max_translation_error;
  d.min_true =
      params.min_true > 0 ? params.min_true : minimal_sample_size(in.config->gnc.model) + 1;
  const Eigen::Matrix3d R = T_gt.block<3, 3>(0, 0);
  const Eigen::Vector3d t = T_gt.block<3, 1>(0, 3);
  for (const Correspondence& c : in.correspondences->items)
    d.residuals.push_back((R * c.p + t - c.q).norm());
  diagnose_front_end(in, d);
  diagnose_levels(in, T_gt, params, d);
  const VerificationParams& vp = in.config->verification;
  d.gt_score = in.verifier ? in.verifier->score(T_gt, vp.mu, vp.score) : HUGE_VAL;
  d.selected = in.verification->selected;
  if (d.selected >= 0 && d.selected < static_cast<int>(d.levels.size())) {
    const auto& sel = d.levels[static_cast<std::size_t>(d.selected)];
    d.selected_error =
        in.selected_pose ? pose_error(*in.selected_pose, T_gt, in.config->evaluation) : sel.error;
    d.score_misled = !(d.selected_error && d.selected_error->success) && d.gt_score > sel.score;
  }
  bool adoption_named = false;  // the verdict's sentence already blames the adoption
  judge(in, params, d, adoption_named);
  if (in.acceptance && in.acceptance->adopted.applied && d.selected_error &&
      !d.selected_error->success && !adoption_named)
    d.explanation += "; the verdict adopted " + in.acceptance->adopted.from +
                     " in place of the selected pose, also wrong";
  if (in.acceptance && !in.acceptance->alternative.description.empty() &&
      !(d.selected_error && d.selected_error->success) &&
      pose_error(in.acceptance->alternative.T_target_source, T_gt, in.config->evaluation).success) {
    d.alternative_right = true;
    d.explanation +=
        "; the ambiguity's alternative, " + in.acceptance->alternative.description + ", is right";
  }
  explain_origins(in, d);
  d.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return d;
}

std::optional<Diagnosis> diagnose(const Pipeline& p, const DiagnosisParams& params) {
  if (!p.ground_truth()) return std::nullopt;
  DiagnosisInput in;
  in.source_landmarks = &p.source_landmarks();
  in.target_landmarks = &p.target_landmarks();
  in.correspondences = &p.correspondences();
  in.graph = &p.graph();
  in.cliques = &p.cliques();
  in.poses = &p.poses();
  in.verification = &p.verification();
  in.verifier = p.verifier();
  in.config = &p.config();
  in.selected_pose = p.selected_transform();
  in.acceptance = &p.acceptance();
  return diagnose(in, *p.ground_truth(), params);
}

std::vector<float> point_contributions(const Verifier& verifier, const Transform& T, double mu) {
  std::vector<float> d = verifier.distances(T, static_cast<float>(mu));
  for (float& x : d) x = std::min(x, static_cast<float>(mu));
  return d;
}

namespace {

nlohmann::json finite_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
}

nlohmann::json level_json(const LevelDiagnosis& l) {
  nlohmann::json j = {
      {"epsilon", l.epsilon},
      {"vertices", l.vertices},
      {"true_vertices", l.true_vertices},
      {"consistent_true", l.consistent_true},
      {"consistent_exact", l.consistent_exact},
      {"clique_size", l.clique_size},
      {"clique_true", l.clique_true},
      {"precision", l.precision},
      {"recall", l.recall},
      {"pose_valid", l.pose_valid},
      {"gnc_inliers", l.gnc_inliers},
      {"gnc_true_inliers", l.gnc_true_inliers},
      {"score_D", finite_or_null(l.score)},
      {"origin",
       {{"landmark",
         {{"clique", l.clique_origin.landmark}, {"clique_true", l.clique_true_origin.landmark}}},
        {"matcher",
         {{"clique", l.clique_origin.matcher}, {"clique_true", l.clique_true_origin.matcher}}}}}};
  if (l.error) {
    j["translation_error_m"] = l.error->translation;
    j["rotation_error_deg"] = l.error->rotation_deg;
    j["success"] = l.error->success;
  }
  return j;
}

}  // namespace

std::string diagnosis_json(const Diagnosis& d, int indent) {
  using json = nlohmann::json;
  json classes = json::array();
  for (const ClassDiagnosis& c : d.classes)
    classes.push_back({{"name", c.name},
                       {"source_landmarks", c.source_landmarks},
                       {"target_landmarks", c.target_landmarks},
                       {"correspondences", c.correspondences},
                       {"true_correspondences", c.true_correspondences},
                       {"best_achievable", c.best_achievable}});
  json levels = json::array();
  json candidates = json::array();
  for (const LevelDiagnosis& l : d.levels) {
    levels.push_back(level_json(l));
    candidates.push_back(finite_or_null(l.score));
  }
  const json out = {
      {"verdict", verdict_name(d.verdict)},
      {"stage_at_fault", verdict_sentence(d.verdict)},
      {"explanation", d.explanation},
      {"at_fault_level", d.at_fault_level >= 0 ? json(d.at_fault_level) : json()},
      {"labels_look_like", d.labels_look_like.empty() ? json() : json(d.labels_look_like)},
      {"residual_tolerance_m", d.residual_tolerance},
      {"min_true", d.min_true},
      {"true_correspondences", d.true_correspondences},
      {"best_achievable", d.best_achievable},
      {"classes", classes},
      {"levels", levels},
      {"verification",
       {{"gt_score_D", finite_or_null(d.gt_score)},
        {"candidates_D", candidates},
        {"selected", d.selected >= 0 ? json(d.selected) : json()},
        {"score_misled", d.score_misled}}},
      {"alternative_right", d.alternative_right},
      {"time_ms", d.time_ms}};
  return out.dump(indent, ' ', false, json::error_handler_t::replace);
}

}  // namespace pagor
