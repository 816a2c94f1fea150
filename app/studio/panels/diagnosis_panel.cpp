// The diagnosis panel: why the pair failed, stage by stage, against the ground truth (the worker
// computes it; see pagor/diagnosis.hpp), and the 3D view's diagnosis items.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "panels/panels.hpp"
#include "widgets/number_format.hpp"
#include "widgets/timings.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

const ImVec4 kGood(0.35f, 0.9f, 0.45f, 1.0f), kBad(1.0f, 0.4f, 0.4f, 1.0f),
    kDim(0.6f, 0.6f, 0.6f, 1.0f);

void cell_text(const char* text) {
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(text);
}

void cell(std::size_t v) {
  char t[24];
  std::snprintf(t, sizeof(t), "%zu", v);
  cell_text(t);
}

// A matcher's file with inlier flags: how many it flags, beside the diagnosis' own count (its
// rule is the residual under the truth; pagor register --json reports both the same way:
// correspondences.flagged_inliers and diagnosis.true_correspondences).
void flags_line(const Snapshot& s, const Diagnosis& d) {
  if (s.inlier_flags.empty()) return;
  std::size_t flagged = 0;
  for (char f : s.inlier_flags) flagged += f != 0;
  ui::figure(ui::format("the file flags %zu of %zu as inliers (its own rule); %zu are within "
                        "%s of the truth",
                        flagged, s.inlier_flags.size(), d.true_correspondences,
                        with_unit(d.residual_tolerance, "m").c_str()),
             kDim, true);
}

void front_end_table(const Snapshot& s, const Diagnosis& d) {
  ui::figure("Front end (true: residual <= " + with_unit(d.residual_tolerance, "m") + ")",
             ImVec4(0, 0, 0, 0), true);
  flags_line(s, d);
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders |
                                ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX;
  const float h =
      ImGui::GetTextLineHeightWithSpacing() * (static_cast<float>(d.classes.size()) + 3);
  if (!ImGui::BeginTable("front_end", 5, flags, ImVec2(0, h))) return;
  ImGui::TableSetupScrollFreeze(1, 1);
  for (const char* c : {"class", "landm. S/T", "corr.", "true", "best"}) ImGui::TableSetupColumn(c);
  ImGui::TableHeadersRow();
  std::size_t putative = 0;
  char t[48];
  for (const ClassDiagnosis& c : d.classes) {
    ImGui::TableNextRow();
    cell_text(c.name.c_str());
    std::snprintf(t, sizeof(t), "%zu / %zu", c.source_landmarks, c.target_landmarks);
    cell_text(t);
    cell(c.correspondences);
    ImGui::TableNextColumn();
    ImGui::TextColored(c.true_correspondences ? kGood : kDim, "%zu", c.true_correspondences);
    cell(c.best_achievable);
    putative += c.correspondences;
  }
  ImGui::TableNextRow();
  cell_text("all");
  cell_text("");
  cell(putative);
  cell(d.true_correspondences);
  ImGui::TableNextColumn();
  ImGui::TextColored(static_cast<int>(d.best_achievable) >= d.min_true ? kGood : kBad, "%zu",
                     d.best_achievable);
  ImGui::EndTable();
  ImGui::TextDisabled("best: most true ones usable at once\n(one per landmark); %d needed",
                      d.min_true);
}

// One level's row; true when its label was clicked. Without clouds there is no D (n/a).
bool level_row(const Diagnosis& d, std::size_t l, int shown, bool clouds) {
  const LevelDiagnosis& x = d.levels[l];
  ImGui::TableNextRow();
  if (static_cast<int>(l) == d.at_fault_level)
    ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, IM_COL32(120, 60, 40, 170));
  char t[48];
  std::snprintf(t, sizeof(t), "%s%zu##diag_level", static_cast<int>(l) == d.selected ? "* " : "  ",
                l);
  ImGui::TableNextColumn();
  ImGui::PushID(static_cast<int>(l));
  const bool clicked =
      ui::selectable(t, static_cast<int>(l) == shown, ImGuiSelectableFlags_SpanAllColumns);
  ImGui::PopID();
  std::snprintf(t, sizeof(t), "%.3f", x.epsilon);
  cell_text(t);
  cell(x.true_vertices);
  std::snprintf(t, sizeof(t), "%zu%s", x.consistent_true, x.consistent_exact ? "" : "+");
  cell_text(t);
  std::snprintf(t, sizeof(t), "%zu (%zu)", x.clique_size, x.clique_true);
  cell_text(t);
  // A ratio of nothing (an empty clique; no consistent true ones) is undefined: n/a.
  const std::string precision =
      x.clique_size ? ui::format("%.0f", 100.0 * x.clique_true / x.clique_size) : "n/a";
  const std::string recall =
      x.consistent_true
          ? ui::format("%.0f", 100.0 * std::min(1.0, double(x.clique_true) / x.consistent_true))
          : "n/a";
  ImGui::TableNextColumn();
  ui::figure(precision + " / " + recall, x.clique_size && x.precision >= 0.5 ? kGood : kBad);
  ImGui::TableNextColumn();
  if (x.error)
    ImGui::TextColored(x.error->success ? kGood : kBad, "%.2f m, %.2f\xc2\xb0",
                       x.error->translation, x.error->rotation_deg);
  else
    ImGui::TextColored(kDim, "no pose");
  ImGui::TableNextColumn();
  if (!clouds)
    ui::figure("n/a", kDim);
  else if (std::isfinite(x.score))
    ImGui::Text("%.1f", x.score);
  else
    ImGui::TextColored(kDim, "invalid");
  std::snprintf(t, sizeof(t), "%zu (%zu)", x.gnc_inliers, x.gnc_true_inliers);
  cell_text(t);
  cell(x.vertices);
  return clicked;
}

// Per level; returns the level clicked, or -1.
int levels_table(const Diagnosis& d, int shown, bool clouds) {
  int clicked = -1;
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders |
                                ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX;
  const float h = ImGui::GetTextLineHeightWithSpacing() * (static_cast<float>(d.levels.size()) + 3);
  if (!ImGui::BeginTable("diag_levels", 10, flags, ImVec2(0, h))) return -1;
  ImGui::TableSetupScrollFreeze(1, 1);
  for (const char* c : {"level", "\xce\xb5", "true", "consist.", "clique (true)",
                        "truth prec./rec. [%]", "errors", "D [m]", "GNC (true)", "verts"})
    ImGui::TableSetupColumn(c);
  ImGui::TableHeadersRow();
  for (std::size_t l = 0; l < d.levels.size(); ++l)
    if (level_row(d, l, shown, clouds)) clicked = static_cast<int>(l);
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted("truth");
  for (int c = 0; c < 6; ++c) ImGui::TableNextColumn();
  ImGui::TextColored(kDim, "ground truth");
  ImGui::TableNextColumn();
  if (!clouds)
    ui::figure("n/a", kDim);
  else if (std::isfinite(d.gt_score))
    ImGui::TextColored(d.score_misled ? kBad : kGood, "%.1f", d.gt_score);
  ImGui::EndTable();
  return clicked;
}

// The 3D view's diagnosis items.
void view_controls(DiagnosisView& dv, const Snapshot& s) {
  ImGui::TextUnformatted("3D view");
  ui::checkbox("residual colours", &dv.color_by_residual,
               "Colour every correspondence line by its ground-truth residual |T_gt p - q| "
               "(legend in the 3D view)");
  const char* preview = dv.class_name.empty() ? "every class" : dv.class_name.c_str();
  if (ui::begin_combo("class", preview, "Show the correspondences of one class only")) {
    if (ui::selectable("every class", dv.class_name.empty())) dv.class_name.clear();
    for (const ClassSummary& c : s.source_landmarks.classes)
      if (ui::selectable(c.name.c_str(), dv.class_name == c.name)) dv.class_name = c.name;
    ui::end_combo();
  }
  ui::radio("all##truth", &dv.truth, TruthFilter::all, "Every correspondence");
  ImGui::SameLine();
  ui::radio("true##truth", &dv.truth, TruthFilter::inliers,
            "Only those within the tolerance of the truth");
  ImGui::SameLine();
  ui::radio("false##truth", &dv.truth, TruthFilter::outliers,
            "Only those beyond the tolerance of the truth");
  ui::checkbox("graph edges on hover", &dv.edges_on_hover,
               "Hovering a correspondence line shows its edges in the shown level's graph");
  ImGui::TextUnformatted("source points: part of D");
  ui::radio("off##part", &dv.contribution, Contribution::off,
            "Source points in their class (or cloud) colours");
  ImGui::SameLine();
  ui::radio("level##part", &dv.contribution, Contribution::candidate,
            "min(d, \xce\xbc) of each verification point under the shown level's pose, drawn "
            "there");
  ImGui::SameLine();
  ui::radio("truth##part", &dv.contribution, Contribution::ground_truth,
            "min(d, \xce\xbc) of each verification point under the ground truth, drawn there");
}

}  // namespace

void bottom_panel_switch(DiagnosisView& diagnosis) {
  int which = diagnosis.panel ? 1 : 0;
  ui::radio("pyramid##bottom", &which, 0, "Levels, clique sizes, poses and scores");
  ImGui::SameLine();
  ui::radio("diagnosis##bottom", &which, 1,
            "Which stage failed and why, against the ground truth (needs one)");
  diagnosis.panel = which == 1;
  ImGui::SameLine(0.0f, 24.0f);  // the panel's first line follows on this one
}

void diagnosis_panel(const Snapshot* s, const std::string& stale_reason, ViewState& view,
                     const Exports& exports) {
  if (!s) {
    ImGui::TextDisabled("no result yet: open data on the left");
    return;
  }
  if (!s->diagnosis) {
    ImGui::TextWrapped(
        "The diagnosis needs a ground truth: give a 4x4 T_target_source file in the Data panel "
        "(KITTI pairs and the synthetic scene have one).");
    return;
  }
  const Diagnosis& d = *s->diagnosis;
  if (!stale_reason.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.25f, 1.0f), "STALE: %s", stale_reason.c_str());
  const bool ok = d.verdict == DiagnosisVerdict::success;
  ui::figure(
      std::string("verdict: ") + verdict_name(d.verdict) + " - " + verdict_sentence(d.verdict),
      ok ? kGood : kBad);
  ui::figure("why: " + d.explanation, ok ? kGood : kBad, true);
  if (result_button("diagnosis CSV",
                    "Writes the per-level table to <export path>-diagnosis.csv (the export path "
                    "of the Session panel).",
                    stale_reason))
    write_export(exports, "diagnosis.csv", diagnosis_csv(d));

  const float w = ImGui::GetContentRegionAvail().x;
  const float front_w = std::min(330.0f, w * 0.28f), controls_w = std::min(260.0f, w * 0.22f);
  ImGui::BeginChild("diag_front", ImVec2(front_w, 0));
  front_end_table(*s, d);
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginChild("diag_mid", ImVec2(w - front_w - controls_w - 16.0f, 0));
  ImGui::TextUnformatted("Per level: the clique against the most consistent true ones");
  const int shown = shown_level(view, s->selected, static_cast<int>(s->levels.size()));
  const bool clouds = s->source != nullptr;
  const int clicked = levels_table(d, shown, clouds);
  if (clicked >= 0) view.level = clicked;
  ui::figure(
      "truth prec./rec.: the clique's true members over its size / over the most consistent true "
      "ones, by the ground-truth pose (pagor register's flag prec./rec. are against a matcher "
      "file's inlier flags instead).",
      kDim, true);
  // The rule the selection followed, as pagor register --correspondences names it.
  if (clouds)
    ui::figure_dim("* selected (lowest D). Shaded: the level the verdict is about.");
  else
    ui::figure(
        "* selected (lowest S = sum of min(residual, noise bound) over all correspondences; no "
        "clouds, so no D). Shaded: the level the verdict is about.",
        kDim, true);
  if (!clouds)
    ui::figure_dim("D (verification on the clouds): n/a without clouds");
  else if (d.selected >= 0)
    ImGui::TextColored(d.score_misled ? kBad : kDim,
                       "D of the truth %.1f m vs selected %.1f m%s (\xce\xbc %.2f m, %zu points)",
                       d.gt_score, d.levels[static_cast<std::size_t>(d.selected)].score,
                       d.score_misled ? ": the score itself misled" : "", s->config.verification.mu,
                       s->verification_points);
  ImGui::TextDisabled("%s", ui::timing("diagnosis took %.1f ms", d.time_ms).c_str());
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginChild("diag_view", ImVec2(0, 0));
  view_controls(view.diagnosis, *s);
  ImGui::EndChild();
}

}  // namespace pagor::studio
