// The 3D view window: the scene image, camera input, hover tooltips and a legend.

#include "scene/scene_window.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "pagor/graph/trim.hpp"
#include "render/imgui_renderer.hpp"
#include "scene/diagnosis_overlay.hpp"
#include "scene/picking.hpp"
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
              correspondence_class_name(c, s.source_landmarks).c_str());
  if (c.origin == CorrespondenceOrigin::matcher)
    ImGui::Text("matcher's keypoint %d -> %d, weight %.2f; p (%.2f, %.2f, %.2f) -> q (%.2f, "
                "%.2f, %.2f) m",
                c.source, c.target, c.score, c.p.x(), c.p.y(), c.p.z(), c.q.x(), c.q.y(), c.q.z());
  else
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

// The cluster landmark nearest to `mouse` (pixels in `r`) within a few pixels, or -1; `source`
// says on which side.
int nearest_landmark(const Snapshot& s, const Transform& pose, const ViewRect& r,
                     const Eigen::Vector2f& mouse, bool& source) {
  float best = kLandmarkPickPx;
  int best_index = -1;
  for (int side = 0; side < 2; ++side) {
    const LandmarkSet& set = side == 0 ? s.source_landmarks : s.target_landmarks;
    for (std::size_t i = 0; i < set.landmarks.size(); ++i) {
      if (set.landmarks[i].kind != LandmarkKind::cluster) continue;
      const Eigen::Vector3f p = side == 0 ? transform_point(pose, set.landmarks[i].centroid)
                                          : set.landmarks[i].centroid.cast<float>();
      Eigen::Vector2f px;
      if (!project_to_screen(r.view_projection, p, r.width, r.height, px)) continue;
      const float d = (px - mouse).norm();
      if (d < best) {
        best = d;
        best_index = static_cast<int>(i);
        source = side == 0;
      }
    }
  }
  return best_index;
}

// The shown correspondence line nearest to `mouse` within a few pixels at `level`, or -1.
int nearest_line(const Snapshot& s, const ViewState& view, const Transform& pose, const ViewRect& r,
                 const Eigen::Vector2f& mouse, int level) {
  const auto& clique = s.levels[static_cast<std::size_t>(level)].clique;
  float best = kLinePickPx;
  int best_index = -1;
  for (std::size_t i = 0; i < s.correspondences.size(); ++i) {
    const bool member = std::binary_search(clique.begin(), clique.end(), static_cast<int>(i));
    if (!member && !view.layers.all_correspondences) continue;
    if (!diagnosis_keeps(s, view.diagnosis, i)) continue;
    Eigen::Vector2f a, b;
    const Correspondence& c = s.correspondences[i];
    if (!project_to_screen(r.view_projection, transform_point(pose, c.p), r.width, r.height, a) ||
        !project_to_screen(r.view_projection, c.q.cast<float>(), r.width, r.height, b))
      continue;
    const float d = segment_distance(mouse, a, b);
    if (d < best) {
      best = d;
      best_index = static_cast<int>(i);
    }
  }
  return best_index;
}

}  // namespace

void CameraControl::reset() const {
  const bool top_down = camera.top_down;
  camera = Camera{};
  camera.top_down = top_down;
  fitted = false;
}

Transform shown_source_pose(const ViewState& view, const Snapshot& s) {
  switch (view.pose) {
    case PoseShown::ground_truth:
      if (s.ground_truth) return *s.ground_truth;
      break;
    case PoseShown::selected: {
      const int level = shown_level(view, s.selected, static_cast<int>(s.levels.size()));
      if (level >= 0 && s.levels[static_cast<std::size_t>(level)].pose.valid)
        return s.levels[static_cast<std::size_t>(level)].pose.T_target_source;
      break;
    }
    case PoseShown::refined:
      if (s.acceptance.adopted.applied) return s.acceptance.adopted.T_target_source;
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

namespace {

constexpr float kPointPickPx = 8.0f;

// The picks' facts, top right of the view.
void pick_box(ImDrawList* dl, ImVec2 origin, float w, const std::vector<Pick>& picks) {
  std::string text;
  for (std::size_t k = 0; k < picks.size(); ++k)
    text += (k ? "\n\n" : "") + std::to_string(k + 1) + ": " + pick_text(picks[k]);
  if (picks.size() == 2) {
    char buf[96];
    std::snprintf(buf, sizeof(buf), "\n\n1 to 2: %.3f m", pick_distance(picks[0], picks[1]));
    text += buf;
  }
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const ImVec2 at(origin.x + w - size.x - 14, origin.y + 10);
  dl->AddRectFilled(ImVec2(at.x - 5, at.y - 4), ImVec2(at.x + size.x + 5, at.y + size.y + 4),
                    IM_COL32(0, 0, 0, 170), 4.0f);
  dl->AddText(at, IM_COL32(240, 240, 240, 255), text.c_str());
}

// A click (pressed and released without a drag) picks; Shift keeps the first pick to measure.
void handle_pick(const Snapshot& s, const ViewState& view, const Transform& pose, const ViewRect& r,
                 const Eigen::Vector2f& mouse, std::vector<Pick>& picks) {
  const ImGuiIO& io = ImGui::GetIO();
  // Shift as it was when the button went down (it is often let go with the button).
  static bool shift_at_press = false;
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) shift_at_press = io.KeyShift;
  if (!ImGui::IsMouseReleased(ImGuiMouseButton_Left) || io.MouseDragMaxDistanceSqr[0] > 16.0f)
    return;
  const std::optional<Pick> p = pick_point(s, view, pose, r, mouse, kPointPickPx);
  if (!p) {
    picks.clear();
    return;
  }
  if (!(shift_at_press || io.KeyShift) || picks.size() >= 2) picks.clear();
  picks.push_back(*p);
}

}  // namespace

void scene_window(SceneView& scene, const Snapshot* s, const ViewState& view,
                  CameraControl camera_control, std::vector<Pick>& picks) {
  Camera& camera = camera_control.camera;
  const ImVec2 size = ImGui::GetContentRegionAvail();
  const int w = std::max(1, static_cast<int>(size.x)), h = std::max(1, static_cast<int>(size.y));
  if (!s || (!s->target && s->correspondences.empty())) {  // a matcher's alone: p, q and lines
    ImGui::TextDisabled("nothing to show yet");
    return;
  }
  const Transform pose = shown_source_pose(view, *s);
  if (!camera_control.fitted && s->request >= camera_control.fit_request) {
    Eigen::Vector3f lo, hi;
    if (shown_bounds(*s, view, pose, lo, hi)) camera.fit(lo, hi, float(w) / float(h));
    camera_control.fitted = true;
  }
  scene.update(*s, view, pose);
  scene.render(w, h, camera, view, pose);

  const ImVec2 origin = ImGui::GetCursorScreenPos();
  // The picture is opaque: drawn without blending. While the camera moves it may fill only a
  // share of the texture (drawn at a lower resolution), shown stretched over the view.
  const Eigen::Vector2f share = scene.texture_share();
  ImGui::GetWindowDrawList()->AddCallback(kOpaqueBegin, nullptr);
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(scene.texture())),
               ImVec2(static_cast<float>(w), static_cast<float>(h)), ImVec2(0, share.y()),
               ImVec2(share.x(), 0));
  ImGui::GetWindowDrawList()->AddCallback(kOpaqueEnd, nullptr);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(origin, ImVec2(origin.x + w, origin.y + h), true);
  ViewRect rect{origin, static_cast<float>(w), static_cast<float>(h),
                camera.projection(static_cast<float>(w) / h) * camera.view()};
  if (view.grid) draw_grid_axes_scale(dl, rect, camera, scene.ground_z(*s));
  const int shown = shown_level(view, s->selected, static_cast<int>(s->levels.size()));
  if (s->plan && view.layers.plan) {
    draw_floor_plan(dl, rect, *s->plan, 0.0f);
    if (s->scan_columns && view.layers.source)
      draw_scan_columns(dl, rect, *s->scan_columns, pose, 0.0f);
  }
  draw_correspondence_lines(dl, rect, *s, view, pose, shown, scene.class_colors());
  if (view.legend && w >= 360 && h >= 220) {  // a small view keeps its picture
    draw_legend(dl, ImVec2(origin.x + 10, origin.y + 10), *s, view, scene.class_colors(),
                scene.drawn_classes(), scene.color_scale());
    const float dh = diagnosis_legend_height(*s, view);
    if (dh > 0)  // bottom right, clear of the scale bar
      draw_diagnosis_legend(dl, ImVec2(origin.x + w - 196, origin.y + h - dh - 8), *s, view, shown);
  }
  draw_picks(dl, rect, picks);
  if (!picks.empty()) pick_box(dl, origin, static_cast<float>(w), picks);
  dl->PopClipRect();
  if (!hovered) return;

  ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) camera.orbit(io.MouseDelta.x, io.MouseDelta.y);
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) ||
      ImGui::IsMouseDragging(ImGuiMouseButton_Middle))
    camera.pan(io.MouseDelta.x, io.MouseDelta.y, static_cast<float>(h));
  if (io.MouseWheel != 0) camera.zoom(io.MouseWheel);

  // Hover: the nearest landmark within a few pixels, else the nearest correspondence line.
  const Eigen::Vector2f mouse(io.MousePos.x - origin.x, io.MousePos.y - origin.y);
  // The camera as moved by this frame's input.
  const ViewRect now{origin, static_cast<float>(w), static_cast<float>(h),
                     camera.projection(static_cast<float>(w) / h) * camera.view()};
  handle_pick(*s, view, pose, now, mouse, picks);
  bool best_source = false;
  int best_index = view.layers.landmarks ? nearest_landmark(*s, pose, now, mouse, best_source) : -1;
  if (best_index >= 0) {
    ImGui::BeginTooltip();
    landmark_tooltip(best_source ? s->source_landmarks : s->target_landmarks, best_index,
                     best_source);
    ImGui::EndTooltip();
    return;
  }
  const int level = shown_level(view, s->selected, static_cast<int>(s->levels.size()));
  if (!view.layers.correspondences || level < 0) return;
  best_index = nearest_line(*s, view, pose, now, mouse, level);
  if (best_index >= 0) {
    int true_neighbours = -1, edges = -1;
    if (view.diagnosis.edges_on_hover) {
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

}  // namespace pagor::studio
