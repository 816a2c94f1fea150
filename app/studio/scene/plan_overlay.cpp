#include "scene/plan_overlay.hpp"

#include <cmath>

namespace pagor::studio {
namespace {

constexpr float kWallWidth = 2.0f, kColumnWidth = 2.0f;  // [px]
constexpr float kCrossPx = 4.0f;                         // half the centre cross [px]

bool to_screen(const ViewRect& r, const Eigen::Vector3f& p, ImVec2& out) {
  Eigen::Vector2f px;
  if (!project_to_screen(r.view_projection, p, r.width, r.height, px)) return false;
  out = ImVec2(r.origin.x + px.x(), r.origin.y + px.y());
  return std::abs(px.x()) < 1e5f && std::abs(px.y()) < 1e5f;
}

void segment(ImDrawList* dl, const ViewRect& r, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
             float z, ImU32 color) {
  ImVec2 p, q;
  if (to_screen(r, Eigen::Vector3f(float(a.x()), float(a.y()), z), p) &&
      to_screen(r, Eigen::Vector3f(float(b.x()), float(b.y()), z), q))
    dl->AddLine(p, q, color, kWallWidth);
}

// A circle in the plane z, projected point by point (an ellipse in a tilted view).
void circle(ImDrawList* dl, const ViewRect& r, const Eigen::Vector2d& c, double radius, float z,
            ImU32 color) {
  ImVec2 pts[kPlanCircleSegments];
  for (int i = 0; i < kPlanCircleSegments; ++i) {
    const double a = 2.0 * M_PI * i / kPlanCircleSegments;
    const Eigen::Vector3f p(float(c.x() + radius * std::cos(a)),
                            float(c.y() + radius * std::sin(a)), z);
    if (!to_screen(r, p, pts[i])) return;
  }
  dl->AddPolyline(pts, kPlanCircleSegments, color, ImDrawFlags_Closed, kColumnWidth);
}

}  // namespace

int wall_segment_count(const FloorPlan& plan) {
  int n = 0;
  for (const PlanWall& w : plan.walls) {
    const int k = static_cast<int>(w.points.size());
    n += k < 2 ? 0 : (w.closed && k > 2 ? k : k - 1);
  }
  return n;
}

int draw_floor_plan(ImDrawList* dl, const ViewRect& r, const FloorPlan& plan, float z) {
  int drawn = 0;
  for (const PlanWall& w : plan.walls) {
    const std::size_t k = w.points.size();
    for (std::size_t i = 0; i + 1 < k; ++i, ++drawn)
      segment(dl, r, w.points[i], w.points[i + 1], z, PlanPalette::wall);
    if (w.closed && k > 2) {
      segment(dl, r, w.points[k - 1], w.points[0], z, PlanPalette::wall);
      ++drawn;
    }
  }
  for (const PlanColumn& c : plan.columns) {
    circle(dl, r, c.center, c.radius, z, PlanPalette::column);
    ++drawn;
  }
  return drawn;
}

int draw_scan_columns(ImDrawList* dl, const ViewRect& r, const std::vector<DetectedColumn>& columns,
                      const Transform& T, float z) {
  for (const DetectedColumn& c : columns) {
    const Eigen::Vector3d p =
        T.topLeftCorner<3, 3>() * Eigen::Vector3d(c.center.x(), c.center.y(), 0) +
        T.topRightCorner<3, 1>();
    circle(dl, r, p.head<2>(), c.radius, z, PlanPalette::scan_column);
    ImVec2 s;
    if (!to_screen(r, Eigen::Vector3f(float(p.x()), float(p.y()), z), s)) continue;
    dl->AddLine(ImVec2(s.x - kCrossPx, s.y), ImVec2(s.x + kCrossPx, s.y), PlanPalette::scan_column);
    dl->AddLine(ImVec2(s.x, s.y - kCrossPx), ImVec2(s.x, s.y + kCrossPx), PlanPalette::scan_column);
  }
  return static_cast<int>(columns.size());
}

}  // namespace pagor::studio
