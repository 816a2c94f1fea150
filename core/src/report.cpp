#include "pagor/report.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "pagor/io/clouds.hpp"

namespace pagor {
namespace {

using json = nlohmann::json;

// A finite number, or null (JSON has no infinity).
json finite_or_null(double x) {
  return std::isfinite(x) ? json(x) : json();
}

json error_json(const PoseError& e) {
  return {{"translation_error_m", e.translation},
          {"rotation_error_deg", e.rotation_deg},
          {"success", e.success}};
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
json refinement_json(const Registration& r) {
  const RefinementResult& f = r.refinement;
  json j = {{"enabled", r.config.refinement.enabled}, {"ran", f.ran}};
  if (!f.ran) return j;
  j["applied"] = f.applied;
  j["reason"] = f.reason;
  j["iterations"] = f.iterations;
  j["pairs"] = f.pairs;
  j["D_before"] = f.score_before;
  j["D_after"] = f.score_after;
  j["correction_translation_m"] = f.correction_translation;
  j["correction_rotation_deg"] = f.correction_rotation;
  if (r.unrefined_error) j["before"] = error_json(*r.unrefined_error);
  return j;
}

// The configured pose model and, for `auto` with clouds, the scans' ground planes that decided it.
json pose_model_json(const Registration& r) {
  json j = {{"configured", to_string(r.pose_model_configured)},
            {"used", to_string(r.pose_model_used)}};
  if (const auto& g = r.ground_planes) {
    const auto plane = [](const GroundPlane& x) {
      return json{{"found", x.found}, {"tilt_deg", x.tilt_deg}, {"share", x.share}};
    };
    j["source_ground"] = plane(g->first);
    j["target_ground"] = plane(g->second);
  }
  return j;
}

json level_json(const Registration& r, std::size_t l) {
  const LevelSummary& s = r.levels[l];
  json level = {{"level", l},
                {"epsilon", s.epsilon},
                {"vertices", s.vertices},
                {"edges", s.edges},
                {"clique_size", s.clique.size()},
                {"clique", s.clique},
                {"clique_time_ms", s.clique_time_ms},
                {"clique_gradient_steps", s.clique_gradient_steps},
                {"clique_penalty_updates", s.clique_penalty_updates},
                {"clique_proven", s.clique_proven},
                {"clique_upper_bound",
                 s.clique_number_bound > 0 ? json(s.clique_number_bound) : json()},
                {"clique_budget_hit", to_string(s.clique_budget)},
                {"clique_start", to_string(s.clique_start)},
                {"pose_valid", s.pose.valid},
                {"pose_model", to_string(s.pose.model)},
                {"inliers", s.pose.inliers.size()},
                {"T_target_source", s.pose.valid ? matrix_json(s.pose.T_target_source) : json()},
                {"score_D", finite_or_null(s.score_D)}};
  if (!s.pose.valid) level["failure"] = s.pose.failure;
  if (s.support) {
    level["support"] = *s.support;
    level["support_score"] = finite_or_null(s.support_score);
  }
  if (s.error) {
    level["translation_error_m"] = s.error->translation;
    level["rotation_error_deg"] = s.error->rotation_deg;
    level["success"] = s.error->success;
  }
  if (s.file_inliers) {
    level["precision"] = s.file_inliers->precision;
    level["recall"] = s.file_inliers->recall;
    level["true_inliers"] = s.file_inliers->true_inliers;
  }
  return level;
}

json ground_truth_json(const Registration& r) {
  if (!r.T_target_source_gt) return nullptr;
  json gt = {{"T_target_source", matrix_json(*r.T_target_source_gt)},
             {"upper_bound", r.any_level_succeeds}};
  if (r.error) {
    gt["translation_error_m"] = r.error->translation;
    gt["rotation_error_deg"] = r.error->rotation_deg;
    gt["success"] = r.error->success;
  } else {
    gt["success"] = false;
  }
  return gt;
}

json acceptance_json(const Registration& r) {
  const Acceptance& a = r.acceptance;
  json tests = json::array();
  for (const AcceptanceTest& t : a.tests)
    tests.push_back({{"name", t.name},
                     {"value", finite_or_null(t.value)},
                     {"threshold", finite_or_null(t.threshold)},
                     {"comparison", t.at_most ? "<=" : ">="},
                     {"passed", t.passed},
                     {"applies", t.applies},
                     {"unit", t.unit},
                     {"description", t.description}});
  json alternative = nullptr;
  if (!a.alternative.description.empty())
    alternative = {{"description", a.alternative.description},
                   {"ratio", finite_or_null(a.alternative.ratio)},
                   {"only_alternative", a.alternative.only_alternative},
                   {"only_selected", a.alternative.only_selected},
                   {"T_target_source", matrix_json(a.alternative.T_target_source)}};
  json adopted = nullptr;
  if (a.adopted.applied)
    adopted = {{"from", a.adopted.from},
               {"ratio", finite_or_null(a.adopted.ratio)},
               {"inlier_count", a.adopted.inliers.size()},
               {"score_D", finite_or_null(a.adopted.score_D)},
               {"selected_reason", a.adopted.selected_reason},
               {"T_target_source", matrix_json(a.adopted.T_target_source)}};
  return {{"accepted", a.accepted},   {"verified", a.verified},
          {"overlap", a.overlap},     {"inliers", a.inliers},
          {"margin", a.margin},       {"sharpness", a.sharpness},
          {"ambiguity", a.ambiguity}, {"alternative", alternative},
          {"adopted", adopted},       {"tests", tests},
          {"reason", a.reason},       {"wrong_pose_accepted", r.accepted_wrong()}};
}

json correspondences_json(const Registration& r) {
  json per_class = json::object();
  for (const ClassCount& c : r.classes) per_class[c.name] = c.correspondences;
  const auto one = [](std::size_t n, std::size_t c, std::size_t i) {
    return json{{"count", n}, {"selected_clique", c}, {"selected_inliers", i}};
  };
  json j = {{"count", r.correspondences},
            {"candidates", r.correspondence_candidates},
            {"capped", r.correspondences_capped},
            {"per_class", per_class},
            {"origin",
             {{"landmark", one(r.origin_all.landmark, r.origin_clique.landmark,
                               r.origin_inliers.landmark)},
              {"matcher", one(r.origin_all.matcher, r.origin_clique.matcher,
                              r.origin_inliers.matcher)}}}};
  if (const auto& f = r.matches_file) {  // what only the file knows
    j["file"] = f->path;
    j["weights"] = f->weighted;
    j["inlier_flags"] = !f->inliers.empty();
    j["flagged_inliers"] =
        f->inliers.empty() ? json() : json(std::count_if(f->inliers.begin(), f->inliers.end(), [](char x) { return x != 0; }));
  }
  return j;
}

json timings_json(const Registration& r) {
  const auto ms = [&](Stage s) { return r.stage_ms[static_cast<std::size_t>(s)]; };
  return {{"landmarks", ms(Stage::landmarks)},
          {"correspondences", ms(Stage::correspondences)},
          {"graph", ms(Stage::graph)},
          {"clique", ms(Stage::clique)},
          {"gnc", ms(Stage::gnc)},
          {"verification", ms(Stage::verification_prep) + ms(Stage::verification)},
          {"refinement", ms(Stage::refinement)},
          {"acceptance", ms(Stage::acceptance)},
          {"evaluation", ms(Stage::evaluation)},
          {"total", r.total_ms}};
}

}  // namespace

nlohmann::json matrix_json(const Transform& T) {
  json rows = json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({T(r, 0), T(r, 1), T(r, 2), T(r, 3)});
  return rows;
}

nlohmann::json report_object(const Registration& r, bool with_config) {
  json levels = json::array();
  for (std::size_t l = 0; l < r.levels.size(); ++l) levels.push_back(level_json(r, l));
  json landmarks_source = json::object(), landmarks_target = json::object();
  for (const ClassCount& c : r.classes) {
    landmarks_source[c.name] = c.source;
    landmarks_target[c.name] = c.target;
  }
  json out = {
      {"schema", "pagor.register/1"},
      {"source", r.source_name},
      {"target", r.target_name},
      {"T_target_source", r.T_target_source ? matrix_json(*r.T_target_source) : json()},
      {"selected_level", r.selected_level >= 0 ? json(r.selected_level) : json()},
      {"levels", levels},
      {"selected_by", to_string(r.selected_by)},
      {"pose_model", pose_model_json(r)},
      {"acceptance", acceptance_json(r)},
      {"refinement", refinement_json(r)},
      {"ground_truth", ground_truth_json(r)},
      {"correspondences", correspondences_json(r)},
      {"landmarks", {{"source", landmarks_source}, {"target", landmarks_target}}},
      {"labels", {{"source", labels_json(r.source_labels)}, {"target", labels_json(r.target_labels)}}},
      {"timings_ms", timings_json(r)},
      {"warnings", r.warnings},
      {"pair_time_budget_hit", r.pair_time_budget_hit}};
  if (with_config) out["config"] = json::parse(config_to_json(r.config));
  out["diagnosis"] = r.diagnosis ? json::parse(diagnosis_json(*r.diagnosis)) : json();
  return out;
}

std::string dump_report(const nlohmann::json& report, int indent) {
  // Paths are bytes, not always UTF-8: replace what JSON cannot hold rather than throw. An indent
  // is a number of spaces a reader can bear, not a buffer size.
  return report.dump(std::clamp(indent, -1, 16), ' ', false,
                     nlohmann::json::error_handler_t::replace);
}

std::string to_json(const Registration& registration, int indent, bool with_config) {
  return dump_report(report_object(registration, with_config), indent);
}

}  // namespace pagor
