#include "scene/scene_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "scene/diagnosis_overlay.hpp"
#include "scene/plan_overlay.hpp"
#include "widgets/number_format.hpp"

namespace pagor::studio {
namespace {

ImU32 col(const Rgba& c, int alpha = -1) {
  return IM_COL32(c[0], c[1], c[2], alpha < 0 ? c[3] : alpha);
}

bool to_screen(const ViewRect& r, const Eigen::Vector3f& p, ImVec2& out) {
  Eigen::Vector2f px;
  if (!project_to_screen(r.view_projection, p, r.width, r.height, px)) return false;
  out = ImVec2(r.origin.x + px.x(), r.origin.y + px.y());
  return std::abs(px.x()) < 1e5f && std::abs(px.y()) < 1e5f;
}

// A world segment, cut into pieces so that the parts in front of the camera still show.
void world_line(ImDrawList* dl, const ViewRect& r, const Eigen::Vector3f& a,
                const Eigen::Vector3f& b, ImU32 color, float width, int pieces = 8) {
  for (int i = 0; i < pieces; ++i) {
    ImVec2 p, q;
    const Eigen::Vector3f u = a + (b - a) * (static_cast<float>(i) / pieces);
    const Eigen::Vector3f v = a + (b - a) * (static_cast<float>(i + 1) / pieces);
    if (to_screen(r, u, p) && to_screen(r, v, q)) dl->AddLine(p, q, color, width);
  }
}

void extend(Eigen::Vector3f& lo, Eigen::Vector3f& hi, const Eigen::Vector3f& p) {
  lo = lo.cwiseMin(p);
  hi = hi.cwiseMax(p);
}

// The central 96 % of a cloud under a transform (LiDAR scans have far, sparse outliers).
void cloud_box(const PointCloud& cloud, const Transform& T, Eigen::Vector3f& lo,
               Eigen::Vector3f& hi) {
  if (cloud.points.empty()) return;
  const std::size_t stride = std::max<std::size_t>(1, cloud.points.size() / 20000);
  std::vector<float> axis[3];
  for (std::size_t i = 0; i < cloud.points.size(); i += stride) {
    const Eigen::Vector3f p = transform_point(T, cloud.points[i].cast<double>());
    for (int k = 0; k < 3; ++k) axis[k].push_back(p[k]);
  }
  for (int k = 0; k < 3; ++k) {
    auto& v = axis[k];
    const auto at = [&v](double q) {
      const auto i = static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
      std::nth_element(v.begin(), v.begin() + i, v.end());
      return v[static_cast<std::size_t>(i)];
    };
    lo[k] = std::min(lo[k], at(0.02));
    hi[k] = std::max(hi[k], at(0.98));
  }
}

void legend_item(ImDrawList* dl, ImVec2& at, ImU32 c, const char* text, bool line) {
  if (line)
    dl->AddLine(ImVec2(at.x, at.y + 7), ImVec2(at.x + 16, at.y + 7), c, 3.0f);
  else
    dl->AddCircleFilled(ImVec2(at.x + 8, at.y + 7), 5.0f, c);
  dl->AddText(ImVec2(at.x + 22, at.y), IM_COL32(230, 230, 230, 255), text);
  at.y += 17;
}

}  // namespace

float nice_length(float x) {
  if (!(x > 0) || !std::isfinite(x)) return 1.0f;
  const float p = std::pow(10.0f, std::floor(std::log10(x)));
  const float m = x / p;
  return (m < 1.5f ? 1.0f : m < 3.5f ? 2.0f : m < 7.5f ? 5.0f : 10.0f) * p;
}

float metres_per_pixel(const Camera& camera, float height) {
  return 2.0f * camera.distance * std::tan(camera.fov_deg * 0.5f * 3.14159265f / 180.0f) /
         std::max(height, 1.0f);
}

bool shown_bounds(const Snapshot& s, const ViewState& view, const Transform& pose,
                  Eigen::Vector3f& lo, Eigen::Vector3f& hi) {
  lo = Eigen::Vector3f::Constant(HUGE_VALF);
  hi = Eigen::Vector3f::Constant(-HUGE_VALF);
  if (view.layers.target && s.target) cloud_box(*s.target, Transform::Identity(), lo, hi);
  if (view.layers.source && s.source) cloud_box(*s.source, pose, lo, hi);
  if (view.layers.landmarks) {
    for (const auto& lm : s.target_landmarks.landmarks)
      if (lm.kind == LandmarkKind::cluster) extend(lo, hi, lm.centroid.cast<float>());
    for (const auto& lm : s.source_landmarks.landmarks)
      if (lm.kind == LandmarkKind::cluster) extend(lo, hi, transform_point(pose, lm.centroid));
    for (const Correspondence& c : s.correspondences)  // a matcher's points p and q
      if (c.origin == CorrespondenceOrigin::matcher) {
        extend(lo, hi, transform_point(pose, c.p));
        extend(lo, hi, c.q.cast<float>());
      }
  }
  if (view.layers.plan && s.plan)
    for (const PlanWall& w : s.plan->walls)
      for (const Eigen::Vector2d& p : w.points)
        extend(lo, hi, Eigen::Vector3f(float(p.x()), float(p.y()), 0.0f));
  if (view.layers.correspondences) {
    const int level = shown_level(view, s.selected, static_cast<int>(s.levels.size()));
    if (level >= 0)
      for (int i : s.levels[static_cast<std::size_t>(level)].clique) {
        const Correspondence& c = s.correspondences[static_cast<std::size_t>(i)];
        extend(lo, hi, transform_point(pose, c.p));
        extend(lo, hi, c.q.cast<float>());
      }
  }
  if (!(lo.array() <= hi.array()).all()) {
    // Nothing shown: the target cloud, so that the camera still has something to look at.
    if (!s.target || s.target->points.empty()) return false;
    cloud_box(*s.target, Transform::Identity(), lo, hi);
  }
  return (lo.array() <= hi.array()).all();
}

void draw_grid_axes_scale(ImDrawList* dl, const ViewRect& r, const Camera& camera, float ground_z) {
  const float step = nice_length(camera.distance / 6.0f);
  const int half = 12;
  const float cx = std::round(camera.target.x() / step) * step,
              cy = std::round(camera.target.y() / step) * step;
  const ImU32 grid = IM_COL32(150, 150, 160, 60);
  for (int i = -half; i <= half; ++i) {
    const float x = cx + i * step, y = cy + i * step, e = half * step;
    world_line(dl, r, {x, cy - e, ground_z}, {x, cy + e, ground_z}, grid, 1.0f);
    world_line(dl, r, {cx - e, y, ground_z}, {cx + e, y, ground_z}, grid, 1.0f);
  }
  // Axes at the target frame's origin (the target sensor), one grid step long: thin, light and
  // lettered, so that they are never taken for correspondence lines (green / red).
  const Eigen::Vector3f o(0, 0, 0);
  const ImU32 axis = col(Palette::axis);
  const char* names[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3f tip = o;
    tip[k] = step;
    world_line(dl, r, o, tip, axis, 1.5f, 1);
    ImVec2 p;
    if (to_screen(r, tip, p)) {
      dl->AddCircleFilled(p, 3.0f, axis);
      dl->AddText(ImVec2(p.x + 4, p.y - 8), axis, names[k]);
    }
  }
  // Scale bar, bottom left: true at the camera target's depth.
  const float mpp = metres_per_pixel(camera, r.height);
  const float metres = nice_length(120.0f * mpp), px = metres / mpp;
  const ImVec2 a(r.origin.x + 14, r.origin.y + r.height - 16), b(a.x + px, a.y);
  dl->AddRectFilled(ImVec2(a.x - 6, a.y - 22), ImVec2(b.x + 8, a.y + 8), IM_COL32(0, 0, 0, 140),
                    3.0f);
  dl->AddLine(a, b, IM_COL32(240, 240, 240, 255), 3.0f);
  dl->AddLine(ImVec2(a.x, a.y - 5), ImVec2(a.x, a.y + 5), IM_COL32(240, 240, 240, 255), 2.0f);
  dl->AddLine(ImVec2(b.x, b.y - 5), ImVec2(b.x, b.y + 5), IM_COL32(240, 240, 240, 255), 2.0f);
  char text[96];
  std::snprintf(text, sizeof(text), "%g m%s, grid %g m", metres,
                camera.top_down ? "" : " at the centre", step);
  dl->AddText(ImVec2(a.x, a.y - 20), IM_COL32(240, 240, 240, 255), text);
}

int draw_correspondence_lines(ImDrawList* dl, const ViewRect& r, const Snapshot& s,
                              const ViewState& view, const Transform& pose, int level,
                              const ClassColors& colors) {
  if (!view.layers.correspondences || level < 0) return 0;
  const auto& clique = s.levels[static_cast<std::size_t>(level)].clique;
  std::vector<char> in_clique(s.correspondences.size(), 0);
  for (int v : clique) in_clique[static_cast<std::size_t>(v)] = 1;
  int drawn = 0;
  // A clique member (`member`) is outlined and marked at both ends: a dot at the source point, a
  // ring at the target point, so that one of zero length (a right pose puts p on q) still shows.
  const auto line = [&](const Correspondence& c, ImU32 color, float width, bool member) {
    ImVec2 a, b;
    if (!to_screen(r, transform_point(pose, c.p), a) || !to_screen(r, c.q.cast<float>(), b)) return;
    if (member) dl->AddLine(a, b, IM_COL32(0, 0, 0, 200), width + 2.0f);
    dl->AddLine(a, b, color, width);
    if (member) {
      const float ring = std::max(3.5f, width * 1.8f);
      dl->AddCircle(b, ring + 1.0f, IM_COL32(0, 0, 0, 200), 16, 3.0f);
      dl->AddCircle(b, ring, color, 16, 1.5f);
      dl->AddCircleFilled(a, std::max(1.5f, width * 0.8f), color, 8);
    }
    ++drawn;
  };
  const DiagnosisView& dv = view.diagnosis;
  if (view.layers.all_correspondences)
    for (std::size_t i = 0; i < s.correspondences.size(); ++i) {
      if (in_clique[i] || !diagnosis_keeps(s, dv, i)) continue;
      const Correspondence& c = s.correspondences[i];
      const std::string name = correspondence_class_name(c, s.source_landmarks);
      line(c, diagnosis_line_color(s, dv, i, col(colors.of(name), 70), 110),
           std::max(1.0f, view.line_width * 0.4f), false);
    }
  const double tolerance = s.config.evaluation.max_translation_error;
  for (int v : clique) {
    const auto i = static_cast<std::size_t>(v);
    if (!diagnosis_keeps(s, dv, i)) continue;
    const Correspondence& c = s.correspondences[i];
    const bool outlier = s.ground_truth && !true_inlier(c, *s.ground_truth, tolerance);
    line(c,
         diagnosis_line_color(s, dv, i, col(outlier ? Palette::clique_outlier : Palette::clique)),
         view.line_width, true);
  }
  return drawn;
}

namespace {

constexpr std::size_t kLegendClasses = 12;  // class entries at most; the rest are counted

// The point entries of the legend for the clouds: what they are drawn in.
std::vector<std::pair<ImU32, std::string>> cloud_entries(const Snapshot& s, const ViewState& view,
                                                         const ClassColors& colors,
                                                         const std::vector<DrawnClass>& drawn) {
  std::vector<std::pair<ImU32, std::string>> points;
  if (view.color == ColorMode::by_cloud)
    return {{col(Palette::source), "source"}, {col(Palette::target), "target"}};
  if (view.color == ColorMode::residual) return {{col(Palette::plain), "target"}};
  if (view.color != ColorMode::by_class) return points;  // a colour bar instead
  std::size_t more = 0;
  for (const DrawnClass& c : drawn) {
    if (points.size() >= kLegendClasses) {
      ++more;
      continue;
    }
    points.push_back({col(c.color), c.name.empty() ? "labels of no class of the scheme" : c.name});
  }
  // Classes that made landmarks but colour no point: the class-agnostic `structure` keypoints,
  // or every landmark class of unlabelled clouds.
  for (const auto& c : s.source_landmarks.classes)
    if (c.landmarks > 0 && std::none_of(drawn.begin(), drawn.end(),
                                        [&](const DrawnClass& d) { return d.name == c.name; }))
      points.push_back({col(colors.of(c.name)), c.name + " (landmarks only)"});
  if (drawn.empty() && (s.source || s.target))
    points.push_back({IM_COL32(120, 120, 120, 255), "unlabelled points"});
  if (more) points.push_back({IM_COL32(0, 0, 0, 0), "+ " + std::to_string(more) + " more classes"});
  return points;
}

}  // namespace

std::vector<std::pair<ImU32, std::string>> point_entries(const Snapshot& s, const ViewState& view,
                                                         const ClassColors& colors,
                                                         const std::vector<DrawnClass>& drawn) {
  auto points = cloud_entries(s, view, colors, drawn);
  // A matcher's points p and q are drawn in the source and target colours whatever the colouring.
  const bool matcher =
      std::any_of(s.correspondences.begin(), s.correspondences.end(),
                  [](const Correspondence& c) { return c.origin == CorrespondenceOrigin::matcher; });
  if (matcher && view.layers.landmarks && view.color != ColorMode::by_cloud) {
    points.push_back({col(Palette::source), "matcher's source points p"});
    points.push_back({col(Palette::target), "matcher's target points q"});
  }
  return points;
}

namespace {

// A horizontal viridis bar from scale.lo to scale.hi with its title.
void scale_bar(ImDrawList* dl, ImVec2& at, const ColorScale& scale) {
  const ImU32 text = IM_COL32(230, 230, 230, 255);
  if (!scale.valid) {
    dl->AddText(at, text, "no intensities in these clouds: grey");
    at.y += 17;
    return;
  }
  dl->AddText(at, text, scale.title.c_str());
  at.y += 17;
  const float w = 170.0f, h = 10.0f;
  const int steps = 34;
  for (int i = 0; i < steps; ++i)
    dl->AddRectFilled(ImVec2(at.x + w * i / steps, at.y),
                      ImVec2(at.x + w * (i + 1) / steps + 0.5f, at.y + h),
                      col(scale_color((i + 0.5) / steps)));
  const std::string lo = with_unit(scale.lo, scale.unit), hi = with_unit(scale.hi, scale.unit);
  dl->AddText(ImVec2(at.x, at.y + h + 1), text, lo.c_str());
  dl->AddText(ImVec2(at.x + w - ImGui::CalcTextSize(hi.c_str()).x, at.y + h + 1), text,
              hi.c_str());
  at.y += h + 20;
}

}  // namespace

void draw_legend(ImDrawList* dl, ImVec2 at, const Snapshot& s, const ViewState& view,
                 const ClassColors& colors, const std::vector<DrawnClass>& drawn,
                 const ColorScale& scale) {
  const bool gt = s.ground_truth.has_value();
  const auto points = point_entries(s, view, colors, drawn);
  const bool bar = view.color == ColorMode::height || view.color == ColorMode::intensity;
  const bool by_residual = view.diagnosis.color_by_residual && s.diagnosis;  // its own legend
  const bool plan = s.plan && view.layers.plan;
  const int lines = (by_residual ? 0 : 1 + (gt ? 1 : 0)) +
                    (view.layers.all_correspondences ? 1 : 0) + (plan ? 3 : 0);
  const float h = 17.0f * static_cast<float>(lines + points.size()) + (bar ? 48.0f : 0.0f) + 4.0f;
  dl->AddRectFilled(ImVec2(at.x - 4, at.y - 4), ImVec2(at.x + 200, at.y + h),
                    IM_COL32(0, 0, 0, 150), 4.0f);
  if (!by_residual) {
    legend_item(dl, at, col(Palette::clique), gt ? "clique, true inlier" : "clique", true);
    if (gt) legend_item(dl, at, col(Palette::clique_outlier), "clique, outlier (truth)", true);
  }
  if (view.layers.all_correspondences)
    legend_item(dl, at, IM_COL32(200, 200, 200, 160), "other corr. (class)", true);
  if (plan) {
    legend_item(dl, at, PlanPalette::wall, "plan: walls", true);
    legend_item(dl, at, PlanPalette::column, "plan: columns", true);
    legend_item(dl, at, PlanPalette::scan_column, "scan: columns found", true);
  }
  if (bar) scale_bar(dl, at, scale);
  for (const auto& [c, name] : points) legend_item(dl, at, c, name.c_str(), false);
}

}  // namespace pagor::studio
