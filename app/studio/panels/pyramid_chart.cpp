#include "panels/pyramid_chart.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pagor/registration.hpp"
#include "widgets/number_format.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

const ImVec4 kGood(0.35f, 0.9f, 0.45f, 1.0f), kBad(1.0f, 0.45f, 0.45f, 1.0f),
    kAmber(1.0f, 0.8f, 0.3f, 1.0f), kDim(0.6f, 0.6f, 0.6f, 1.0f);
constexpr std::size_t kWarningLines = 2;

// What refinement did to the selected pose: D and, with ground truth, the errors before/after.
void refinement_lines(const Snapshot& s) {
  const RefinementResult& r = s.refinement;
  if (!r.ran) {
    ui::figure_dim("refinement: off");
    return;
  }
  if (!r.applied) {
    ui::figure_dim("refinement: not applied (" + r.reason + ")");
    return;
  }
  const std::string change =
      r.score_before > 0
          ? ui::format("%.1f %%", 100.0 * (r.score_after - r.score_before) / r.score_before)
          : std::string("n/a");
  ui::figure(ui::format("refinement: D %.0f -> %.0f m (%s), moved %.2f m / %.2f\xc2\xb0",
                        r.score_before, r.score_after, change.c_str(), r.correction_translation,
                        r.correction_rotation));
  const std::optional<PoseError> after = refined_error(s);
  if (s.unrefined_error && after)
    ui::figure(ui::format("  errors before %.2f m / %.2f\xc2\xb0, after %.2f m / %.2f\xc2\xb0",
                          s.unrefined_error->translation, s.unrefined_error->rotation_deg,
                          after->translation, after->rotation_deg));
}

// The labels under the bars: every level's when they fit, else every k-th (never overlapping).
int label_stride(int n, float slot) {
  const float label_w = ImGui::CalcTextSize("L00 *").x + 4.0f;
  int stride = 1;
  while (stride < n && slot * stride < label_w) ++stride;
  return stride;
}

}  // namespace

std::optional<PoseError> refined_error(const Snapshot& s) {
  if (!s.acceptance.adopted.applied) return s.selected_error;
  if (!s.ground_truth || !s.refinement.applied) return std::nullopt;
  return pose_error(s.refinement.T_after, *s.ground_truth, s.config.evaluation);
}

std::string selected_text(const Snapshot& s) {
  const PoseError& e = *s.selected_error;
  std::string t = ui::format("selected: %s (L%d), ", e.success ? "SUCCESS" : "FAILURE", s.selected);
  if (s.acceptance.adopted.applied)
    return ui::format("selected: %s (the verdict's alternative, in place of L%d's pose), ",
                      e.success ? "SUCCESS" : "FAILURE", s.selected) +
           ui::format("%.2f m / %.2f\xc2\xb0", e.translation, e.rotation_deg);
  if (!s.refinement.applied)
    return t + ui::format("%.2f m / %.2f\xc2\xb0 (not refined)", e.translation, e.rotation_deg);
  t += ui::format("refined %.2f m / %.2f\xc2\xb0", e.translation, e.rotation_deg);
  if (s.unrefined_error)
    t += ui::format(" (candidate before refinement %.2f m / %.2f\xc2\xb0)",
                    s.unrefined_error->translation, s.unrefined_error->rotation_deg);
  return t;
}

bool same_pose(const Transform& a, const Transform& b) {
  const double dt = (a.block<3, 1>(0, 3) - b.block<3, 1>(0, 3)).norm();
  const Eigen::Matrix3d R = a.block<3, 3>(0, 0).transpose() * b.block<3, 3>(0, 0);
  const double angle_deg =
      std::acos(std::clamp((R.trace() - 1.0) / 2.0, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
  return dt <= kSamePoseTranslation && angle_deg <= kSamePoseRotationDeg;
}

std::string level_gap_text(const Snapshot& s) {
  const auto m = d_gap(s);
  if (!m && !s.source) return "D gap to the runner-up pose: n/a (no clouds, so no D)";
  if (!m) return "D gap to the runner-up pose: n/a (fewer than two valid levels)";
  // The runner-up is the best level with another pose: levels that found the selected pose
  // again (the same clique) score the same D and are no competition.
  const Transform& best = s.levels[static_cast<std::size_t>(m->best_level)].pose.T_target_source;
  std::string same;
  int runner = -1;
  for (std::size_t i = 0; i < s.levels.size(); ++i) {
    const LevelView& l = s.levels[i];
    if (static_cast<int>(i) == m->best_level || !l.pose.valid || !std::isfinite(l.score_D))
      continue;
    if (same_pose(l.pose.T_target_source, best))
      same += (same.empty() ? "L" : ", L") + std::to_string(i);
    else if (runner < 0 || l.score_D < s.levels[static_cast<std::size_t>(runner)].score_D)
      runner = static_cast<int>(i);
  }
  std::string t = "D gap to the runner-up pose: n/a (every valid level found the same pose)";
  if (runner >= 0) {
    const double d = s.levels[static_cast<std::size_t>(runner)].score_D;
    // Three significant digits: a gap of half a metre is not "0 m".
    t = "D gap to the runner-up pose: " + with_unit(d - m->best, "m") +
        ui::format(" (L%d %.1f m, L%d %.1f m)", m->best_level, m->best, runner, d);
  }
  if (!same.empty())
    t += "; " + same + " found the same pose as L" + std::to_string(m->best_level) + " (same D)";
  return t;
}

// Whether the verdict trusted a pose that the loaded ground truth calls wrong.
bool accepted_wrong(const Snapshot& s) {
  return wrong_pose_accepted(s.acceptance.accepted, s.selected_error);
}

// The verdict with every test it took, each with its value and threshold (test_text, as the CLI
// prints them); the margin as a share of mu times the points.
std::string acceptance_text(const Snapshot& s) {
  const Acceptance& a = s.acceptance;
  const AcceptanceParams& p = s.config.acceptance;
  if (!a.verified) return "not verified: " + a.reason;
  std::string t = accepted_wrong(s) ? "ACCEPTED, BUT THE GROUND TRUTH CALLS THE POSE WRONG"
                  : a.accepted      ? "ACCEPTED"
                                    : "REJECTED";
  std::string tests;
  for (const AcceptanceTest& x : a.tests) {
    if (!x.applies) continue;
    tests += tests.empty() ? "" : ", ";
    if (x.name == "margin")
      tests += ui::format("acceptance margin %.0f %% of \xce\xbc\xc2\xb7points (needs %.0f %%)%s",
                          100.0 * a.margin, 100.0 * p.min_margin, x.passed ? "" : ": FAILED");
    else
      tests += test_text(x);
  }
  t += ": " + tests + ui::format(" (aligned: within %.2f m)", p.inlier_distance);
  if (!a.accepted) t += "; " + a.reason;
  if (a.adopted.applied)
    t += ui::format(
        "; adopted in place of L%d's pose: %s, which fitted %.2f times as well where both are "
        "seen, refitted on %zu GNC inliers (L%d's pose: %s)",
        s.selected, a.adopted.from.c_str(), a.adopted.ratio, a.adopted.inliers.size(), s.selected,
        a.adopted.selected_reason.c_str());
  if (!a.alternative.description.empty())
    t += ui::format(
        "; best distinct alternative: %s (%.2f times as well supported: %zu points only it "
        "aligns, %zu only the selected pose)",
        a.alternative.description.c_str(), a.alternative.ratio, a.alternative.only_alternative,
        a.alternative.only_selected);
  return t;
}

void bar_chart(const Snapshot& s, int shown, const RunChanges& changes) {
  ImGui::TextDisabled("score D per level [m], lower is better, axis from 0");
  const int n = static_cast<int>(s.levels.size());
  double top = 0;
  for (const auto& l : s.levels)
    if (l.pose.valid && std::isfinite(l.score_D)) top = std::max(top, l.score_D);
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
  const int stride = label_stride(n, slot);
  for (int i = 0; i < n; ++i) {
    const auto& l = s.levels[static_cast<std::size_t>(i)];
    const float x0 = origin.x + slot * i + slot * 0.15f,
                x1 = origin.x + slot * (i + 1) - slot * 0.15f;
    char text[48];
    if (l.pose.valid && std::isfinite(l.score_D) && top > 0) {
      const float h = static_cast<float>(l.score_D / top) * (height - 18.0f);
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
        std::snprintf(text, sizeof(text), "%.0f (%+.0f)", l.score_D, *changes.levels[k].d_delta);
      else
        std::snprintf(text, sizeof(text), "%.0f", l.score_D);
      if (ImGui::CalcTextSize(text).x > slot * 0.95f)  // too narrow for the delta
        std::snprintf(text, sizeof(text), "%.0f", l.score_D);
      if (ImGui::CalcTextSize(text).x <= slot * stride * 0.95f && i % stride == 0)
        dl->AddText(ImVec2(x0, base - h - 15.0f), IM_COL32(220, 220, 220, 255), text);
    } else if (i % stride == 0) {
      if (l.pose.valid)  // a pose, but no clouds to score it on
        dl->AddText(ImVec2(x0, base - 16.0f), IM_COL32(170, 170, 170, 255), "no D");
      else
        dl->AddText(ImVec2(x0, base - 16.0f), IM_COL32(255, 110, 110, 255), "invalid");
    }
    if (i % stride != 0 && i != s.selected) continue;
    std::snprintf(text, sizeof(text), "L%d%s", i, i == s.selected ? " *" : "");
    dl->AddText(ImVec2(x0, base + 1.0f), IM_COL32(200, 200, 200, 255), text);
  }
  ImGui::Dummy(ImVec2(width, height + label_h));
  ui::figure(level_gap_text(s), ImGui::GetStyle().Colors[ImGuiCol_TextDisabled], true);
  if (s.selected >= 0) {  // the verdict a loop-closure user acts on; wrapped in a narrow column
    const Acceptance& a = s.acceptance;
    const ImVec4 color = accepted_wrong(s) ? kBad : !a.verified ? kDim : a.accepted ? kGood : kBad;
    ui::figure(acceptance_text(s), color, true);
    ImGui::PushTextWrapPos(0.0f);
    refinement_lines(s);
    ImGui::PopTextWrapPos();
  }
}

void diagnosis_verdict_line(const Snapshot& s) {
  if (!s.diagnosis) return;
  const Diagnosis& d = *s.diagnosis;
  const bool ok = d.verdict == DiagnosisVerdict::success;
  ui::figure(std::string("diagnosis: ") + verdict_name(d.verdict) + ": " + d.explanation,
             ok ? kGood : kBad, true);
}

void warning_lines(const Snapshot& s) {
  for (std::size_t i = 0; i < s.warnings.size() && i < kWarningLines; ++i)
    ui::figure("warning: " + s.warnings[i], kAmber, true);
  if (s.warnings.size() > kWarningLines)
    ui::figure_dim(
        ui::format("(%zu more warnings: hover the status bar)", s.warnings.size() - kWarningLines));
}

}  // namespace pagor::studio
