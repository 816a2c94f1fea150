// Data, parameters, view and session panels.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <string>

#include "pagor/errors.hpp"
#include "pagor/kitti.hpp"
#include "panels.hpp"

namespace pagor::studio {
namespace {

void set_message(AppState& s, const std::string& text, bool error) {
  s.message = text;
  s.message_is_error = error;
}

template <class E>
bool enum_combo(const char* label, E& value, std::initializer_list<E> options) {
  bool changed = false;
  if (ImGui::BeginCombo(label, to_string(value))) {
    for (E o : options)
      if (ImGui::Selectable(to_string(o), o == value)) {
        changed = o != value;
        value = o;
      }
    ImGui::EndCombo();
  }
  return changed;
}

bool slider_double(const char* label, double& v, double lo, double hi, const char* fmt,
                   bool log = false) {
  float f = static_cast<float>(v);
  const bool changed = ImGui::SliderFloat(label, &f, static_cast<float>(lo), static_cast<float>(hi),
                                          fmt, log ? ImGuiSliderFlags_Logarithmic : 0);
  if (changed) v = f;
  return changed;
}

void section(const char* title) {
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextDisabled("%s", title);
}

void step_pair(UiContext& ui, int delta) {
  AppState& s = ui.state;
  if (s.pairs.empty()) return;
  s.pair_index = std::clamp(s.pair_index + delta, 0, static_cast<int>(s.pairs.size()) - 1);
  s.data.kind = PairSource::Kind::kitti;
  s.data.source_frame = s.pairs[static_cast<std::size_t>(s.pair_index)].first;
  s.data.target_frame = s.pairs[static_cast<std::size_t>(s.pair_index)].second;
  s.have_data = true;
  s.view.level = -1;
  ui.submit_data();
}

}  // namespace

void data_panel(UiContext& ui) {
  AppState& s = ui.state;
  PairSource& d = s.data;
  int kind = static_cast<int>(d.kind);
  ImGui::RadioButton("KITTI", &kind, static_cast<int>(PairSource::Kind::kitti));
  ImGui::SameLine();
  ImGui::RadioButton("files", &kind, static_cast<int>(PairSource::Kind::files));
  ImGui::SameLine();
  ImGui::RadioButton("synthetic", &kind, static_cast<int>(PairSource::Kind::synthetic));
  d.kind = static_cast<PairSource::Kind>(kind);
  if (d.kind == PairSource::Kind::kitti) {
    ImGui::InputText("root", &d.kitti_root);
    ImGui::InputText("sequence", &d.sequence);
    ImGui::InputInt("source frame", &d.source_frame);
    ImGui::InputInt("target frame", &d.target_frame);
    d.source_frame = std::max(0, d.source_frame);
    d.target_frame = std::max(0, d.target_frame);
    ImGui::InputText("pairs file", &s.pairs_file);
    if (ImGui::Button("read pairs")) {
      try {
        s.pairs = read_pairs_file(resolve_path(s, s.pairs_file));
        s.pair_index = -1;
        set_message(s, "read " + std::to_string(s.pairs.size()) + " pairs", false);
      } catch (const Error& e) {
        set_message(s, e.what(), true);
      }
    }
    if (!s.pairs.empty()) {
      ImGui::SameLine();
      if (ImGui::ArrowButton("##prev", ImGuiDir_Left)) step_pair(ui, s.pair_index < 0 ? 0 : -1);
      ImGui::SameLine();
      if (ImGui::ArrowButton("##next", ImGuiDir_Right)) step_pair(ui, 1);
      ImGui::SameLine();
      ImGui::Text("pair %d / %zu", s.pair_index + 1, s.pairs.size());
    }
  } else if (d.kind == PairSource::Kind::files) {
    ImGui::InputText("source", &d.source);
    ImGui::InputText("source labels", &d.source_labels);
    ImGui::InputText("target", &d.target);
    ImGui::InputText("target labels", &d.target_labels);
  } else {
    int seed = static_cast<int>(d.synthetic_seed);
    if (ImGui::InputInt("seed", &seed))
      d.synthetic_seed = static_cast<std::uint64_t>(std::max(0, seed));
  }
  if (ImGui::Button("Open", ImVec2(-1, 0))) {
    s.have_data = true;
    s.camera_fitted = false;
    s.view.level = -1;
    ui.submit_data();
  }
}

void parameters_panel(UiContext& ui) {
  Config& c = ui.state.config;
  bool changed = false;
  GraphParams& g = c.graph;
  const bool ratio = g.trim == TrimKind::ratio;
  ImGui::TextDisabled("pyramid: %zu levels, TRIM %s", g.thresholds.size(),
                      ratio ? "ratio [-]" : "difference [m]");
  changed |= enum_combo("TRIM", g.trim, {TrimKind::ratio, TrimKind::difference});
  const double lo = ratio ? 0.002 : 0.02, hi = ratio ? 1.0 : 5.0;
  for (std::size_t l = 0; l < g.thresholds.size(); ++l) {
    // Each epsilon stays between its neighbours, so the levels keep increasing.
    const double min = l == 0 ? lo : g.thresholds[l - 1] * 1.01;
    const double max = l + 1 == g.thresholds.size() ? hi : g.thresholds[l + 1] / 1.01;
    const std::string label = "\xce\xb5" + std::to_string(l) + (ratio ? "" : " [m]");
    changed |= slider_double(label.c_str(), g.thresholds[l], min, std::max(min, max), "%.3f", true);
  }
  if (ImGui::Button("+ level") && g.thresholds.size() < 32) {
    g.thresholds.push_back(std::min(hi, g.thresholds.empty() ? lo * 10 : g.thresholds.back() * 2));
    changed = true;
  }
  ImGui::SameLine();
  if (ImGui::Button("- level") && g.thresholds.size() > 1) {
    g.thresholds.pop_back();
    changed = true;
  }
  changed |= enum_combo("affinity", g.affinity, {AffinityKind::binary, AffinityKind::gaussian});
  if (g.affinity == AffinityKind::gaussian)
    changed |= slider_double("\xcf\x83 / \xce\xb5", g.sigma_ratio, 0.05, 2.0, "%.2f");
  changed |= enum_combo("clique solver", c.clique.solver,
                        {CliqueSolver::cascaded, CliqueSolver::independent, CliqueSolver::exact});
  changed |= ImGui::Checkbox("k-core pruning", &c.clique.prune);

  section("pose and verification");
  changed |= enum_combo("pose model", c.gnc.model, {PoseModel::se3, PoseModel::se2});
  changed |= slider_double("GNC bound [m]", c.gnc.noise_bound, 0.05, 5.0, "%.2f m", true);
  changed |= slider_double("\xce\xbc [m]", c.verification.mu, 0.05, 5.0, "%.2f m", true);
  changed |= slider_double("verify voxel [m]", c.verification.voxel_size, 0.1, 2.0, "%.2f m", true);
  changed |= enum_combo("score", c.verification.score,
                        {ScoreKind::truncated, ScoreKind::trimmed, ScoreKind::nearest});

  section("landmarks");
  int cap = c.correspondences.max_correspondences;
  if (ImGui::InputInt("corr. cap", &cap, 100)) {
    c.correspondences.max_correspondences = std::max(0, cap);
    changed = true;
  }
  for (ClassParams& p : c.landmarks.classes) {
    ImGui::PushID(p.name.c_str());
    if (ImGui::TreeNode(p.name.c_str(), "%s (%s)", p.name.c_str(), to_string(p.method))) {
      changed |= slider_double("voxel [m]", p.voxel_size, 0.02, 2.0, "%.2f m", true);
      if (p.method == LandmarkMethod::cluster) {
        changed |= slider_double("tolerance [m]", p.cluster_tolerance, 0.05, 3.0, "%.2f m", true);
        changed |= ImGui::SliderInt("min voxels", &p.min_points, 1, 500);
        changed |= ImGui::SliderInt("max voxels", &p.max_points, p.min_points, 20000, "%d",
                                    ImGuiSliderFlags_Logarithmic);
      } else {
        changed |= slider_double("normal r [m]", p.normal_radius, 0.1, 5.0, "%.2f m", true);
        changed |= slider_double("feature r [m]", p.feature_radius, p.normal_radius * 1.05, 10.0,
                                 "%.2f m", true);
      }
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  section("success criterion");
  changed |=
      slider_double("max t err [m]", c.evaluation.max_translation_error, 0.1, 10.0, "%.1f m");
  changed |= slider_double("max r err [\xc2\xb0]", c.evaluation.max_rotation_error, 0.5, 30.0,
                           "%.1f\xc2\xb0");
  if (ImGui::Button("defaults")) {
    c = default_config();
    changed = true;
  }
  if (changed) ui.submit_config();
}

void view_panel(UiContext& ui) {
  ViewState& v = ui.state.view;
  Layers& l = v.layers;
  ImGui::Checkbox("source", &l.source);
  ImGui::SameLine();
  ImGui::Checkbox("target", &l.target);
  ImGui::SameLine();
  ImGui::Checkbox("landmarks", &l.landmarks);
  ImGui::Checkbox("clique lines", &l.correspondences);
  ImGui::SameLine();
  ImGui::Checkbox("all correspondences", &l.all_correspondences);
  ImGui::SliderFloat("point size [px]", &v.point_size, 1.0f, 8.0f, "%.1f");
  ImGui::SliderFloat("landmark size [px]", &v.landmark_size, 3.0f, 30.0f, "%.0f");
  int color = static_cast<int>(v.color);
  ImGui::Text("colour:");
  ImGui::SameLine();
  ImGui::RadioButton("class", &color, static_cast<int>(ColorMode::by_class));
  ImGui::SameLine();
  ImGui::RadioButton("source/target", &color, static_cast<int>(ColorMode::by_cloud));
  v.color = static_cast<ColorMode>(color);
  int pose = static_cast<int>(v.pose);
  ImGui::Text("source under:");
  ImGui::RadioButton("candidate", &pose, static_cast<int>(PoseShown::selected));
  ImGui::SameLine();
  ImGui::RadioButton("ground truth", &pose, static_cast<int>(PoseShown::ground_truth));
  ImGui::SameLine();
  ImGui::RadioButton("identity", &pose, static_cast<int>(PoseShown::identity));
  v.pose = static_cast<PoseShown>(pose);
  Camera& cam = ui.state.camera;
  if (ImGui::Button("fit")) ui.state.camera_fitted = false;
  ImGui::SameLine();
  if (ImGui::Checkbox("top-down", &cam.top_down)) ui.state.camera_fitted = false;
  ImGui::SameLine();
  ImGui::TextDisabled("drag: orbit, right: pan, wheel: zoom");
}

void session_panel(UiContext& ui) {
  AppState& s = ui.state;
  ImGui::InputText("session", &s.session_path);
  if (ImGui::Button("save session")) {
    try {
      save_session(s, s.session_path);
      set_message(s, "saved " + s.session_path, false);
    } catch (const Error& e) {
      set_message(s, e.what(), true);
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("load session")) {
    try {
      load_session(s.session_path, s);
      set_message(s, "loaded " + s.session_path, false);
      if (s.have_data) ui.submit_data();
    } catch (const Error& e) {
      set_message(s, e.what(), true);
    }
  }
  ImGui::InputText("PNG", &s.screenshot_path);
  if (ImGui::Button("save screenshot")) s.want_screenshot = true;
}

}  // namespace pagor::studio
