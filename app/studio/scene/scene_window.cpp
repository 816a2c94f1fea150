// The 3D view window: the scene image, camera input, hover tooltips and a legend.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/diagnosis_overlay.hpp"
#include "pagor/graph/trim.hpp"
#include "panels/panels.hpp"
#include "scene/plan_overlay.hpp"
#include "scene/scene_overlay.hpp"

namespace pagor::studio {
namespace {

constexpr float kLandmarkPickPx = 8.0f, kLinePickPx = 4.0f;

float segment_distance(const Eigen::Vector2f& m, const Eigen::Vector2f& a,
                       const Eigen::Vector2f& b) {
  const Eigen::Vector2f ab = b - a;
  const float t =
      ab.squaredNorm() > 0 ? std::clamp((m - a).dot(ab) / ab.squaredNorm(), 0.0f, 1.0f) : 0.0f;
  return (a + t * ab - m).norm();
}

void landmark_tooltip(const LandmarkSet& set, int index, bool source) {
  const Landmark& lm = set.landmarks[static_cast<std::size_t>(index)];
  ImGui::Text("%s landmark %d: %s (%s)", source ? "source" : "target", index,
              set.classes[static_cast<std::size_t>(lm.class_index)].name.c_str(),
              lm.kind == LandmarkKind::cluster ? "cluster" : "FPFH keypoint");
  ImGui::Text("centroid (%.2f, %.2f, %.2f) m, %zu points", lm.centroid.x(), lm.centroid.y(),
              lm.centroid.z(), lm.point_count);
  if (lm.kind == LandmarkKind::cluster)
    ImGui::Text("spread (std. dev.) %.2f / %.2f / %.2f m", std::sqrt(lm.covariance(0, 0)),
                std::sqrt(lm.covariance(1, 1)), std::sqrt(lm.covariance(2, 2)));
}

void correspondence_tooltip(const Snapshot& s, int index, int level) {
  const Correspondence& c = s.correspondences[static_cast<std::size_t>(index)];
  ImGui::Text("correspondence %d: %s", index,
              s.source_landmarks.classes[static_cast<std::size_t>(c.class_index)].name.c_str());
  ImGui::Text("source landmark %d -> target landmark %d, rank score %.2f", c.source, c.target,
              c.score);
  if (s.ground_truth) {
    const double tolerance = s.config.evaluation.max_translation_error;
    ImGui::Text("ground truth residual %.2f m: %s (tolerance %.1f m)",
                ground_truth_residual(c, *s.ground_truth),
                true_inlier(c, *s.ground_truth, tolerance) ? "true inlier" : "outlier", tolerance);
  }
  if (level < 0) return;
  const auto& clique = s.levels[static_cast<std::size_t>(level)].clique;
  const bool member = std::binary_search(clique.begin(), clique.end(), index);
  std::vector<double> trims;
  for (int v : clique) {
    if (v == index) continue;
    const Correspondence& o = s.correspondences[static_cast<std::size_t>(v)];
    trims.push_back(trim_value(s.config.graph.trim, (c.p - o.p).norm(), (c.q - o.q).norm()));
  }
  std::sort(trims.begin(), trims.end());
  ImGui::Text("level %d (eps %.3f): %s the clique", level,
              s.levels[static_cast<std::size_t>(level)].epsilon, member ? "in" : "not in");
  if (!trims.empty())
    ImGui::Text("TRIM (%s) to the %zu clique members: min %.4f, median %.4f, max %.4f",
                to_string(s.config.graph.trim), trims.size(), trims.front(),
                trims[trims.size() / 2], trims.back());
}

}  // namespace

Transform shown_source_pose(const AppState& state, const Snapshot& s) {
  switch (state.view.pose) {
    case PoseShown::ground_truth:
      if (s.ground_truth) return *s.ground_truth;
      break;
    case PoseShown::selected: {
      const int level = shown_level(state.view, s.selected, static_cast<int>(s.levels.size()));
      if (level >= 0 && s.levels[static_cast<std::size_t>(level)].pose.valid)
        return s.levels[static_cast<std::size_t>(level)].pose.T_target_source;
      break;
    }
    case PoseShown::refined:
      if (s.refinement.ran)
        return s.refinement.applied ? s.refinement.T_after : s.refinement.T_before;
      if (s.selected >= 0)
        return s.levels[static_cast<std::size_t>(s.selected)].pose.T_target_source;
      break;
    case PoseShown::identity:
      break;
  }
  return Transform::Identity();
}

void scene_window(UiContext& ui) {
  AppState& state = ui.state;
  const ImVec2 size = ImGui::GetContentRegionAvail();
  const int w = std::max(1, static_cast<int>(size.x)), h = std::max(1, static_cast<int>(size.y));
  const Snapshot* s = ui.snapshot;
  if (!s || !s->target) {
    ImGui::TextDisabled("nothing to show yet");
    return;
  }
  const Transform pose = shown_source_pose(state, *s);
  if (!state.camera_fitted) {
    Eigen::Vector3f lo, hi;
    if (shown_bounds(*s, state.view, pose, lo, hi)) state.camera.fit(lo, hi);
    state.camera_fitted = true;
  }
  ui.scene.update(*s, state.view, pose);
  ui.scene.render(w, h, state.camera, state.view, pose);

  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(ui.scene.texture())),
               ImVec2(static_cast<float>(w), static_cast<float>(h)), ImVec2(0, 1), ImVec2(1, 0));
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(origin, ImVec2(origin.x + w, origin.y + h), true);
  ViewRect rect{origin, static_cast<float>(w), static_cast<float>(h),
                state.camera.projection(static_cast<float>(w) / h) * state.camera.view()};
  if (state.view.grid) draw_grid_axes_scale(dl, rect, state.camera, ui.scene.ground_z(*s));
  const int shown = shown_level(state.view, s->selected, static_cast<int>(s->levels.size()));
  if (s->plan && state.view.layers.plan) {
    draw_floor_plan(dl, rect, *s->plan, 0.0f);
    if (s->scan_columns && state.view.layers.source)
      draw_scan_columns(dl, rect, *s->scan_columns, pose, 0.0f);
  }
  draw_correspondence_lines(dl, rect, *s, state.view, pose, shown, ui.scene.class_colors());
  if (state.view.legend && w >= 360 && h >= 220) {  // a small view keeps its picture
    draw_legend(dl, ImVec2(origin.x + 10, origin.y + 10), *s, state.view, ui.scene.class_colors());
    const float dh = diagnosis_legend_height(*s, state.view);
    if (dh > 0)  // bottom right, clear of the scale bar
      draw_diagnosis_legend(dl, ImVec2(origin.x + w - 196, origin.y + h - dh - 8), *s, state.view,
                            shown);
  }
  dl->PopClipRect();
  if (!hovered) return;

  ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Left))
    state.camera.orbit(io.MouseDelta.x, io.MouseDelta.y);
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) ||
      ImGui::IsMouseDragging(ImGuiMouseButton_Middle))
    state.camera.pan(io.MouseDelta.x, io.MouseDelta.y, static_cast<float>(h));
  if (io.MouseWheel != 0) state.camera.zoom(io.MouseWheel);

  // Hover: the nearest landmark within a few pixels, else the nearest correspondence line.
  const Eigen::Vector2f mouse(io.MousePos.x - origin.x, io.MousePos.y - origin.y);
  const Eigen::Matrix4f vp =
      state.camera.projection(static_cast<float>(w) / h) * state.camera.view();
  float best = kLandmarkPickPx;
  int best_index = -1;
  bool best_source = false;
  if (state.view.layers.landmarks) {
    for (int side = 0; side < 2; ++side) {
      const LandmarkSet& set = side == 0 ? s->source_landmarks : s->target_landmarks;
      for (std::size_t i = 0; i < set.landmarks.size(); ++i) {
        if (set.landmarks[i].kind != LandmarkKind::cluster) continue;
        const Eigen::Vector3f p = side == 0 ? transform_point(pose, set.landmarks[i].centroid)
                                            : set.landmarks[i].centroid.cast<float>();
        Eigen::Vector2f px;
        if (!project_to_screen(vp, p, static_cast<float>(w), static_cast<float>(h), px)) continue;
        const float d = (px - mouse).norm();
        if (d < best) {
          best = d;
          best_index = static_cast<int>(i);
          best_source = side == 0;
        }
      }
    }
  }
  if (best_index >= 0) {
    ImGui::BeginTooltip();
    landmark_tooltip(best_source ? s->source_landmarks : s->target_landmarks, best_index,
                     best_source);
    ImGui::EndTooltip();
    return;
  }
  const int level = shown_level(state.view, s->selected, static_cast<int>(s->levels.size()));
  if (!state.view.layers.correspondences || level < 0) return;
  const auto& clique = s->levels[static_cast<std::size_t>(level)].clique;
  best = kLinePickPx;
  for (std::size_t i = 0; i < s->correspondences.size(); ++i) {
    const bool member = std::binary_search(clique.begin(), clique.end(), static_cast<int>(i));
    if (!member && !state.view.layers.all_correspondences) continue;
    if (!diagnosis_keeps(*s, state.view.diagnosis, i)) continue;
    Eigen::Vector2f a, b;
    const Correspondence& c = s->correspondences[i];
    if (!project_to_screen(vp, transform_point(pose, c.p), static_cast<float>(w),
                           static_cast<float>(h), a) ||
        !project_to_screen(vp, c.q.cast<float>(), static_cast<float>(w), static_cast<float>(h), b))
      continue;
    const float d = segment_distance(mouse, a, b);
    if (d < best) {
      best = d;
      best_index = static_cast<int>(i);
    }
  }
  if (best_index >= 0) {
    int true_neighbours = -1, edges = -1;
    if (state.view.diagnosis.edges_on_hover) {
      dl->PushClipRect(origin, ImVec2(origin.x + w, origin.y + h), true);
      edges = draw_hover_edges(dl, rect, *s, pose, level, best_index, true_neighbours);
      dl->PopClipRect();
    }
    ImGui::BeginTooltip();
    correspondence_tooltip(*s, best_index, level);
    if (edges >= 0)
      ImGui::Text("graph edges at level %d: %d (cyan)%s", level, edges,
                  true_neighbours >= 0
                      ? (", " + std::to_string(true_neighbours) + " to true ones").c_str()
                      : "");
    ImGui::EndTooltip();
  }
}

void status_bar(UiContext& ui) {
  const WorkerStatus& st = ui.status;
  if (st.busy) {
    ImGui::ProgressBar(static_cast<float>(st.fraction), ImVec2(160, 0));
    ImGui::SameLine();
    ImGui::Text("%s ...", st.activity.empty() ? "working" : st.activity.c_str());
  } else if (ui.snapshot) {
    const Snapshot& s = *ui.snapshot;
    std::string ran, times;
    double total = 0;
    for (int i = 0; i < kStageCount; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!s.stage_ran[k]) continue;
      ran += std::string(ran.empty() ? "" : ", ") + stage_name(static_cast<Stage>(i));
      total += s.stage_ms[k];
    }
    ImGui::Text("ready | last run %.0f ms: %s", total,
                ran.empty() ? "nothing to recompute" : ran.c_str());
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      for (int i = 0; i < kStageCount; ++i)
        ImGui::Text("%-18s %8.1f ms%s", stage_name(static_cast<Stage>(i)),
                    s.stage_ms[static_cast<std::size_t>(i)],
                    s.stage_ran[static_cast<std::size_t>(i)] ? "" : " (cached)");
      ImGui::EndTooltip();
    }
  } else {
    ImGui::TextDisabled("no data open");
  }
  ImGui::SameLine();
  ImGui::TextDisabled("| frame %.1f ms", ui.frame_ms);
  if (ui.snapshot && !ui.snapshot->warnings.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "| %zu warnings",
                       ui.snapshot->warnings.size());
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      for (const auto& w : ui.snapshot->warnings) ImGui::TextUnformatted(w.c_str());
      ImGui::EndTooltip();
    }
  }
  const std::string& error =
      !st.error.empty() ? st.error : (ui.state.message_is_error ? ui.state.message : "");
  if (!error.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.35f, 1.0f), "| error: %s", error.c_str());
  } else if (!ui.state.message.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("| %s", ui.state.message.c_str());
  }
}

}  // namespace pagor::studio
