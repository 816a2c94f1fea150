// The Data and View panels.

#include "panels/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <limits>
#include <string>

#include "pagor/errors.hpp"
#include "pagor/io/kitti.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

constexpr int kMaxFrame = 999999;

void open_data(AppState& s, StudioActions& actions) {
  s.have_data = true;
  s.camera_fitted = false;
  s.view.level = -1;
  actions.submit_data();
}

void kitti_fields(AppState& s, StudioActions& actions) {
  PairSource& d = s.data;
  ui::input_text("root", &d.kitti_root,
                 "Directory holding sequences/NN/ (velodyne, labels, poses).");
  ui::input_text("sequence", &d.sequence, "KITTI sequence number, two digits (00 to 21).");
  bool reopen = ui::input_int("source frame", &d.source_frame, 0, kMaxFrame, 1, true,
                              "Frame of the source scan; Enter or +/- opens it.");
  reopen |= ui::input_int("target frame", &d.target_frame, 0, kMaxFrame, 1, true,
                          "Frame of the target scan; Enter or +/- opens it.");
  if (reopen) open_data(s, actions);
  ui::input_text("pairs file", &s.pairs_file,
                 "Text file of 'source target' frame pairs to step through with Left/Right.");
  if (ui::button("read pairs", ImVec2(0, 0), "Reads the pairs file.")) {
    try {
      s.pairs = read_pairs_file(resolve_path(s, s.pairs_file));
      s.pair_index = -1;
      actions.notify(Message::info("read " + std::to_string(s.pairs.size()) + " pairs"));
    } catch (const Error& e) {
      actions.notify(Message::error(e.what()));
    }
  }
  if (!s.pairs.empty()) {
    ImGui::SameLine();
    if (ui::arrow_button("##prev", ImGuiDir_Left, "Previous pair (Left arrow)."))
      step_pair(s, s.pair_index < 0 ? 0 : -1, actions);
    ImGui::SameLine();
    if (ui::arrow_button("##next", ImGuiDir_Right, "Next pair (Right arrow)."))
      step_pair(s, 1, actions);
    ImGui::SameLine();
    ImGui::Text("pair %d / %zu", s.pair_index + 1, s.pairs.size());
  }
}

}  // namespace

void step_pair(AppState& s, int delta, StudioActions& actions) {
  if (s.pairs.empty()) return;
  s.pair_index = std::clamp(s.pair_index + delta, 0, static_cast<int>(s.pairs.size()) - 1);
  s.data.kind = PairSource::Kind::kitti;
  s.data.source_frame = s.pairs[static_cast<std::size_t>(s.pair_index)].first;
  s.data.target_frame = s.pairs[static_cast<std::size_t>(s.pair_index)].second;
  s.have_data = true;
  s.view.level = -1;
  actions.submit_data();
}

void indoor_preset_hint(Config& config, bool indoor, const char* id, StudioActions& actions) {
  if (!indoor || config.label_scheme.name == "indoor") return;
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextColored(
      ImVec4(1.0f, 0.8f, 0.3f, 1.0f),
      "scans against a floor plan: these parameters are for labelled outdoor clouds");
  ImGui::PopTextWrapPos();
  if (ui::button((std::string("use the indoor parameters##") + id).c_str(), ImVec2(0, 0),
                 "Apply the 'indoor' preset (pagor config --preset indoor): column landmarks, "
                 "difference TRIM in metres, SE(2) poses, a 1 m / 3 deg criterion.")) {
    config = preset_config("indoor");
    actions.submit_config();
  }
}

void data_panel(AppState& s, StudioActions& actions) {
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
    kitti_fields(s, actions);
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
      open_data(s, actions);
    }
  }
  if (ui::button("Open", ImVec2(-1, 0), "Loads the data above and runs the pipeline."))
    open_data(s, actions);
  indoor_preset_hint(s.config, s.have_data && is_indoor(d), "data", actions);
}

void view_panel(ViewState& v, CameraControl camera, bool& show_help, bool has_plan) {
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
  if (has_plan) {
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
  if (ui::button("fit", ImVec2(0, 0), "Frame everything shown (F).")) camera.fitted = false;
  ImGui::SameLine();
  if (ui::button("reset", ImVec2(0, 0), "Reset the camera (R).")) camera.reset();
  ImGui::SameLine();
  if (ui::checkbox("top-down", &camera.camera.top_down, "Orthographic view straight down (T)."))
    camera.fitted = false;
  ImGui::SameLine();
  if (ui::button("help", ImVec2(0, 0), "Keyboard and mouse shortcuts (F1 or H)."))
    show_help = !show_help;
}

}  // namespace pagor::studio
