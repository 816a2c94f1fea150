#include "pagor/report.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "pagor/io/clouds.hpp"

namespace pagor {
namespace {

using json = nlohmann::json;

json matrix_json(const Transform& T) {
  json rows = json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({T(r, 0), T(r, 1), T(r, 2), T(r, 3)});
  return rows;
}

json counts_by_class(const LandmarkSet& set) {
  json j = json::object();
  for (const auto& c : set.classes) j[c.name] = c.landmarks;
  return j;
}

// How a cloud's labels were read: the scheme in use, whether detected, and what they look like.
json labels_json(const LabelReading& r) {
  json j = {{"scheme", r.scheme.name},
            {"automatic", r.automatic},
            {"looks_like", r.detection.scheme},
            {"margin_nats", r.detection.margin}};
  if (!r.detection.reason.empty()) j["reason"] = r.detection.reason;
  j["mismatch"] = r.mismatch.empty() ? json() : json(r.mismatch);
  return j;
}

// What refinement did; the errors before it when the ground truth is known.
json refinement_json(const Pipeline& p) {
  const RefinementResult& r = p.refinement();
  json j = {{"enabled", p.config().refinement.enabled}, {"ran", r.ran}};
  if (!r.ran) return j;
  j["applied"] = r.applied;
  j["reason"] = r.reason;
  j["iterations"] = r.iterations;
  j["pairs"] = r.pairs;
  j["D_before"] = r.score_before;
  j["D_after"] = r.score_after;
  j["correction_translation_m"] = r.correction_translation;
  j["correction_rotation_deg"] = r.correction_rotation;
  if (const auto e = p.unrefined_error())
    j["before"] = {{"translation_error_m", e->translation},
                   {"rotation_error_deg", e->rotation_deg},
                   {"success", e->success}};
  return j;
}

// Per origin: the correspondences, the selected clique's members and its pose's inliers.
json origin_json(const Pipeline& p) {
  const auto& items = p.correspondences().items;
  const OriginCounts all = count_by_origin(items);
  OriginCounts clique, inliers;
  const int sel = p.selected_level();
  if (sel >= 0 && static_cast<std::size_t>(sel) < p.cliques().size()) {
    clique = count_by_origin(items, p.cliques()[static_cast<std::size_t>(sel)].vertices);
    if (static_cast<std::size_t>(sel) < p.poses().size())
      inliers = count_by_origin(items, p.poses()[static_cast<std::size_t>(sel)].inliers);
  }
  const auto one = [](std::size_t n, std::size_t c, std::size_t i) {
    return json{{"count", n}, {"selected_clique", c}, {"selected_inliers", i}};
  };
  return {{"landmark", one(all.landmark, clique.landmark, inliers.landmark)},
          {"matcher", one(all.matcher, clique.matcher, inliers.matcher)}};
}

// The configured pose model and, for `auto` with clouds, the scans' ground planes that decided it.
json gravity_json(const Pipeline& p) {
  json j = {{"configured", to_string(p.config().gnc.model)},
            {"used", to_string(p.gnc_params().model)}};
  if (const auto& g = p.ground_planes()) {
    const auto plane = [](const GroundPlane& x) {
      return json{{"found", x.found}, {"tilt_deg", x.tilt_deg}, {"share", x.share}};
    };
    j["source_ground"] = plane(g->first);
    j["target_ground"] = plane(g->second);
  }
  return j;
}

json report_object(const Pipeline& p, const std::string& source_name,
                   const std::string& target_name) {
  // Poses as the user's files have them (the pipeline's are between the clouds' own frames).
  const auto pose_json = [&](const Transform& T) {
    return matrix_json(to_file_frames(T, p.source().origin, p.target().origin));
  };
  json levels = json::array();
  const auto& g = p.graph();
  for (std::size_t l = 0; l < p.cliques().size(); ++l) {
    const auto& c = p.cliques()[l];
    const auto& pose = p.poses()[l];
    const double D = p.verification().scores.size() > l ? p.verification().scores[l] : HUGE_VAL;
    json level = {{"level", l},
                  {"epsilon", g.thresholds[l]},
                  {"vertices", g.active_vertices(static_cast<int>(l))},
                  {"edges", g.edges_at_level[l]},
                  {"clique_size", c.vertices.size()},
                  {"clique", c.vertices},
                  {"clique_time_ms", c.time_ms},
                  {"clique_gradient_steps", c.gradient_steps},
                  {"clique_penalty_updates", c.penalty_updates},
                  {"clique_proven", c.optimal},
                  {"clique_upper_bound", c.upper_bound > 0 ? json(c.upper_bound) : json()},
                  {"clique_budget_hit", to_string(c.budget)},
                  {"clique_start", to_string(c.start)},
                  {"pose_valid", pose.valid},
                  {"pose_model", to_string(pose.model)},
                  {"inliers", pose.inliers.size()},
                  {"T_target_source", pose.valid ? pose_json(pose.T_target_source) : json()},
                  {"score_D", std::isfinite(D) ? json(D) : json()}};
    if (!pose.valid) level["failure"] = pose.failure;
    const VerificationResult& v = p.verification();
    if (l < v.support.size()) {  // selected without clouds
      level["support"] = v.support[l];
      level["support_score"] =
          std::isfinite(v.support_scores[l]) ? json(v.support_scores[l]) : json();
    }
    if (l < p.level_errors().size() && p.level_errors()[l]) {
      const auto& e = *p.level_errors()[l];
      level["translation_error_m"] = e.translation;
      level["rotation_error_deg"] = e.rotation_deg;
      level["success"] = e.success;
    }
    levels.push_back(level);
  }
  const auto selected = p.selected_transform();
  json gt = nullptr;
  if (p.ground_truth()) {
    gt = {{"T_target_source", pose_json(*p.ground_truth())},
          {"upper_bound", p.upper_bound_success()}};
    if (const auto e = p.selected_error()) {
      gt["translation_error_m"] = e->translation;
      gt["rotation_error_deg"] = e->rotation_deg;
      gt["success"] = e->success;
    } else {
      gt["success"] = false;
    }
  }
  json per_class = json::object();
  const auto& corr = p.correspondences();
  for (std::size_t c = 0; c < corr.per_class.size() && c < p.source_landmarks().classes.size(); ++c)
    per_class[p.source_landmarks().classes[c].name] = corr.per_class[c];
  json timings = json::object();
  double total = 0;
  for (int s = 0; s < kStageCount; ++s) total += p.time_ms(static_cast<Stage>(s));
  timings["landmarks"] = p.time_ms(Stage::landmarks);
  timings["correspondences"] = p.time_ms(Stage::correspondences);
  timings["graph"] = p.time_ms(Stage::graph);
  timings["clique"] = p.time_ms(Stage::clique);
  timings["gnc"] = p.time_ms(Stage::gnc);
  timings["verification"] = p.time_ms(Stage::verification_prep) + p.time_ms(Stage::verification);
  timings["refinement"] = p.time_ms(Stage::refinement);
  timings["acceptance"] = p.time_ms(Stage::acceptance);
  timings["evaluation"] = p.time_ms(Stage::evaluation);
  timings["total"] = total;

  json out = {
      {"schema", "pagor.register/1"},
      {"source", source_name},
      {"target", target_name},
      {"T_target_source", selected ? pose_json(*selected) : json()},
      {"selected_level", p.selected_level() >= 0 ? json(p.selected_level()) : json()},
      {"levels", levels},
      {"selected_by", p.has_clouds() ? "score_D" : "without_clouds"},
      {"pose_model", gravity_json(p)},
      {"acceptance",
       {{"accepted", p.acceptance().accepted},
        {"verified", p.acceptance().verified},
        {"overlap", p.acceptance().overlap},
        {"inliers", p.acceptance().inliers},
        {"margin", p.acceptance().margin},
        {"sharpness", p.acceptance().sharpness},
        {"reason", p.acceptance().reason}}},
      {"refinement", refinement_json(p)},
      {"ground_truth", gt},
      {"correspondences",
       {{"count", corr.items.size()},
        {"candidates", corr.candidates},
        {"capped", corr.capped},
        {"per_class", per_class},
        {"origin", origin_json(p)}}},
      {"landmarks",
       {{"source", counts_by_class(p.source_landmarks())},
        {"target", counts_by_class(p.target_landmarks())}}},
      {"labels",
       {{"source", labels_json(p.source_landmarks().labels)},
        {"target", labels_json(p.target_landmarks().labels)}}},
      {"timings_ms", timings},
      {"warnings", p.warnings()},
      {"pair_time_budget_hit", p.pair_time_budget_hit()},
      {"config", json::parse(config_to_json(p.config()))}};
  return out;
}

// Paths are bytes, not always UTF-8: replace what JSON cannot hold rather than throw.
std::string dump(const json& report, int indent) {
  return report.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace

std::string registration_report_json(const Pipeline& p, const std::string& source_name,
                                     const std::string& target_name, int indent) {
  return dump(report_object(p, source_name, target_name), indent);
}

std::string registration_report_json(const Pipeline& p, const std::string& source_name,
                                     const std::string& target_name,
                                     const std::optional<Diagnosis>& diagnosis, int indent) {
  json out = report_object(p, source_name, target_name);
  out["diagnosis"] = diagnosis ? json::parse(diagnosis_json(*diagnosis)) : json();
  return dump(out, indent);
}

}  // namespace pagor
