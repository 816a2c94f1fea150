#include "panels/exports.hpp"

#include <imgui.h>

#include <Eigen/Geometry>
#include <cmath>
#include <nlohmann/json.hpp>

#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/report.hpp"  // matrix_json: a transform as the report writes it
#include "pagor/verify/evaluation.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

// A number as CSV: shortest exact text; an undefined one (NaN, +-inf) is an empty cell.
std::string cell(double v) {
  return std::isfinite(v) ? nlohmann::json(v).dump() : std::string();
}

}  // namespace

void write_export(const Exports& to, const std::string& name, const std::string& text) {
  const std::string path = absolute_path(to.base + "-" + name);
  try {
    write_file_atomic(path, text);
    to.actions.notify(Message::info("wrote " + path));
  } catch (const Error& e) {
    to.actions.notify(Message::error(e.what()));
  }
}

std::string pose_matrix_text(const Transform& T) {
  std::string out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out += cell(T(r, c)) + (c == 3 ? "\n" : " ");
  return out;
}

std::string pose_json(const Transform& T, int level, bool refined, const std::string& adopted) {
  nlohmann::json j{{"T_target_source", matrix_json(T)}, {"level", level}, {"refined", refined}};
  if (!adopted.empty()) j["adopted_from"] = adopted;  // the verdict's alternative, not the level's
  return j.dump(2) + "\n";
}

std::string levels_csv(const Snapshot& s) {
  std::string out =
      "level,selected,epsilon,vertices,edges,clique,D_m,translation_error_m,rotation_error_deg,"
      "success,tx_m,ty_m,tz_m,yaw_deg\n";
  for (std::size_t i = 0; i < s.levels.size(); ++i) {
    const LevelView& l = s.levels[i];
    out += std::to_string(i) + "," + (static_cast<int>(i) == s.selected ? "1" : "0") + "," +
           cell(l.epsilon) + "," + std::to_string(l.vertices) + "," + std::to_string(l.edges) +
           "," + std::to_string(l.clique.size()) + "," + cell(l.pose.valid ? l.score_D : NAN) + ",";
    out += l.error ? cell(l.error->translation) + "," + cell(l.error->rotation_deg) + "," +
                         (l.error->success ? "1" : "0")
                   : std::string(",,");
    const Transform& T = l.pose.T_target_source;
    out += l.pose.valid ? "," + cell(T(0, 3)) + "," + cell(T(1, 3)) + "," + cell(T(2, 3)) + "," +
                              cell(yaw_pitch_roll_deg(T.block<3, 3>(0, 0)).x())
                        : std::string(",,,,");
    out += "\n";
  }
  return out;
}

std::string diagnosis_csv(const Diagnosis& d) {
  std::string out =
      "level,epsilon,vertices,true_vertices,consistent_true,clique,clique_true,precision,recall,"
      "translation_error_m,rotation_error_deg,D_m,gnc_inliers,gnc_true_inliers\n";
  for (std::size_t i = 0; i < d.levels.size(); ++i) {
    const LevelDiagnosis& l = d.levels[i];
    // A ratio of nothing is undefined: an empty cell, as the studio shows n/a.
    const double precision = l.clique_size ? double(l.clique_true) / l.clique_size : NAN;
    const double recall =
        l.consistent_true ? std::min(1.0, double(l.clique_true) / l.consistent_true) : NAN;
    out += std::to_string(i) + "," + cell(l.epsilon) + "," + std::to_string(l.vertices) + "," +
           std::to_string(l.true_vertices) + "," + std::to_string(l.consistent_true) + "," +
           std::to_string(l.clique_size) + "," + std::to_string(l.clique_true) + "," +
           cell(precision) + "," + cell(recall) + "," +
           (l.error ? cell(l.error->translation) + "," + cell(l.error->rotation_deg) : ",") + "," +
           cell(l.score) + "," + std::to_string(l.gnc_inliers) + "," +
           std::to_string(l.gnc_true_inliers) + "\n";
  }
  return out;
}

bool result_button(const char* label, const char* tip, const std::string& stale_reason) {
  if (stale_reason.empty()) return ui::small_button(label, tip);
  ImGui::BeginDisabled();
  const std::string why = std::string(tip) + "\nDisabled: the result shown is stale (" +
                          stale_reason +
                          "); it would export the earlier run's. Wait for the run to finish.";
  ui::small_button(label, why.c_str());
  ImGui::EndDisabled();
  return false;
}

void result_exports(const Snapshot& s, const std::string& stale_reason, const Exports& to) {
  const bool selected = s.selected >= 0 && s.selected < static_cast<int>(s.levels.size());
  // The selected pose as the CLI reports it: the verdict's adopted alternative when it took one,
  // else refined when refinement applied.
  const bool refined = s.refinement.ran && s.refinement.applied;
  const Transform T = !selected                      ? Transform::Identity()
                      : s.acceptance.adopted.applied ? s.acceptance.adopted.T_target_source
                      : refined
                          ? s.refinement.T_after
                          : s.levels[static_cast<std::size_t>(s.selected)].pose.T_target_source;
  ImGui::BeginDisabled(!selected);
  if (result_button("copy pose 4x4",
                    "The selected pose T_target_source (the verdict's adopted alternative when it "
                    "took one, else refined when refinement applied) as 4 rows of 4 numbers.",
                    stale_reason))
    to.actions.copy_text(pose_matrix_text(T), "the pose as a 4x4 matrix");
  ImGui::SameLine();
  if (result_button("copy pose JSON", "The selected pose as JSON, with its level.", stale_reason))
    to.actions.copy_text(pose_json(T, s.selected, refined && !s.acceptance.adopted.applied,
                                   s.acceptance.adopted.applied ? s.acceptance.adopted.from : ""),
                         "the pose as JSON");
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (result_button("copy result JSON",
                    "The whole result as pagor register --json writes it (pagor.register/1).",
                    stale_reason))
    to.actions.copy_text(s.report_json, "the result JSON");
  ImGui::SameLine();
  if (result_button("save result JSON",
                    "Writes the result JSON to <export path>-result.json (the export path of the "
                    "Session panel).",
                    stale_reason))
    write_export(to, "result.json", s.report_json);
  ImGui::SameLine();
  if (result_button("levels CSV",
                    "Writes the levels table to <export path>-levels.csv (the export path of the "
                    "Session panel).",
                    stale_reason))
    write_export(to, "levels.csv", levels_csv(s));
}

}  // namespace pagor::studio
