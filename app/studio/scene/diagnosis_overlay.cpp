#include "scene/diagnosis_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "widgets/number_format.hpp"

namespace pagor::studio {
namespace {

ImU32 col(const Rgba& c, int alpha) {
  return IM_COL32(c[0], c[1], c[2], alpha);
}

bool screen(const ViewRect& r, const Eigen::Vector3f& p, ImVec2& out) {
  Eigen::Vector2f px;
  if (!project_to_screen(r.view_projection, p, r.width, r.height, px)) return false;
  out = ImVec2(r.origin.x + px.x(), r.origin.y + px.y());
  return std::abs(px.x()) < 1e5f && std::abs(px.y()) < 1e5f;
}

bool line_ends(const ViewRect& r, const Correspondence& c, const Transform& pose, ImVec2& a,
               ImVec2& b) {
  return screen(r, transform_point(pose, c.p), a) && screen(r, c.q.cast<float>(), b);
}

// A horizontal colour bar from 0 to `top` [m] with three ticks, each with its unit, and a title.
void colour_bar(ImDrawList* dl, ImVec2& at, const char* title, double top, double mid) {
  const ImU32 text = IM_COL32(230, 230, 230, 255);
  dl->AddText(at, text, title);
  at.y += 17;
  const float w = 170.0f, h = 10.0f;
  const int steps = 34;
  for (int i = 0; i < steps; ++i) {
    const float x0 = at.x + w * static_cast<float>(i) / steps,
                x1 = at.x + w * static_cast<float>(i + 1) / steps;
    dl->AddRectFilled(ImVec2(x0, at.y), ImVec2(x1 + 0.5f, at.y + h),
                      col(diagnosis_colormap((static_cast<float>(i) + 0.5f) / steps), 255));
  }
  const std::string lo = with_unit(0.0, "m"), middle = with_unit(mid, "m"),
                    hi = with_unit(top, "m");
  dl->AddText(ImVec2(at.x, at.y + h + 1), text, lo.c_str());
  dl->AddText(ImVec2(at.x + (w - ImGui::CalcTextSize(middle.c_str()).x) * 0.5f, at.y + h + 1),
              text, middle.c_str());
  dl->AddText(ImVec2(at.x + w - ImGui::CalcTextSize(hi.c_str()).x, at.y + h + 1), text,
              hi.c_str());
  at.y += h + 20;
}

}  // namespace

Rgba diagnosis_colormap(float t) {
  t = std::clamp(std::isfinite(t) ? t : 1.0f, 0.0f, 1.0f);
  const auto mix = [](float a, float b, float u) {
    return static_cast<unsigned char>(std::lround(a + (b - a) * u));
  };
  if (t < 0.5f) {  // green -> yellow
    const float u = t * 2;
    return {mix(40, 245, u), mix(200, 215, u), mix(90, 50, u), 255};
  }
  const float u = (t - 0.5f) * 2;  // yellow -> red
  return {mix(245, 230, u), mix(215, 45, u), mix(50, 45, u), 255};
}

double residual_scale(const Snapshot& s) {
  return s.diagnosis ? 2.0 * s.diagnosis->residual_tolerance
                     : 2.0 * s.config.evaluation.max_translation_error;
}

bool diagnosis_keeps(const Snapshot& s, const DiagnosisView& view, std::size_t i) {
  const Correspondence& c = s.correspondences[i];
  if (!view.class_name.empty() &&
      correspondence_class_name(c, s.source_landmarks) != view.class_name)
    return false;
  if (view.truth == TruthFilter::all || !s.diagnosis) return true;
  return s.diagnosis->is_true(i) == (view.truth == TruthFilter::inliers);
}

ImU32 diagnosis_line_color(const Snapshot& s, const DiagnosisView& view, std::size_t i,
                           ImU32 fallback, int alpha) {
  if (!view.color_by_residual || !s.diagnosis || i >= s.diagnosis->residuals.size())
    return fallback;
  const double t = s.diagnosis->residuals[i] / residual_scale(s);
  return col(diagnosis_colormap(static_cast<float>(t)), alpha);
}

int draw_hover_edges(ImDrawList* dl, const ViewRect& r, const Snapshot& s, const Transform& pose,
                     int level, int index, int& true_neighbours) {
  true_neighbours = s.diagnosis ? 0 : -1;
  if (!s.graph || index < 0 || index >= s.graph->vertices || level < 0) return 0;
  const PyramidGraph& g = *s.graph;
  const auto v = static_cast<std::size_t>(index);
  ImVec2 a, b;
  if (!line_ends(r, s.correspondences[v], pose, a, b)) return 0;
  const ImVec2 mid((a.x + b.x) * 0.5f, (a.y + b.y) * 0.5f);
  const ImU32 cyan = IM_COL32(80, 230, 255, 230), link = IM_COL32(80, 230, 255, 110);
  int drawn = 0;
  for (auto e = g.offsets[v]; e < g.offsets[v + 1]; ++e) {
    const auto k = static_cast<std::size_t>(e);
    if (g.level[k] > level) continue;
    const auto n = static_cast<std::size_t>(g.neighbors[k]);
    ImVec2 c, d;
    if (!line_ends(r, s.correspondences[n], pose, c, d)) continue;
    dl->AddLine(c, d, cyan, 2.0f);
    dl->AddLine(mid, ImVec2((c.x + d.x) * 0.5f, (c.y + d.y) * 0.5f), link, 1.0f);
    ++drawn;
    if (s.diagnosis && s.diagnosis->is_true(n)) ++true_neighbours;
  }
  dl->AddLine(a, b, IM_COL32(0, 0, 0, 220), 6.0f);
  dl->AddLine(a, b, IM_COL32(255, 255, 255, 255), 3.5f);
  return drawn;
}

float diagnosis_legend_height(const Snapshot& s, const ViewState& view) {
  float h = 0;
  if (view.diagnosis.color_by_residual && s.diagnosis) h += 48;
  if (shown_contribution(view) != Contribution::off && s.verification_source) h += 48;
  return h;
}

void draw_diagnosis_legend(ImDrawList* dl, ImVec2 at, const Snapshot& s, const ViewState& view,
                           int level) {
  const float h = diagnosis_legend_height(s, view);
  if (h <= 0) return;
  dl->AddRectFilled(ImVec2(at.x - 4, at.y - 4), ImVec2(at.x + 190, at.y + h),
                    IM_COL32(0, 0, 0, 150), 4.0f);
  char title[64];
  if (view.diagnosis.color_by_residual && s.diagnosis)
    colour_bar(dl, at, "lines: truth residual", residual_scale(s),
               s.diagnosis->residual_tolerance);
  if (shown_contribution(view) != Contribution::off && s.verification_source) {
    const double mu = s.config.verification.mu;
    if (shown_contribution(view) == Contribution::ground_truth)
      std::snprintf(title, sizeof(title), "part of D, truth");
    else if (view.color == ColorMode::residual)
      std::snprintf(title, sizeof(title), "residual min(d, \xce\xbc), L%d", level);
    else
      std::snprintf(title, sizeof(title), "part of D, L%d", level);
    colour_bar(dl, at, title, mu, 0.5 * mu);
  }
}

}  // namespace pagor::studio
