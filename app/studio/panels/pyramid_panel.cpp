// The pyramid panel: one row per level, the candidate details, and a bar chart of D.

#include <imgui.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pagor/verify/evaluation.hpp"
#include "panels/exports.hpp"
#include "panels/panels.hpp"
#include "panels/pyramid_chart.hpp"
#include "widgets/number_format.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

const ImVec4 kGood(0.35f, 0.9f, 0.45f, 1.0f), kBad(1.0f, 0.4f, 0.4f, 1.0f),
    kDim(0.6f, 0.6f, 0.6f, 1.0f), kRefined(0.55f, 0.78f, 1.0f, 1.0f);

// The stale-results warning, or the line saying the last run changed the selected level.
void change_line(const RunChanges& changes, const std::string& stale_reason) {
  // Always one line (its full text on hover), so that the table and the buttons below do not move
  // while a run is pending.
  if (!stale_reason.empty()) {
    const std::string text = "STALE: results below are from an earlier run (" + stale_reason + ")";
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.25f, 1.0f));
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopStyleColor();
    ui::hover_tooltip(text);
  } else if (!changes.selected_changed()) {
    ImGui::TextUnformatted("");
  } else {
    // A level, or "none" where a run selected nothing (no valid candidate).
    const auto level = [&](int l, double eps, TrimKind trim) {
      char text[48] = "none";
      if (l >= 0)
        std::snprintf(text, sizeof(text), "\xce\xb5 %.3g%s (L%d)", eps, trim_unit_suffix(trim), l);
      return std::string(text);
    };
    ImGui::TextColored(
        ImVec4(1.0f, 0.85f, 0.3f, 1.0f), "last run changed the selection: %s -> %s",
        level(changes.selected_before, changes.selected_eps_before, changes.trim_before).c_str(),
        level(changes.selected_after, changes.selected_eps_after, changes.trim_after).c_str());
  }
}

// How the level's clique search ended: proven maximum, or the bound it reached and the budget that
// stopped it; and how it started.
std::string clique_search_text(const LevelView& l) {
  std::string out;
  if (l.clique_proven)
    out = "proven maximum";
  else if (l.clique_number_bound > static_cast<int>(l.clique.size()))
    out = "not proven; bound " + std::to_string(l.clique_number_bound);
  else
    out = "not proven (relaxation only)";
  if (l.clique_budget == CliqueBudget::probe)
    out += "; not settled: search of clique.probe_nodes, no fallback";
  else if (l.clique_budget != CliqueBudget::none)
    out += std::string("; ") + to_string(l.clique_budget) + " budget ran out";
  return out + "; start " + to_string(l.clique_start);
}

// ΔD against the previous run: the level of the same ε, or the level at the same place whose ε
// was edited (said so); "new" for a level inserted.
void delta_cell(const RunChanges& changes, const LevelChange* change) {
  if (!changes.comparable || !change) return;
  if (change->added) {
    ui::figure("new", kDim);
    return;
  }
  const std::string eps =
      change->epsilon_before ? ui::format(" (\xce\xb5 was %.3g)", *change->epsilon_before) : "";
  if (change->d_delta && std::abs(*change->d_delta) > 1e-9)
    ui::figure(ui::format("%+.1f", *change->d_delta) + eps, *change->d_delta < 0 ? kGood : kBad);
  else if (!eps.empty())
    ui::figure((change->d_delta ? "0" : "n/a") + eps, kDim);
}

// One level's row of the table; true when its label was clicked.
bool level_row(const Snapshot& s, int i, int shown, const RunChanges& changes) {
  const bool gt = s.ground_truth.has_value();
  const LevelView& l = s.levels[static_cast<std::size_t>(i)];
  const LevelChange* change = static_cast<std::size_t>(i) < changes.levels.size()
                                  ? &changes.levels[static_cast<std::size_t>(i)]
                                  : nullptr;
  ImGui::TableNextRow();
  const bool flipped = changes.comparable && change &&
                       (change->success_flipped || change->validity_flipped ||
                        (changes.selected_changed() && (l.epsilon == changes.selected_eps_before ||
                                                        i == changes.selected_after)));
  if (flipped) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, IM_COL32(120, 95, 20, 160));
  ImGui::TableNextColumn();
  char label[32];
  std::snprintf(label, sizeof(label), "%s%d", i == s.selected ? "* " : "  ", i);
  const bool clicked = ui::selectable(label, i == shown, ImGuiSelectableFlags_SpanAllColumns);
  ImGui::TableNextColumn();
  ImGui::Text("%.3f", l.epsilon);
  ImGui::TableNextColumn();
  ImGui::Text("%zu", l.vertices);
  ImGui::TableNextColumn();
  ImGui::Text("%zu", l.edges);
  ImGui::TableNextColumn();
  if (l.clique_proven || l.clique_number_bound <= static_cast<int>(l.clique.size()))
    ImGui::Text("%zu", l.clique.size());
  else  // not proven maximum: the bound the search reached
    ImGui::Text("%zu (bound %d)", l.clique.size(), l.clique_number_bound);
  ImGui::TableNextColumn();
  if (l.pose.valid && std::isfinite(l.score_D))
    ImGui::Text("%.1f", l.score_D);
  else
    ImGui::TextColored(kDim, l.pose.valid ? "n/a" : "invalid");  // n/a: no clouds to score on
  ImGui::TableNextColumn();
  delta_cell(changes, change);
  if (gt) {
    ImGui::TableNextColumn();
    if (l.error) ImGui::Text("%.2f", l.error->translation);
    ImGui::TableNextColumn();
    if (l.error) ImGui::Text("%.2f", l.error->rotation_deg);
    ImGui::TableNextColumn();
    if (l.error)
      ImGui::TextColored(l.error->success ? kGood : kBad, "%s%s", l.error->success ? "yes" : "no",
                         change && change->success_flipped ? " (flipped)" : "");
  }
  ImGui::TableNextColumn();
  if (l.pose.valid) {
    const Transform& T = l.pose.T_target_source;
    ImGui::Text("%7s %6s %6s", fixed(T(0, 3), 2).c_str(), fixed(T(1, 3), 2).c_str(),
                fixed(T(2, 3), 2).c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(fixed(yaw_pitch_roll_deg(T.block<3, 3>(0, 0)).x(), 2).c_str());
  } else {
    ImGui::TextColored(kDim, "%s", l.pose.failure.c_str());
    ImGui::TableNextColumn();
  }
  return clicked;
}

// A pose row's cells after D: ΔD (empty), the errors (with a ground truth), translation, yaw.
void pose_cells(const Snapshot& s, const std::optional<PoseError>& e, const Transform& T) {
  ImGui::TableNextColumn();  // ΔD
  if (s.ground_truth.has_value()) {
    ImGui::TableNextColumn();
    if (e) ui::figure(ui::format("%.2f", e->translation));
    ImGui::TableNextColumn();
    if (e) ui::figure(ui::format("%.2f", e->rotation_deg));
    ImGui::TableNextColumn();
    if (e) ui::figure(e->success ? "yes" : "no", e->success ? kGood : kBad);
  }
  ImGui::TableNextColumn();
  ui::figure(ui::format("%7s %6s %6s", fixed(T(0, 3), 2).c_str(), fixed(T(1, 3), 2).c_str(),
                        fixed(T(2, 3), 2).c_str()));
  ImGui::TableNextColumn();
  ui::figure(fixed(yaw_pitch_roll_deg(T.block<3, 3>(0, 0)).x(), 2));
}

// Under the selected level's row, when refinement moved its pose: the refined pose, its D and
// errors (what the verdict, copy and exports give unless the verdict adopted an alternative),
// labelled; the row above is the candidate.
void refined_row(const Snapshot& s) {
  const RefinementResult& r = s.refinement;
  if (!r.applied || s.selected < 0) return;
  ImGui::TableNextRow();
  ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, IM_COL32(40, 70, 110, 140));
  ImGui::TableNextColumn();
  ui::figure("  refined", kRefined);
  ui::hover_tooltip(
      "The selected level's pose after refinement (ICP on the clouds): the pose the verdict, "
      "copy and exports give. The row above is the candidate before refinement.");
  for (int c = 0; c < 5; ++c) ImGui::TableNextColumn();  // eps, verts, edges, clique -> D
  ui::figure(ui::format("%.1f", r.score_after));
  pose_cells(s, refined_error(s), r.T_after);
}

// Under the selected level's rows, when the verdict took its better-fitting alternative in place
// of the selected pose (acceptance.adopt_alternative): that pose, its D and errors.
void adopted_row(const Snapshot& s) {
  const AcceptanceAdoption& a = s.acceptance.adopted;
  if (!a.applied || s.selected < 0) return;
  ImGui::TableNextRow();
  ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, IM_COL32(40, 90, 60, 140));
  ImGui::TableNextColumn();
  ui::figure("  adopted", kRefined);
  ui::hover_tooltip("The verdict's alternative taken in place of the selected pose: " + a.from +
                    ui::format(" fitted %.2f times as well where both poses are seen; refitted "
                               "by GNC on %zu correspondences, it was accepted. It is the pose "
                               "the copy and exports give.",
                               a.ratio, a.inliers.size()));
  for (int c = 0; c < 5; ++c) ImGui::TableNextColumn();  // eps, verts, edges, clique -> D
  ui::figure(ui::format("%.1f", a.score_D));
  pose_cells(s, s.selected_error, a.T_target_source);
}

// One row per level; returns the level clicked, or -1.
int levels_table(const Snapshot& s, int shown, const RunChanges& changes) {
  int clicked = -1;
  const bool gt = s.ground_truth.has_value();
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders |
                                ImGuiTableFlags_ScrollX | ImGuiTableFlags_SizingFixedFit;
  const int columns = gt ? 12 : 9;
  const float rows = static_cast<float>(s.levels.size()) + (s.refinement.applied ? 1.0f : 0.0f) +
                     (s.acceptance.adopted.applied ? 1.0f : 0.0f);
  const float table_h = ImGui::GetTextLineHeightWithSpacing() * (rows + 2.4f);
  if (!ImGui::BeginTable("pyramid", columns, flags, ImVec2(0, table_h))) return -1;
  ImGui::TableSetupScrollFreeze(1, 1);
  // A difference TRIM's thresholds are lengths; a ratio's have no unit.
  const char* eps = s.config.graph.trim == TrimKind::difference ? "\xce\xb5 [m]" : "\xce\xb5";
  for (const char* h : {"level", eps, "verts", "edges", "clique", "D [m]",
                        "\xce\x94"
                        "D [m]"})
    ImGui::TableSetupColumn(h);
  if (gt) {
    ImGui::TableSetupColumn("t err [m]");
    ImGui::TableSetupColumn("r err [\xc2\xb0]");
    ImGui::TableSetupColumn("ok");
  }
  ImGui::TableSetupColumn("t (x, y, z) [m]");
  ImGui::TableSetupColumn("yaw [\xc2\xb0]");
  ImGui::TableHeadersRow();
  for (int i = 0; i < static_cast<int>(s.levels.size()); ++i) {
    if (level_row(s, i, shown, changes)) clicked = i;
    if (i == s.selected) {
      refined_row(s);
      adopted_row(s);
    }
  }
  ImGui::EndTable();
  return clicked;
}

// The shown level's candidate and, with a ground truth, the selected pose's outcome.
void level_details(const Snapshot& s, int shown) {
  const bool gt = s.ground_truth.has_value();
  if (shown >= 0) {
    const LevelView& l = s.levels[static_cast<std::size_t>(shown)];
    ImGui::Spacing();
    ImGui::Text("level %d (\xce\xb5 %.3f%s): clique of %zu", shown, l.epsilon,
                trim_unit_suffix(s.config.graph.trim), l.clique.size());
    ui::figure(clique_search_text(l), ImGui::GetStyle().Colors[ImGuiCol_TextDisabled], true);
    if (l.pose.valid) {
      const Transform& T = l.pose.T_target_source;
      const Eigen::Vector3d a = yaw_pitch_roll_deg(T.block<3, 3>(0, 0));
      ui::figure("t = (" + fixed(T(0, 3), 2) + ", " + fixed(T(1, 3), 2) + ", " + fixed(T(2, 3), 2) +
                 ") m");
      ui::figure("yaw " + fixed(a.x(), 2) + "\xc2\xb0 pitch " + fixed(a.y(), 2) + "\xc2\xb0 roll " +
                 fixed(a.z(), 2) + "\xc2\xb0");
      ImGui::Text("%zu GNC inliers, %d iterations", l.pose.inliers.size(), l.pose.iterations);
    } else {
      ImGui::TextColored(kBad, "no pose: %s", l.pose.failure.c_str());
    }
  }
  if (gt) {
    ImGui::Spacing();
    if (s.selected_error)
      ui::figure(selected_text(s), s.selected_error->success ? kGood : kBad, true);
    else
      ui::figure("selected: none", kBad);
    ui::figure_dim(ui::format("upper bound (any pose right): %s", s.upper_bound ? "yes" : "no"));
  }
}

// With a matcher's correspondences: how many of each origin, and of the shown level's clique.
void origin_line(const Snapshot& s, int shown) {
  const OriginCounts all = count_by_origin(s.correspondences);
  if (all.matcher == 0) return;
  if (shown < 0 || shown >= static_cast<int>(s.levels.size())) {
    ImGui::TextDisabled("by origin: landmark %zu, matcher %zu", all.landmark, all.matcher);
    return;
  }
  const OriginCounts clique =
      count_by_origin(s.correspondences, s.levels[static_cast<std::size_t>(shown)].clique);
  ImGui::TextDisabled(
      "by origin: landmark %zu, matcher %zu; level %d clique: landmark %zu, "
      "matcher %zu",
      all.landmark, all.matcher, shown, clique.landmark, clique.matcher);
}

}  // namespace

void pyramid_panel(const Snapshot* s, const RunChanges& changes, const std::string& stale_reason,
                   ViewState& view, const Exports& exports) {
  if (!s) {
    ImGui::TextDisabled("no result yet: open data on the left");
    return;
  }
  change_line(changes, stale_reason);
  ImGui::PushStyleVar(ImGuiStyleVar_Alpha, stale_reason.empty() ? 1.0f : 0.55f);
  ImGui::Text("%s", s->description.c_str());
  if (!s->matches_file.empty() && !s->source)
    ImGui::TextDisabled("%zu correspondences from the matcher's file, no clouds",
                        s->correspondences.size());
  else
    ImGui::TextDisabled("%zu / %zu cluster landmarks, %zu correspondences%s",
                        cluster_landmark_count(s->source_landmarks),
                        cluster_landmark_count(s->target_landmarks), s->correspondences.size(),
                        s->correspondences_capped ? " (capped)" : "");
  diagnosis_verdict_line(*s);
  warning_lines(*s);
  result_exports(*s, stale_reason, exports);
  const int shown = shown_level(view, s->selected, static_cast<int>(s->levels.size()));
  origin_line(*s, shown);
  const float chart_w = std::min(330.0f, ImGui::GetContentRegionAvail().x * 0.34f);
  ImGui::BeginChild("levels", ImVec2(ImGui::GetContentRegionAvail().x - chart_w - 8.0f, 0));
  const int clicked = levels_table(*s, shown, changes);
  if (clicked >= 0) view.level = clicked;
  if (!s->source)  // as pagor register --correspondences says it
    ui::figure(
        "* selected: lowest S = sum of min(residual, noise bound) over all correspondences (no "
        "clouds, so no D). Click a row to view its level.",
        kDim, true);
  else
    ImGui::TextDisabled(
        "* selected: lowest D (\xce\xbc %.2f m, %zu points). Click a row to view its level.",
        s->config.verification.mu, s->verification_points);

  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginChild("chart", ImVec2(0, 0));
  bar_chart(*s, shown, changes);
  level_details(*s, shown);
  ImGui::EndChild();
  ImGui::PopStyleVar();
}

}  // namespace pagor::studio
