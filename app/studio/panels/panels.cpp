// The Data and View panels.

#include "panels/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>
#include <string>

#include "pagor/errors.hpp"
#include "pagor/io/kitti.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {
namespace {

constexpr int kMaxFrame = 999999;
constexpr int kExistsRecheckFrames = 60;  // a file may appear or go: looked at again after these

bool path_exists(const std::string& path) {
  struct Seen {
    bool exists;
    int frame;
  };
  static std::map<std::string, Seen> seen;  // the paths of the last few seconds' fields
  const int now = ImGui::GetFrameCount();
  auto it = seen.find(path);
  if (it == seen.end() || now - it->second.frame > kExistsRecheckFrames) {
    if (seen.size() > 64) seen.clear();
    std::error_code ec;
    it = seen.insert_or_assign(path, Seen{std::filesystem::exists(path, ec), now}).first;
  }
  return it->second.exists;
}

void open_data(AppState& s, StudioActions& actions) {
  s.have_data = true;
  s.camera_fitted = false;
  s.view.level = -1;
  s.picks.clear();
  s.inline_truth.reset();
  actions.submit_data();
}

// A path field with a "..." button that opens the file browser for it; a path that names nothing
// is drawn as a warning.
void path_field(AppState& s, const char* label, std::string* path, FilePurpose purpose,
                const char* tip) {
  ImGui::PushID(label);
  ImGui::PushItemWidth(ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - 4);
  ui::input_path(label, path, tip, path->empty() || path_exists(resolve_path(s, *path)));
  ImGui::PopItemWidth();
  ImGui::SameLine(0, 4);
  if (ui::button("...", ImVec2(ImGui::GetFrameHeight(), 0), "Choose the file in a browser."))
    open_file_dialog(s, purpose, *path);
  ImGui::PopID();
}

void kitti_fields(AppState& s, StudioActions& actions) {
  PairSource& d = s.data;
  path_field(s, "root", &d.kitti_root, FilePurpose::kitti_root,
             "Directory holding sequences/NN/ (velodyne, labels, poses).");
  ui::input_text("sequence", &d.sequence, "KITTI sequence number, two digits (00 to 21).");
  bool reopen = ui::input_int("source frame", &d.source_frame, 0, kMaxFrame, 1, true,
                              "Frame of the source scan; Enter or +/- opens it.");
  reopen |= ui::input_int("target frame", &d.target_frame, 0, kMaxFrame, 1, true,
                          "Frame of the target scan; Enter or +/- opens it.");
  if (reopen) open_data(s, actions);
}

void files_fields(AppState& s) {
  PairSource& d = s.data;
  path_field(s, "source cloud", &d.source, FilePurpose::source_cloud,
             "Path of the source cloud (PCD, PLY or .bin).");
  path_field(s, "source labels", &d.source_labels, FilePurpose::source_labels,
             "Optional .label file of the source; empty when the cloud holds labels.");
  path_field(s, "target cloud", &d.target, FilePurpose::target_cloud,
             "Path of the target cloud (PCD, PLY or .bin), or a floor plan (.json, .svg).");
  path_field(s, "target labels", &d.target_labels, FilePurpose::target_labels,
             "Optional .label file of the target; empty when the cloud holds labels.");
  path_field(s, "ground truth file", &d.ground_truth, FilePurpose::ground_truth,
             "Optional 4x4 T_target_source file (row-major): errors, success and green/red "
             "lines against it. It belongs to these files: KITTI and the synthetic scene keep "
             "their own.");
  path_field(s, "correspondences", &d.correspondences, FilePurpose::correspondences,
             "Optional matcher's correspondences (px py pz qx qy qz [weight [inlier 0/1]] per "
             "line, as pagor register --correspondences): they replace the landmark ones. With "
             "both clouds they are verified on them; without, the back end runs alone.");
  if (s.inline_truth) ui::figure_dim("ground truth: from the benchmark results row");
}

// The pairs file or manifest to step through, and the arrows.
void pairs_fields(AppState& s, StudioActions& actions) {
  path_field(s, "pairs file", &s.pairs_file, FilePurpose::pairs,
             "A KITTI pairs file ('source target' frames of the sequence above) or any manifest "
             "(SOURCE TARGET [gt=...] per line, as pagor bench --manifest) to step through with "
             "Left/Right.");
  if (ui::button("read pairs", ImVec2(0, 0), "Reads the pairs file or manifest.")) {
    try {
      s.pairs = read_step_pairs(resolve_path(s, s.pairs_file), resolve_path(s, s.data.kitti_root),
                                s.data.sequence);
      s.pair_index = index_of_pair(s.pairs, resolved_data(s));
      actions.notify(Message::info("read " + std::to_string(s.pairs.pairs.size()) + " pairs"));
    } catch (const Error& e) {
      actions.notify(Message::error(e.what()));
    }
  }
  if (s.pairs.pairs.empty()) return;
  ImGui::SameLine();
  if (ui::arrow_button("##prev", ImGuiDir_Left, "Previous pair (Left arrow)."))
    step_pair(s, -1, actions);
  ImGui::SameLine();
  if (ui::arrow_button("##next", ImGuiDir_Right, "Next pair (Right arrow)."))
    step_pair(s, 1, actions);
  ImGui::SameLine();
  const std::string name =
      s.pair_index >= 0 ? s.pairs.pairs[static_cast<std::size_t>(s.pair_index)].name : "-";
  ui::figure(ui::format("pair %d / %zu: %s", s.pair_index + 1, s.pairs.pairs.size(), name.c_str()));
}

// The recently opened files, newest first; a pick opens it again.
void recent_files(AppState& s, StudioActions& actions) {
  if (s.recent.empty()) return;
  // On a line of its own, as wide as the fields: its preview is never cut.
  const std::string preview = std::to_string(s.recent.size()) + " files, newest first";
  if (ui::begin_combo("recent files", preview.c_str(),
                      "Files opened recently (by the browser, a drop or here), newest first; a "
                      "file that failed to open leaves the list.")) {
    const std::vector<std::string> recent = s.recent;  // opening reorders the list
    for (std::size_t i = 0; i < recent.size(); ++i)
      if (ui::selectable((recent[i] + "##recent" + std::to_string(i)).c_str(), false))
        actions.open_file(recent[i], FilePurpose::any);
    ui::end_combo();
  }
}

}  // namespace

void open_file_dialog(AppState& s, FilePurpose purpose, const std::string& current) {
  FileDialogState& f = s.dialog;
  f.open = true;
  f.purpose = purpose;
  f.name.clear();
  f.filter.clear();
  std::error_code ec;
  const std::string at = current.empty() ? std::string() : resolve_path(s, current);
  const std::filesystem::path p(at);
  if (!at.empty() && std::filesystem::is_directory(p, ec))
    f.directory = absolute_path(at);
  else if (!at.empty() && std::filesystem::is_directory(p.parent_path(), ec))
    f.directory = absolute_path(p.parent_path().string()), f.name = p.filename().string();
  else if (f.directory.empty())
    f.directory = absolute_path(s.base_dir.empty() ? "." : s.base_dir);
}

void step_pair(AppState& s, int delta, StudioActions& actions) {
  if (step_pair_index(s, delta)) actions.submit_data();
}

void indoor_preset_hint(Config& config, std::string& preset, bool indoor, const char* id,
                        StudioActions& actions) {
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
    preset = "indoor";
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
    files_fields(s);
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
  pairs_fields(s, actions);
  if (ui::button("open a file...", ImVec2(0, 0),
                 "Any file the studio reads: clouds, .label files, a ground truth, a "
                 "configuration, a session, a pairs file or manifest, pagor bench results. "
                 "Files can also be dropped on the window."))
    open_file_dialog(s, FilePurpose::any, "");
  recent_files(s, actions);
  indoor_preset_hint(s.config, s.preset, s.have_data && is_indoor(d), "data", actions);
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
  ui::radio("class", &v.color, ColorMode::by_class,
            "Colour points by semantic class (the legend lists the classes drawn).");
  ImGui::SameLine();
  ui::radio("source/target", &v.color, ColorMode::by_cloud,
            "Colour points by cloud: source blue, target orange.");
  ImGui::SameLine();
  ui::radio("height", &v.color, ColorMode::height,
            "Colour points by height z in the target frame [m] (colour bar in the legend).");
  ui::radio("intensity", &v.color, ColorMode::intensity,
            "Colour points by the lidar's reflectance (grey where a cloud has none).");
  ImGui::SameLine();
  ui::radio("residual", &v.color, ColorMode::residual,
            "Colour the source's verification points by their distance to the nearest target "
            "point under the shown pose, capped at mu [m]; the target stays grey.");
  ImGui::TextUnformatted("source under:");
  ui::radio("candidate", &v.pose, PoseShown::selected,
            "Place the source under the shown level's candidate pose.");
  ImGui::SameLine();
  ui::radio("refined", &v.pose, PoseShown::refined,
            "Place the source under the selected pose after refinement (the candidate itself "
            "where refinement is off or did not lower D; the verdict's adopted alternative when "
            "it took one). Toggle with 'candidate' to compare.");
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
  ui::figure("click a point in the 3D view to pick it, Shift+click a second to measure",
             ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), true);
}

}  // namespace pagor::studio
