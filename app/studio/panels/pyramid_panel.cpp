// The pyramid panel: one row per level, the candidate details, and a bar chart of D.

#include <imgui.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pagor/verify/evaluation.hpp"
#include "panels/panels.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

const ImVec4 kGood(0.35f, 0.9f, 0.45f, 1.0f), kBad(1.0f, 0.4f, 0.4f, 1.0f),
    kDim(0.6f, 0.6f, 0.6f, 1.0f);

// What refinement did to the selected pose: D and, with ground truth, the errors before/after.
void refinement_lines(const Snapshot& s) {
  const RefinementResult& r = s.refinement;
  if (!r.ran) {
    ImGui::TextDisabled("refinement: off");
    return;
  }
  if (!r.applied) {
    ImGui::TextDisabled("refinement: not applied (%s)", r.reason.c_str());
    return;
  }
  ImGui::Text("refinement: D %.0f -> %.0f m (%.1f %%), moved %.2f m / %.2f deg", r.score_before,
              r.score_after, 100.0 * (r.score_after - r.score_before) / r.score_before,
              r.correction_translation, r.correction_rotation);
  if (s.unrefined_error && s.selected_error)
    ImGui::Text("  errors before %.2f m / %.2f deg, after %.2f m / %.2f deg",
                s.unrefined_error->translation, s.unrefined_error->rotation_deg,
                s.selected_error->translation, s.selected_error->rotation_deg);
}

// D per level, from zero. Bars are green / red by success when the ground truth is known (else
// blue); the selected level is marked with * and the shown one outlined.
void bar_chart(const Snapshot& s, int shown, const RunChanges& changes) {
  ImGui::TextDisabled("score D per level [m], lower is better, axis from 0");
  const int n = static_cast<int>(s.levels.size());
  double top = 0;
  for (const auto& l : s.levels)
    if (l.pose.valid && std::isfinite(l.score)) top = std::max(top, l.score);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x, label_h = 16.0f;
  const float height = std::clamp(
      ImGui::GetContentRegionAvail().y * 0.55f - label_h - ImGui::GetTextLineHeightWithSpacing(),
      40.0f, 220.0f);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + height + label_h),
                    IM_COL32(30, 32, 38, 255));
  const float base = origin.y + height;
  dl->AddLine(ImVec2(origin.x, base), ImVec2(origin.x + width, base), IM_COL32(160, 160, 160, 255));
  const float slot = width / std::max(n, 1);
  for (int i = 0; i < n; ++i) {
    const auto& l = s.levels[static_cast<std::size_t>(i)];
    const float x0 = origin.x + slot * i + slot * 0.15f,
                x1 = origin.x + slot * (i + 1) - slot * 0.15f;
    char text[48];
    if (l.pose.valid && std::isfinite(l.score) && top > 0) {
      const float h = static_cast<float>(l.score / top) * (height - 18.0f);
      const ImU32 color = !l.error           ? IM_COL32(90, 130, 200, 255)
                          : l.error->success ? IM_COL32(80, 200, 110, 255)
                                             : IM_COL32(215, 80, 80, 255);
      dl->AddRectFilled(ImVec2(x0, base - h), ImVec2(x1, base), color);
      if (i == shown)
        dl->AddRect(ImVec2(x0 - 2, base - h - 2), ImVec2(x1 + 2, base),
                    IM_COL32(255, 255, 255, 255), 0, 0, 2.0f);
      const auto k = static_cast<std::size_t>(i);
      if (k < changes.levels.size() && changes.levels[k].d_delta &&
          std::abs(*changes.levels[k].d_delta) > 1e-9)
        std::snprintf(text, sizeof(text), "%.0f (%+.0f)", l.score, *changes.levels[k].d_delta);
      else
        std::snprintf(text, sizeof(text), "%.0f", l.score);
      if (ImGui::CalcTextSize(text).x > slot * 0.95f)  // too narrow for the delta
        std::snprintf(text, sizeof(text), "%.0f", l.score);
      dl->AddText(ImVec2(x0, base - h - 15.0f), IM_COL32(220, 220, 220, 255), text);
    } else {
      dl->AddText(ImVec2(x0, base - 16.0f), IM_COL32(255, 110, 110, 255), "invalid");
    }
    std::snprintf(text, sizeof(text), "L%d%s", i, i == s.selected ? " *" : "");
    dl->AddText(ImVec2(x0, base + 1.0f), IM_COL32(200, 200, 200, 255), text);
  }
  ImGui::Dummy(ImVec2(width, height + label_h));
  if (const auto m = score_margin(s))
    ImGui::Text("margin %.0f m (%.2g %%): L%d %.0f vs L%d %.0f", m->second - m->best,
                m->best > 0 ? 100.0 * (m->second - m->best) / m->best : 0.0, m->best_level, m->best,
                m->second_level, m->second);
  else
    ImGui::TextDisabled("margin: fewer than two valid levels");
  if (s.selected >= 0) {  // the verdict a loop-closure user acts on; wrapped in a narrow column
    ImGui::PushTextWrapPos(0.0f);
    const Acceptance& a = s.acceptance;
    ImGui::TextColored(a.accepted ? ImVec4(0.45f, 0.85f, 0.45f, 1) : ImVec4(1, 0.45f, 0.45f, 1),
                       "%s: %.0f %% of structure within %.2f m, %d inliers%s%s",
                       a.accepted ? "ACCEPTED" : "REJECTED", 100.0 * a.overlap,
                       s.config.acceptance.inlier_distance, a.inliers, a.accepted ? "" : "; ",
                       a.reason.c_str());
    refinement_lines(s);
    ImGui::PopTextWrapPos();
  }
}

// The stale-results warning, or the line saying the last run changed the selected level.
void change_line(const RunChanges& changes, const std::string& stale_reason) {
  if (!stale_reason.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.25f, 1.0f));
    ImGui::PushTextWrapPos(0.0f);
    ImGui::Text("STALE: results below are from an earlier run (%s)", stale_reason.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
  } else if (changes.selected_changed()) {
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
  ImGui::Text("%zu", l.clique.size());
  ImGui::TableNextColumn();
  if (l.pose.valid)
    ImGui::Text("%.1f", l.score);
  else
    ImGui::TextColored(kDim, "invalid");
  ImGui::TableNextColumn();
  if (changes.comparable && change && change->d_delta && std::abs(*change->d_delta) > 1e-9)
    ImGui::TextColored(*change->d_delta < 0 ? kGood : kBad, "%+.1f", *change->d_delta);
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
    ImGui::Text("%7.2f %6.2f %6.2f", T(0, 3), T(1, 3), T(2, 3));
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", yaw_pitch_roll_deg(T.block<3, 3>(0, 0)).x());
  } else {
    ImGui::TextColored(kDim, "%s", l.pose.failure.c_str());
    ImGui::TableNextColumn();
  }
  return clicked;
}

// One row per level; returns the level clicked, or -1.
int levels_table(const Snapshot& s, int shown, const RunChanges& changes) {
  int clicked = -1;
  const bool gt = s.ground_truth.has_value();
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders |
                                ImGuiTableFlags_ScrollX | ImGuiTableFlags_SizingFixedFit;
  const int columns = gt ? 12 : 9;
  const float table_h =
      ImGui::GetTextLineHeightWithSpacing() * (static_cast<float>(s.levels.size()) + 2.4f);
  if (!ImGui::BeginTable("pyramid", columns, flags, ImVec2(0, table_h))) return -1;
  ImGui::TableSetupScrollFreeze(1, 1);
  // A difference TRIM's thresholds are lengths; a ratio's have no unit.
  const char* eps = s.config.graph.trim == TrimKind::difference ? "\xce\xb5 [m]" : "\xce\xb5";
  for (const char* h : {"level", eps, "verts", "edges", "clique", "D [m]",
                        "\xce\x94"
                        "D"})
    ImGui::TableSetupColumn(h);
  if (gt) {
    ImGui::TableSetupColumn("t err [m]");
    ImGui::TableSetupColumn("r err [\xc2\xb0]");
    ImGui::TableSetupColumn("ok");
  }
  ImGui::TableSetupColumn("t (x, y, z) [m]");
  ImGui::TableSetupColumn("yaw [\xc2\xb0]");
  ImGui::TableHeadersRow();
  for (int i = 0; i < static_cast<int>(s.levels.size()); ++i)
    if (level_row(s, i, shown, changes)) clicked = i;
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
    if (l.pose.valid) {
      const Transform& T = l.pose.T_target_source;
      const Eigen::Vector3d a = yaw_pitch_roll_deg(T.block<3, 3>(0, 0));
      ImGui::Text("t = (%.2f, %.2f, %.2f) m", T(0, 3), T(1, 3), T(2, 3));
      ImGui::Text("yaw %.2f\xc2\xb0 pitch %.2f\xc2\xb0 roll %.2f\xc2\xb0", a.x(), a.y(), a.z());
      ImGui::Text("%zu GNC inliers, %d iterations", l.pose.inliers.size(), l.pose.iterations);
    } else {
      ImGui::TextColored(kBad, "no pose: %s", l.pose.failure.c_str());
    }
  }
  if (gt) {
    ImGui::Spacing();
    if (s.selected_error)
      ImGui::TextColored(s.selected_error->success ? kGood : kBad,
                         "selected: %s (%.2f m, %.2f\xc2\xb0)",
                         s.selected_error->success ? "SUCCESS" : "FAILURE",
                         s.selected_error->translation, s.selected_error->rotation_deg);
    else
      ImGui::TextColored(kBad, "selected: none");
    ImGui::SameLine();
    ImGui::TextDisabled("bound: %s", s.upper_bound ? "yes" : "no");
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
                   ViewState& view) {
  if (!s) {
    ImGui::TextDisabled("no result yet: open data on the left");
    return;
  }
  change_line(changes, stale_reason);
  ImGui::PushStyleVar(ImGuiStyleVar_Alpha, stale_reason.empty() ? 1.0f : 0.55f);
  ImGui::Text("%s", s->description.c_str());
  ImGui::TextDisabled("%zu / %zu cluster landmarks, %zu correspondences%s",
                      cluster_landmark_count(s->source_landmarks),
                      cluster_landmark_count(s->target_landmarks), s->correspondences.size(),
                      s->correspondences_capped ? " (capped)" : "");
  const int shown = shown_level(view, s->selected, static_cast<int>(s->levels.size()));
  origin_line(*s, shown);
  const float chart_w = std::min(330.0f, ImGui::GetContentRegionAvail().x * 0.34f);
  ImGui::BeginChild("levels", ImVec2(ImGui::GetContentRegionAvail().x - chart_w - 8.0f, 0));
  const int clicked = levels_table(*s, shown, changes);
  if (clicked >= 0) view.level = clicked;
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
