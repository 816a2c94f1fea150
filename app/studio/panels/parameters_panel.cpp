// The Parameters panel: every parameter of the configuration, section by section, as the
// config's own structs hold them; a change re-runs the pipeline (cached stages are reused).

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "panels/panels.hpp"
#include "widgets/number_format.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

constexpr std::size_t kMaxLevels = 32;
constexpr int kMaxCap = 5000;  // correspondences: ~2 s for the graph and clique stages
const ImVec4 kRed(1.0f, 0.4f, 0.4f, 1.0f);

void section(const char* title) {
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextDisabled("%s", title);
}

// Keeps the levels strictly increasing inside the fixed range: sorts, clamps and drops equal
// neighbours (saying so). True when something had to change.
bool normalise_levels(GraphParams& g, StudioActions& actions) {
  auto& th = g.thresholds;
  const auto [lo, hi] = epsilon_range(g.trim);
  const std::vector<double> before = th;
  for (double& e : th) e = std::clamp(e, lo, hi);
  if (th != before)
    actions.notify(Message::info("\xce\xb5 clamped into [" + std::to_string(lo) + ", " +
                                 std::to_string(hi) + "], the range of TRIM '" + to_string(g.trim) +
                                 "'"));
  std::sort(th.begin(), th.end());
  th.erase(std::unique(th.begin(), th.end()), th.end());
  if (th.size() < before.size())
    actions.notify(Message::info("two levels had the same \xce\xb5; kept one"));
  return th != before;
}

// The built-in label schemes that name every configured landmark class (others would make the
// configuration invalid). Returns whether the scheme changed.
bool label_scheme_combo(Config& c) {
  bool changed = false;
  if (ui::begin_combo(
          "labels", c.label_scheme.name.c_str(),
          "Numbering of the clouds' labels: auto (detected per cloud), none (labels not used), "
          "raw SemanticKITTI ids, the 0-based training numbering, or the learning map that "
          "segmentation networks output.")) {
    for (const std::string& name : builtin_label_scheme_names()) {
      const LabelScheme scheme = builtin_label_scheme(name);
      const bool fits = std::all_of(c.landmarks.classes.begin(), c.landmarks.classes.end(),
                                    [&](const ClassParams& p) { return scheme.find(p.name) >= 0; });
      if (!fits) continue;
      if (ui::selectable(name.c_str(), name == c.label_scheme.name) &&
          name != c.label_scheme.name) {
        c.label_scheme = scheme;
        changed = true;
      }
    }
    ui::end_combo();
  }
  return changed;
}

// One row per level: its epsilon slider, insert and delete, drawn for the TRIM kind `trim` (the
// one at the start of the frame). True when a level changed.
bool level_rows(GraphParams& g, TrimKind trim, StudioActions& actions) {
  bool changed = false;
  const bool ratio = trim == TrimKind::ratio;
  const auto [lo, hi] = epsilon_range(trim);
  for (std::size_t l = 0; l < g.thresholds.size(); ++l) {
    ImGui::PushID(static_cast<int>(l));
    const std::string label = "\xce\xb5" + std::to_string(l) + (ratio ? "" : " [m]");
    ImGui::PushItemWidth(ImGui::CalcItemWidth() - 2 * (ImGui::GetFrameHeight() + 4));
    changed |= ui::slider_double(label.c_str(), &g.thresholds[l], lo, hi, "%.4g", true,
                                 "Consistency threshold of this pyramid level: two "
                                 "correspondences agree when their TRIM value is below it. The "
                                 "scale is fixed and logarithmic; levels are kept sorted.");
    const bool released = ImGui::IsItemDeactivatedAfterEdit();
    ImGui::PopItemWidth();
    ImGui::SameLine();
    const bool can_insert =
        g.thresholds.size() < kMaxLevels && (l == 0 ? g.thresholds[0] > lo : true);
    ImGui::BeginDisabled(!can_insert);
    if (ui::small_button("+", "Inserts a level below this one (between it and the one before).")) {
      const double v = l == 0 ? std::max(lo, g.thresholds[0] * 0.5)
                              : std::sqrt(g.thresholds[l - 1] * g.thresholds[l]);
      g.thresholds.insert(g.thresholds.begin() + static_cast<std::ptrdiff_t>(l),
                          shortest(static_cast<float>(v)));
      changed = true;
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(g.thresholds.size() <= 1);
    if (ui::small_button("x", "Deletes this level.")) {
      g.thresholds.erase(g.thresholds.begin() + static_cast<std::ptrdiff_t>(l));
      changed = true;
    }
    ImGui::EndDisabled();
    ImGui::PopID();
    if (released && normalise_levels(g, actions)) changed = true;
    if (l >= g.thresholds.size()) break;
  }
  return changed;
}

// The label scheme, the pyramid's levels, TRIM, affinity and the clique solver.
bool graph_section(Config& c, StudioActions& actions) {
  GraphParams& g = c.graph;
  const TrimKind trim = g.trim;
  const auto [lo, hi] = epsilon_range(trim);
  bool changed = label_scheme_combo(c);
  ImGui::TextDisabled("%zu levels, \xce\xb5 in [%g, %g]%s", g.thresholds.size(), lo, hi,
                      trim == TrimKind::ratio ? "" : " m");
  ImGui::SameLine();
  ImGui::BeginDisabled(g.thresholds.size() >= kMaxLevels || g.thresholds.back() >= hi);
  if (ui::small_button("+ level at end", "Appends a level with twice the largest \xce\xb5.")) {
    g.thresholds.push_back(std::min(hi, shortest(static_cast<float>(g.thresholds.back() * 2))));
    changed = true;
  }
  ImGui::EndDisabled();
  if (ui::enum_combo("TRIM", g.trim,
                     "How two correspondences are compared: 'ratio' of their lengths (outdoor, "
                     "unitless) or 'difference' of lengths in metres (indoor).")) {
    normalise_levels(g, actions);
    changed = true;
  }
  changed |= level_rows(g, trim, actions);
  if (!ImGui::IsAnyItemActive() && normalise_levels(g, actions)) changed = true;
  changed |= ui::enum_combo("affinity", g.affinity,
                            "Edge weights of the consistency graph: 1 for every consistent pair "
                            "('binary') or a Gaussian of the TRIM value ('gaussian').");
  if (g.affinity == AffinityKind::gaussian)
    changed |= ui::slider_double("\xcf\x83 / \xce\xb5", &g.sigma_ratio, 0.05, 2.0, "%.2f", false,
                                 "Width of the Gaussian weight as a fraction of the level's "
                                 "\xce\xb5.");
  changed |= ui::enum_combo("clique solver", c.clique.solver,
                            "Densest clique per level: CLIPPER relaxation warm-started from the "
                            "previous level ('cascaded'), from scratch ('independent'), or exact "
                            "branch and bound ('exact', small graphs).");
  changed |= ui::checkbox("k-core pruning", &c.clique.prune,
                          "Runs the relaxation only on the k-core that can hold a clique as "
                          "large as a greedy one; never returns less than the greedy clique.");
  return changed;
}

bool pose_section(Config& c) {
  bool changed = false;
  section("pose and verification");
  changed |= ui::enum_combo("pose model", c.gnc.model,
                            "Degrees of freedom of the estimated pose (e.g. full SE(3), or SE(2) "
                            "for planar robots).");
  changed |= ui::slider_double("GNC bound [m]", &c.gnc.noise_bound, 0.05, 5.0, "%.2f m", true,
                               "Truncation of the TLS cost in GNC: residuals beyond this are "
                               "treated as outliers.");
  changed |= ui::slider_double("\xce\xbc [m]", &c.verification.mu, 0.05, 5.0, "%.2f m", true,
                               "Truncation distance of the score D = \xce\xa3 min(|Tp - q|, "
                               "\xce\xbc) on the dense clouds.");
  changed |= ui::slider_double("verify voxel [m]", &c.verification.voxel_size, 0.1, 2.0, "%.2f m",
                               true, "Voxel size the dense clouds are reduced to before scoring.");
  changed |= ui::enum_combo("score", c.verification.score,
                            "How a candidate pose is scored: truncated distances (the method), "
                            "or the trimmed / plain sums (ablations).");
  changed |= ui::checkbox("refine selected pose", &c.refinement.enabled,
                          "Point-to-plane ICP of the selected pose on the verification clouds, "
                          "bounded in iterations and in how far it may move the pose; kept only "
                          "when it lowers D.");
  changed |= ui::checkbox("refine roll/pitch", &c.refinement.free_roll_pitch,
                          "Let refinement correct roll and pitch when the pose model holds them "
                          "level (4-DoF); SE(2) stays planar.");
  return changed;
}

// One landmark class's extraction parameters (cluster or FPFH).
bool class_fields(ClassParams& p) {
  bool changed = false;
  // Lower bounds keep one run to seconds on a KITTI scan (a run cannot be interrupted
  // inside a stage): FPFH at a 0.02 m voxel took over 100 s, at 0.3 m 6 s.
  const bool fpfh = p.method == LandmarkMethod::fpfh;
  changed |= ui::slider_double("voxel [m]", &p.voxel_size, fpfh ? 0.3 : 0.05, 2.0, "%.2f m", true,
                               fpfh ? "Downsampling voxel of this class before FPFH (at least "
                                      "0.3 m here: finer takes minutes on a KITTI scan)."
                                    : "Downsampling voxel of this class before clustering.");
  if (p.method == LandmarkMethod::cluster) {
    changed |= ui::slider_double("tolerance [m]", &p.cluster_tolerance, 0.05, 3.0, "%.2f m", true,
                                 "Largest gap between two points of one cluster.");
    changed |= ui::slider_int("min voxels", &p.min_points, 1, 500, false,
                              "Smallest cluster kept as a landmark [voxels].");
    changed |= ui::slider_int("max voxels", &p.max_points, 1, 20000, true,
                              "Largest cluster kept as a landmark [voxels]; at least min.");
    if (p.max_points < p.min_points) {
      p.max_points = p.min_points;
      changed = true;
    }
  } else {
    changed |= ui::slider_double("normal r [m]", &p.normal_radius, 0.1, 3.0, "%.2f m", true,
                                 "Radius of the normal estimate for FPFH.");
    changed |= ui::slider_double("feature r [m]", &p.feature_radius, 0.15, 5.0, "%.2f m", true,
                                 "Radius of the FPFH descriptor; kept larger than the normal "
                                 "radius.");
    if (p.feature_radius <= p.normal_radius) {
      p.feature_radius = shortest(static_cast<float>(p.normal_radius * 1.25));
      changed = true;
    }
  }
  return changed;
}

bool landmark_section(Config& c) {
  bool changed = false;
  section("landmarks");
  changed |=
      ui::input_int("corr. cap", &c.correspondences.max_correspondences, 1, kMaxCap, 100, true,
                    "At most this many correspondences (the most promising are kept); "
                    "Enter applies. Up to 5000 here: a run cannot be interrupted inside a "
                    "stage and larger graphs take minutes (0, no cap, only from a config "
                    "file).");
  changed |= ui::checkbox("fuse with landmarks", &c.correspondences.fuse_matches,
                          "With a matcher's correspondences (--correspondences FILE): keep the "
                          "landmark correspondences too, both in one pyramid, counted per origin "
                          "above the levels (off: the matcher's replace them).");
  for (ClassParams& p : c.landmarks.classes) {
    ImGui::PushID(p.name.c_str());
    const std::string text = p.name + " (" + to_string(p.method) + ")";
    if (ui::tree_node("##class", text.c_str())) {
      changed |= class_fields(p);
      ui::tree_pop();
    }
    ImGui::PopID();
  }
  return changed;
}

bool criterion_section(Config& c) {
  bool changed = false;
  section("success criterion");
  changed |=
      ui::slider_double("max t err [m]", &c.evaluation.max_translation_error, 0.1, 10.0, "%.1f m",
                        false, "A pose succeeds when its translation error is below this.");
  changed |= ui::slider_double("max r err [\xc2\xb0]", &c.evaluation.max_rotation_error, 0.5, 30.0,
                               "%.1f\xc2\xb0", false,
                               "A pose succeeds when its rotation error is below this.");
  return changed;
}

}  // namespace

std::pair<double, double> epsilon_range(TrimKind trim) {
  return trim == TrimKind::ratio ? std::pair{0.001, 1.0} : std::pair{0.01, 10.0};
}

void undo_redo_buttons(const ParamHistory& params, StudioActions& actions, const char* id) {
  const std::string suffix = id[0] ? std::string("##") + id : std::string();
  ImGui::BeginDisabled(!params.can_undo());
  if (ui::button(("undo" + suffix).c_str(), ImVec2(0, 0),
                 "Undo the last parameter change (Ctrl+Z)."))
    actions.undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!params.can_redo());
  if (ui::button(("redo" + suffix).c_str(), ImVec2(0, 0), "Redo (Ctrl+Y).")) actions.redo();
  ImGui::EndDisabled();
}

void parameters_panel(Config& config, const ParamHistory& params, const std::string& config_error,
                      StudioActions& actions) {
  if (!config_error.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kRed, "invalid: %s", config_error.c_str());
    ImGui::PopTextWrapPos();
  }
  bool changed = graph_section(config, actions);
  changed |= pose_section(config);
  changed |= landmark_section(config);
  changed |= criterion_section(config);
  undo_redo_buttons(params, actions, "");
  ImGui::SameLine();
  if (ui::button("defaults", ImVec2(0, 0), "Every parameter back to the paper's defaults.")) {
    config = default_config();
    changed = true;
  }
  if (changed) actions.submit_config();
}

}  // namespace pagor::studio
