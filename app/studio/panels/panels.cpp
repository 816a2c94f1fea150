// Data, parameters, view, history and session panels.

#include "panels/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "pagor/errors.hpp"
#include "pagor/io/kitti.hpp"
#include "widgets/number_format.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

constexpr int kMaxFrame = 999999, kMaxLevels = 32;
constexpr int kMaxCap = 5000;  // correspondences: ~2 s for the graph and clique stages
const ImVec4 kRed(1.0f, 0.4f, 0.4f, 1.0f);

void set_message(AppState& s, const std::string& text, bool error) {
  s.message = text;
  s.message_is_error = error;
}

void section(const char* title) {
  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextDisabled("%s", title);
}

void open_data(UiContext& ui) {
  ui.state.have_data = true;
  ui.state.camera_fitted = false;
  ui.state.view.level = -1;
  ui.submit_data();
}

// Keeps the levels strictly increasing inside the fixed range: sorts, clamps and drops equal
// neighbours (saying so). True when something had to change.
bool normalise_levels(AppState& s) {
  auto& th = s.config.graph.thresholds;
  const auto [lo, hi] = epsilon_range(s.config.graph.trim);
  const std::vector<double> before = th;
  for (double& e : th) e = std::clamp(e, lo, hi);
  if (th != before)
    set_message(s,
                "\xce\xb5 clamped into [" + std::to_string(lo) + ", " + std::to_string(hi) +
                    "], the range of TRIM '" + to_string(s.config.graph.trim) + "'",
                false);
  std::sort(th.begin(), th.end());
  th.erase(std::unique(th.begin(), th.end()), th.end());
  if (th.size() < before.size())
    set_message(s, "two levels had the same \xce\xb5; kept one", false);
  return th != before;
}

void kitti_fields(UiContext& ui) {
  AppState& s = ui.state;
  PairSource& d = s.data;
  ui::input_text("root", &d.kitti_root,
                 "Directory holding sequences/NN/ (velodyne, labels, poses).");
  ui::input_text("sequence", &d.sequence, "KITTI sequence number, two digits (00 to 21).");
  bool reopen = ui::input_int("source frame", &d.source_frame, 0, kMaxFrame, 1, true,
                              "Frame of the source scan; Enter or +/- opens it.");
  reopen |= ui::input_int("target frame", &d.target_frame, 0, kMaxFrame, 1, true,
                          "Frame of the target scan; Enter or +/- opens it.");
  if (reopen) open_data(ui);
  ui::input_text("pairs file", &s.pairs_file,
                 "Text file of 'source target' frame pairs to step through with Left/Right.");
  if (ui::button("read pairs", ImVec2(0, 0), "Reads the pairs file.")) {
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
    if (ui::arrow_button("##prev", ImGuiDir_Left, "Previous pair (Left arrow)."))
      step_pair(ui, s.pair_index < 0 ? 0 : -1);
    ImGui::SameLine();
    if (ui::arrow_button("##next", ImGuiDir_Right, "Next pair (Right arrow).")) step_pair(ui, 1);
    ImGui::SameLine();
    ImGui::Text("pair %d / %zu", s.pair_index + 1, s.pairs.size());
  }
}

}  // namespace

std::pair<double, double> epsilon_range(TrimKind trim) {
  return trim == TrimKind::ratio ? std::pair{0.001, 1.0} : std::pair{0.01, 10.0};
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

void indoor_preset_hint(UiContext& ui, bool indoor, const char* id) {
  if (!indoor || ui.state.config.label_scheme.name == "indoor") return;
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextColored(
      ImVec4(1.0f, 0.8f, 0.3f, 1.0f),
      "scans against a floor plan: these parameters are for labelled outdoor clouds");
  ImGui::PopTextWrapPos();
  if (ui::button((std::string("use the indoor parameters##") + id).c_str(), ImVec2(0, 0),
                 "Apply the 'indoor' preset (pagor config --preset indoor): column landmarks, "
                 "difference TRIM in metres, SE(2) poses, a 1 m / 3 deg criterion.")) {
    ui.state.config = preset_config("indoor");
    ui.submit_config();
  }
}

void data_panel(UiContext& ui) {
  AppState& s = ui.state;
  PairSource& d = s.data;
  if (ui::button(s.bench.open ? "back to the benchmark" : "benchmark view...", ImVec2(-1, 0),
                 "Many pairs at once: a pairs file or manifest, rates, plots, sweeps."))
    s.main_view = MainView::benchmark;
  ui::radio("KITTI", &d.kind, PairSource::Kind::kitti,
            "A pair of scans of a KITTI odometry sequence, with ground truth.");
  ImGui::SameLine();
  ui::radio("files", &d.kind, PairSource::Kind::files,
            "Two clouds from PCD, PLY or KITTI .bin files, with optional .label files.");
  ImGui::SameLine();
  ui::radio("synthetic", &d.kind, PairSource::Kind::synthetic,
            "A labelled scene generated from a seed, seen by two sensors with a known pose.");
  if (d.kind == PairSource::Kind::kitti) {
    kitti_fields(ui);
  } else if (d.kind == PairSource::Kind::files) {
    ui::input_text("source cloud", &d.source, "Path of the source cloud (PCD, PLY or .bin).");
    ui::input_text("source labels", &d.source_labels,
                   "Optional .label file of the source; empty when the cloud holds labels.");
    ui::input_text("target cloud", &d.target, "Path of the target cloud (PCD, PLY or .bin).");
    ui::input_text("target labels", &d.target_labels,
                   "Optional .label file of the target; empty when the cloud holds labels.");
    ui::input_text("ground truth file", &d.ground_truth,
                   "Optional 4x4 T_target_source file (row-major): errors, success and green/red "
                   "lines against it.");
  } else {
    int seed = static_cast<int>(std::min<std::uint64_t>(d.synthetic_seed, 2147483647));
    if (ui::input_int("seed", &seed, 0, std::numeric_limits<int>::max(), 1, true,
                      "Seed of the generated scene; Enter or +/- opens it.")) {
      d.synthetic_seed = static_cast<std::uint64_t>(seed);
      open_data(ui);
    }
  }
  if (ui::button("Open", ImVec2(-1, 0), "Loads the data above and runs the pipeline."))
    open_data(ui);
  indoor_preset_hint(ui, ui.state.have_data && is_indoor(d), "data");
}

// The built-in label schemes that name every configured landmark class (others would make the
// configuration invalid). Returns whether the scheme changed.
bool label_scheme_combo(Config& c) {
  bool changed = false;
  if (ui::begin_combo(
          "labels", c.label_scheme.name.c_str(),
          "Numbering of the clouds' labels: raw SemanticKITTI ids, the 0-based training "
          "numbering, or the learning map that segmentation networks output.")) {
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

void parameters_panel(UiContext& ui) {
  AppState& s = ui.state;
  Config& c = s.config;
  bool changed = false;
  GraphParams& g = c.graph;
  const bool ratio = g.trim == TrimKind::ratio;
  const auto [lo, hi] = epsilon_range(g.trim);
  if (!ui.config_error.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kRed, "invalid: %s", ui.config_error.c_str());
    ImGui::PopTextWrapPos();
  }
  changed |= label_scheme_combo(c);
  ImGui::TextDisabled("%zu levels, \xce\xb5 in [%g, %g]%s", g.thresholds.size(), lo, hi,
                      ratio ? "" : " m");
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
    normalise_levels(s);
    changed = true;
  }
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
    if (released && normalise_levels(s)) changed = true;
    if (l >= g.thresholds.size()) break;
  }
  if (!ImGui::IsAnyItemActive() && normalise_levels(s)) changed = true;
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

  section("landmarks");
  changed |=
      ui::input_int("corr. cap", &c.correspondences.max_correspondences, 1, kMaxCap, 100, true,
                    "At most this many correspondences (the most promising are kept); "
                    "Enter applies. Up to 5000 here: a run cannot be interrupted inside a "
                    "stage and larger graphs take minutes (0, no cap, only from a config "
                    "file).");
  for (ClassParams& p : c.landmarks.classes) {
    ImGui::PushID(p.name.c_str());
    const std::string text = p.name + " (" + to_string(p.method) + ")";
    if (ui::tree_node("##class", text.c_str())) {
      // Lower bounds keep one run to seconds on a KITTI scan (a run cannot be interrupted
      // inside a stage): FPFH at a 0.02 m voxel took over 100 s, at 0.3 m 6 s.
      const bool fpfh = p.method == LandmarkMethod::fpfh;
      changed |=
          ui::slider_double("voxel [m]", &p.voxel_size, fpfh ? 0.3 : 0.05, 2.0, "%.2f m", true,
                            fpfh ? "Downsampling voxel of this class before FPFH (at least "
                                   "0.3 m here: finer takes minutes on a KITTI scan)."
                                 : "Downsampling voxel of this class before clustering.");
      if (p.method == LandmarkMethod::cluster) {
        changed |= ui::slider_double("tolerance [m]", &p.cluster_tolerance, 0.05, 3.0, "%.2f m",
                                     true, "Largest gap between two points of one cluster.");
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
      ui::tree_pop();
    }
    ImGui::PopID();
  }
  section("success criterion");
  changed |=
      ui::slider_double("max t err [m]", &c.evaluation.max_translation_error, 0.1, 10.0, "%.1f m",
                        false, "A pose succeeds when its translation error is below this.");
  changed |= ui::slider_double("max r err [\xc2\xb0]", &c.evaluation.max_rotation_error, 0.5, 30.0,
                               "%.1f\xc2\xb0", false,
                               "A pose succeeds when its rotation error is below this.");
  ImGui::BeginDisabled(!ui.params || !ui.params->can_undo());
  if (ui::button("undo", ImVec2(0, 0), "Undo the last parameter change (Ctrl+Z).")) ui.undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!ui.params || !ui.params->can_redo());
  if (ui::button("redo", ImVec2(0, 0), "Redo (Ctrl+Y).")) ui.redo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ui::button("defaults", ImVec2(0, 0), "Every parameter back to the paper's defaults.")) {
    c = default_config();
    changed = true;
  }
  if (changed) ui.submit_config();
}

void view_panel(UiContext& ui) {
  ViewState& v = ui.state.view;
  Layers& l = v.layers;
  using L = ViewLimits;
  ui::checkbox("source", &l.source, "Show the source cloud (under the pose chosen below).");
  ImGui::SameLine();
  ui::checkbox("target", &l.target, "Show the target cloud.");
  ImGui::SameLine();
  ui::checkbox("landmarks", &l.landmarks, "Show the landmarks as round points in class colours.");
  ui::checkbox("clique lines", &l.correspondences,
               "Show the shown level's clique as lines from source to target landmark.");
  ImGui::SameLine();
  ui::checkbox("all corr.", &l.all_correspondences,
               "Also show every correspondence outside the clique, faint, in class colours.");
  if (ui.snapshot && ui.snapshot->plan) {
    ImGui::SameLine();
    ui::checkbox(
        "floor plan", &l.plan,
        "Indoor pair: the plan's walls as lines and columns as circles (orange), and the "
        "columns found in the scan as circles with a cross (blue), under the source pose.");
  }
  ui::checkbox("grid, axes, scale", &v.grid,
               "Ground grid, XYZ axes at the origin and a scale bar.");
  ImGui::SameLine();
  ui::checkbox("legend", &v.legend, "Colour legend in the 3D view.");
  ui::slider_float("point size [px]", &v.point_size, L::min_point_size, L::max_point_size, "%.1f",
                   false, "Size of the dense cloud points (+ / - keys).");
  ui::slider_float("landmark size [px]", &v.landmark_size, L::min_landmark_size,
                   L::max_landmark_size, "%.0f", false, "Size of the landmark points.");
  ui::slider_float("line width [px]", &v.line_width, L::min_line_width, L::max_line_width, "%.1f",
                   false, "Width of the correspondence lines.");
  ImGui::TextUnformatted("colour:");
  ImGui::SameLine();
  ui::radio("class", &v.color, ColorMode::by_class, "Colour points by semantic class.");
  ImGui::SameLine();
  ui::radio("source/target", &v.color, ColorMode::by_cloud,
            "Colour points by cloud: source blue, target orange.");
  ImGui::TextUnformatted("source under:");
  ui::radio("candidate", &v.pose, PoseShown::selected,
            "Place the source under the shown level's candidate pose.");
  ImGui::SameLine();
  ui::radio("refined", &v.pose, PoseShown::refined,
            "Place the source under the selected pose after refinement (the candidate itself "
            "where refinement is off or did not lower D). Toggle with 'candidate' to compare.");
  ui::radio("ground truth", &v.pose, PoseShown::ground_truth,
            "Place the source under the ground-truth pose (when known).");
  ImGui::SameLine();
  ui::radio("identity", &v.pose, PoseShown::identity, "Leave the source where its sensor saw it.");
  Camera& cam = ui.state.camera;
  if (ui::button("fit", ImVec2(0, 0), "Frame everything shown (F)."))
    ui.state.camera_fitted = false;
  ImGui::SameLine();
  if (ui::button("reset", ImVec2(0, 0), "Reset the camera (R).")) {
    const bool top = cam.top_down;
    cam = Camera{};
    cam.top_down = top;
    ui.state.camera_fitted = false;
  }
  ImGui::SameLine();
  if (ui::checkbox("top-down", &cam.top_down, "Orthographic view straight down (T)."))
    ui.state.camera_fitted = false;
  ImGui::SameLine();
  if (ui::button("help", ImVec2(0, 0), "Keyboard and mouse shortcuts (F1 or H)."))
    ui.state.show_help = !ui.state.show_help;
}

}  // namespace pagor::studio
