#include "scene/picking.hpp"

#include <cmath>
#include <cstdio>

#include "scene/cloud_colors.hpp"

namespace pagor::studio {
namespace {

bool screen(const ViewRect& r, const Eigen::Vector3f& p, ImVec2& out) {
  Eigen::Vector2f px;
  if (!project_to_screen(r.view_projection, p, r.width, r.height, px)) return false;
  out = ImVec2(r.origin.x + px.x(), r.origin.y + px.y());
  return true;
}

}  // namespace

std::optional<Pick> pick_point(const Snapshot& s, const ViewState& view, const Transform& pose,
                               const ViewRect& r, const Eigen::Vector2f& mouse, float radius_px) {
  float best = radius_px * radius_px;
  std::optional<Pick> out;
  for (const bool source : {false, true}) {
    const PointCloud* cloud = source ? s.source.get() : s.target.get();
    if (!cloud || !(source ? view.layers.source : view.layers.target)) continue;
    const Eigen::Matrix4f mvp =
        source ? Eigen::Matrix4f(r.view_projection * pose.cast<float>()) : r.view_projection;
    for (std::size_t i = 0; i < cloud->size(); ++i) {
      Eigen::Vector2f px;
      if (!project_to_screen(mvp, cloud->points[i], r.width, r.height, px)) continue;
      const float d = (px - mouse).squaredNorm();
      if (d >= best) continue;
      best = d;
      Pick p;
      p.source = source;
      p.index = i;
      p.raw = cloud->points[i];
      out = p;
    }
  }
  if (!out) return out;
  Pick& p = *out;
  const PointCloud& cloud = p.source ? *s.source : *s.target;
  p.at = p.source ? transform_point(pose, p.raw.cast<double>()) : p.raw;
  if (p.index < cloud.labels.size()) {
    p.label = static_cast<long>(semantic_id(cloud.labels[p.index]));
    p.class_name = class_of_label(cloud_scheme(s, p.source), cloud.labels[p.index]);
  }
  p.nearest_target = 0.0f;
  if (p.source && s.target_index && s.target_index->size() > 0)
    p.nearest_target = std::sqrt(s.target_index->nearest(p.at).second);
  return out;
}

std::string pick_text(const Pick& p) {
  char buf[384];
  std::snprintf(buf, sizeof(buf),
                "%s point %zu\nin its cloud (%.3f, %.3f, %.3f) m\nin the target frame (%.3f, "
                "%.3f, %.3f) m",
                p.source ? "source" : "target", p.index, p.raw.x(), p.raw.y(), p.raw.z(), p.at.x(),
                p.at.y(), p.at.z());
  std::string t = buf;
  if (p.label >= 0)
    t += "\nlabel " + std::to_string(p.label) + ": " +
         (p.class_name.empty() ? std::string("no class of the scheme") : p.class_name);
  else
    t += "\nno labels";
  if (p.source) {
    std::snprintf(buf, sizeof(buf), "\nnearest target point %.3f m away (under the shown pose)",
                  p.nearest_target);
    t += buf;
  }
  return t;
}

double pick_distance(const Pick& a, const Pick& b) {
  return (a.at - b.at).cast<double>().norm();
}

void draw_picks(ImDrawList* dl, const ViewRect& r, const std::vector<Pick>& picks) {
  const ImU32 white = IM_COL32(255, 255, 255, 255), black = IM_COL32(0, 0, 0, 220);
  std::vector<ImVec2> at;
  for (std::size_t k = 0; k < picks.size(); ++k) {
    ImVec2 p;
    if (!screen(r, picks[k].at, p)) continue;
    at.push_back(p);
    dl->AddCircle(p, 7.0f, black, 0, 4.0f);
    dl->AddCircle(p, 7.0f, white, 0, 2.0f);
    dl->AddText(ImVec2(p.x + 9, p.y - 18), white, std::to_string(k + 1).c_str());
  }
  if (picks.size() == 2 && at.size() == 2) {
    dl->AddLine(at[0], at[1], black, 4.0f);
    dl->AddLine(at[0], at[1], white, 2.0f);
    char t[64];
    std::snprintf(t, sizeof(t), "%.3f m", pick_distance(picks[0], picks[1]));
    const ImVec2 mid((at[0].x + at[1].x) * 0.5f + 6, (at[0].y + at[1].y) * 0.5f);
    const ImVec2 size = ImGui::CalcTextSize(t);
    dl->AddRectFilled(ImVec2(mid.x - 3, mid.y - 2), ImVec2(mid.x + size.x + 3, mid.y + size.y + 2),
                      black, 3.0f);
    dl->AddText(mid, white, t);
  }
}

}  // namespace pagor::studio
