#pragma once
/// \file app_state.hpp
/// The studio's state: what data is open, every parameter, the camera and what is shown. Panels
/// draw from it and edit it; the session file is this state on disk.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pagor/config.hpp"
#include "pagor/eval/dataset.hpp"
#include "pagor/eval/pair_set.hpp"
#include "state/camera.hpp"
#include "state/camera_views.hpp"
#include "state/message.hpp"

namespace pagor::studio {

/// What the dense clouds are coloured by: semantic class, cloud (source blue, target orange),
/// height z in the target frame, the lidar's intensity, or (source) the residual of each
/// verification point: its distance to the nearest target point under the shown pose, capped at
/// mu. The legend shows the same.
enum class ColorMode { by_class, by_cloud, height, intensity, residual };
/// Where the source is drawn: under the shown level's candidate, the truth, its own frame, or
/// the refined selection (the candidate where refinement did not apply).
enum class PoseShown { selected, ground_truth, identity, refined };

/// Which correspondences the diagnosis filter keeps (by their ground-truth residual).
enum class TruthFilter { all, inliers, outliers };
/// What the source cloud is coloured by: its class (or cloud), or each verification point's
/// contribution min(d, mu) to D under the shown level's candidate or under the ground truth.
enum class Contribution { off, candidate, ground_truth };

/// The diagnosis items of the view (diagnosis_panel.cpp); they need a ground truth.
struct DiagnosisView {
  bool panel = false;              ///< the bottom panel shows the diagnosis instead of the pyramid
  bool color_by_residual = false;  ///< correspondence lines coloured by ground-truth residual
  std::string class_name;          ///< only this class's correspondences (empty: every class)
  TruthFilter truth = TruthFilter::all;  ///< only true / only false correspondences
  bool edges_on_hover = true;  ///< a hovered correspondence shows its graph edges at the level
  Contribution contribution = Contribution::off;  ///< colour the source by its part of D
};

/// Which layers of the 3D view are drawn.
struct Layers {
  bool source = true;
  bool target = true;
  bool landmarks = true;
  bool correspondences = true;       ///< the shown level's clique
  bool all_correspondences = false;  ///< also those outside the clique, faint
  bool plan = true;  ///< indoor pairs: the plan's walls and columns, and the scan's columns
};

struct ViewState {
  Layers layers;
  float point_size = 2.0f;      ///< dense clouds [px]
  float landmark_size = 11.0f;  ///< landmarks [px]
  float line_width = 2.5f;      ///< correspondence lines [px]
  bool grid = true;             ///< ground grid, axes and scale bar
  bool legend = true;           ///< colour legend
  ColorMode color = ColorMode::by_class;
  PoseShown pose = PoseShown::selected;  ///< how the source cloud is placed
  int level = -1;                        ///< pyramid level shown; -1 follows the selected one
  DiagnosisView diagnosis;               ///< diagnosis panel and 3D-view items
};

/// Where the splitters are; kept in the session.
struct LayoutState {
  float left_width = 330.0f;  ///< left panel [px] (clamped to the window)
  float scene_share = 0.6f;   ///< share of the height right of the panel taken by the 3D view
};

/// Limits of the view settings (widgets and the session reader enforce them).
struct ViewLimits {
  static constexpr float min_point_size = 1.0f, max_point_size = 10.0f;        ///< [px]
  static constexpr float min_landmark_size = 3.0f, max_landmark_size = 30.0f;  ///< [px]
  static constexpr float min_line_width = 1.0f, max_line_width = 8.0f;         ///< [px]
  static constexpr float min_left_width = 180.0f, max_left_width = 1200.0f;    ///< [px]
  static constexpr float min_scene_share = 0.2f, max_scene_share = 0.9f;
};

/// What the main area shows: the pair view (3D view and pyramid) or the benchmark view.
enum class MainView { pair, benchmark };

/// What the benchmark view opens: a manifest, a KITTI pairs file or `pagor bench --out` results.
enum class BenchSource { manifest, kitti_pairs, results };

/// Which rows the benchmark table lists. The session stores the number (0 all ... 4 rejected).
enum class RowFilter { all, failures, successes, accepted, rejected };

/// The benchmark view (benchmark_view.hpp); kept in the session.
struct BenchViewState {
  BenchSource source = BenchSource::manifest;  ///< what `path` names
  std::string path;  ///< the manifest, KITTI pairs file or `pagor bench --out` results
  std::string kitti_root = "../shared/data/kitti";  ///< kitti_pairs: the KITTI root
  std::string sequence = "00";                      ///< kitti_pairs: the sequence
  std::string config_path;          ///< a configuration JSON the user loads for the set
  bool open = false;                ///< a set is open (re-opened when a session is loaded)
  std::string filter;               ///< rows whose pair name contains this
  RowFilter show = RowFilter::all;  ///< which rows the table lists
  int sort = 0;                     ///< column index of benchmark_view's columns
  bool descending = false;
  int budget_mib = 1024;                       ///< memory budget of the per-pair caches [MiB]
  int jobs = 1;                                ///< pairs evaluated at once, 1 .. kMaxBenchJobs
  std::string plot_path = "pagor-plot";        ///< exports go to PATH-<plot>.png / .csv
  std::string sweep_path = "verification.mu";  ///< sweep: the parameter (configuration key path)
  std::string sweep_values = "0.5,1,2";        ///< its values: "a,b,c"; threshold sets "a,b;c"
  std::string sweep_path2;                     ///< a second parameter for a 2-D sweep (empty: 1-D)
  std::string sweep_values2;                   ///< its values
  int flip_a = 0, flip_b = 1;                  ///< the two sweep settings the flip view compares
};

/// A point picked in the 3D view (click; Shift+click adds a second to measure between).
struct Pick {
  bool source = false;           ///< picked from the source cloud (else the target)
  std::size_t index = 0;         ///< the point's index in its cloud
  Eigen::Vector3f at{0, 0, 0};   ///< where it is drawn: the target frame [m]
  Eigen::Vector3f raw{0, 0, 0};  ///< its coordinates in its own cloud's frame [m]
  std::string class_name;        ///< its class under the label scheme ("" without labels)
  long label = -1;               ///< its raw label's semantic id (-1 without labels)
  float nearest_target = 0;  ///< distance to the nearest target point [m] (the target itself: 0)
};

/// What a file dialog opens the chosen file as.
enum class FilePurpose {
  any,              ///< by its kind: a cloud, labels, a config, a session, a manifest, ...
  source_cloud,     ///< files mode's source cloud
  target_cloud,     ///< files mode's target cloud
  source_labels,    ///< files mode's source .label file
  target_labels,    ///< files mode's target .label file
  ground_truth,     ///< files mode's 4x4 T_target_source
  correspondences,  ///< files mode's matcher correspondences (px py pz qx qy qz [w [inlier]])
  pairs,            ///< a pairs file or manifest to step through
  config,           ///< a configuration JSON
  session,          ///< a session JSON
  bench,            ///< the benchmark view's set or results file
  kitti_root,       ///< a KITTI root directory
};

/// The studio's own file browser (panels/file_dialog.cpp).
struct FileDialogState {
  bool open = false;
  FilePurpose purpose = FilePurpose::any;
  std::string directory;  ///< listed directory (absolute)
  std::string name;       ///< the file name typed or clicked
  std::string filter;     ///< only names containing this
  /// The listing shown, read once per directory, filter and purpose (`listed` names them).
  std::vector<std::pair<std::string, bool>> listing;  ///< (name, is a directory)
  std::string listed;
  bool truncated = false;     ///< the directory holds more than the listing shows
  std::string listing_error;  ///< why the directory could not be listed (empty: it was)
};

/// What the parameter lists are narrowed to (param_editor.hpp: field_matches); not saved.
struct SearchState {
  std::string parameters;  ///< the Parameters panel's every-parameter list
  std::string sweep;       ///< the sweep's parameter choices
};

/// What a session file holds (save_session writes this part only): the data, the parameters,
/// the view, the camera and its saved views, the layout, the window and the benchmark view.
struct SessionState {
  PairSource data;  ///< as the user wrote it; relative paths are taken from `base_dir`
  bool have_data = false;
  std::string pairs_file;  ///< optional: a KITTI pairs file or a manifest to step through
  /// A ground truth that came with the data without a file (a row of `pagor bench --out`
  /// results); dropped when other data is opened.
  std::optional<Transform> inline_truth;

  Config config = default_config();
  /// The preset the configuration starts from ("default", "paper", "indoor"): what "defaults" and
  /// each parameter's reset go back to, and what a parameter is marked modified against.
  std::string preset = "default";
  MainView main_view = MainView::pair;
  BenchViewState bench;
  ViewState view;
  LayoutState layout;
  Camera camera;
  std::vector<CameraView> camera_views;  ///< saved with "save view", restored with a click

  /// The pair view's exports (result JSON, levels and diagnosis CSV) go to <export_path>-<name>;
  /// the benchmark view has its own (bench.plot_path).
  std::string export_path = "pagor-pair";
  int width = 1280, height = 720;  ///< window or image size [px]
};

/// What the UI holds between frames and no session keeps: messages, picks, the file browser,
/// the recent files, the help overlay, the search fields, where files are saved to.
struct UiState {
  std::string session_path = "pagor-session.json";
  std::string screenshot_path = "pagor-studio.png";
  bool camera_fitted = false;  ///< false: fit to the data when it arrives
  Message message;  ///< the last message for the user (StudioActions::notify), in the status bar
  bool want_screenshot = false;
  std::vector<Pick> picks;          ///< at most two: coordinates, and the distance between
  FileDialogState dialog;           ///< the file browser
  std::vector<std::string> recent;  ///< recently opened files, newest first (absolute)
  std::string recent_file;          ///< where `recent` is kept between runs (empty: not kept)
  bool show_help = false;           ///< the shortcut overlay (F1 or H)
  SearchState search;               ///< the parameter lists' search fields
};

/// The studio's whole state: the session's part, the UI's part, and what follows from the session
/// (where its relative paths start, the pairs read from its pairs file).
struct AppState : SessionState, UiState {
  std::string base_dir;  ///< directory of the loaded session file (empty: working directory)
  PairSet pairs;         ///< read from pairs_file (read_step_pairs)
  int pair_index = -1;   ///< the pair of `pairs` shown, -1: none of them
};

/// The part of the state the benchmark view draws and edits (panels/benchmark_view.hpp): its
/// settings, the parameters its set runs with and their preset, the sweep's search field and which
/// main view is shown. Its relative paths are taken from `base_dir`.
struct BenchPanelState {
  BenchViewState& view;
  Config& config;
  std::string& preset;
  std::string& sweep_search;
  MainView& main_view;
  const std::string& base_dir;
};

/// That part of `state`.
BenchPanelState bench_panel_state(AppState& state);

/// Writes the session's part of the state as a session file (schema pagor.session/1). Throws
/// pagor::InputError.
void save_session(const SessionState& state, const std::string& path);

/// Reads a session file into `state`. Data paths are kept as written; relative ones are taken
/// from the session file's directory (`base_dir`). Throws pagor::InputError or
/// pagor::ConfigError naming the file and key.
void load_session(const std::string& path, AppState& state);

/// A path the user wrote, resolved against `base_dir` when relative.
std::string resolve_path(const AppState& state, const std::string& path);
/// The same against a base directory (empty: the working directory).
std::string resolve_path(const std::string& base_dir, const std::string& path);

/// `data` with its relative paths resolved against `base_dir`.
PairSource resolved_data(const AppState& state);

/// Whether `data` is an indoor pair: a scan against a floor plan (dataset.hpp).
bool is_indoor(const PairSource& data);

/// Reads pairs to step through: a KITTI pairs file ('source target' frame numbers per line, in
/// the sequence `kitti_root`/`sequence`) or any manifest (pair_set.hpp), told apart by the first
/// pair line. Throws InputError naming the file (and line).
PairSet read_step_pairs(const std::string& path, const std::string& kitti_root,
                        const std::string& sequence);

/// Index of `data` in `pairs` (the same KITTI frames, or the same two files), or -1.
int index_of_pair(const PairSet& pairs, const PairSource& data);

/// Makes `state.data` the pair `entry` (absolute paths, so a session elsewhere still finds them),
/// with its ground truth; the view follows the new pair's selected level.
void show_pair(AppState& state, const PairEntry& entry);

/// Moves through `state.pairs` by `delta` (clamped; from no pair, +1 and -1 both open the first)
/// and shows that pair. False when there are no pairs.
bool step_pair_index(AppState& state, int delta);

/// `path` made absolute and normal (relative to the working directory); unchanged when empty or
/// when the working directory cannot be read.
std::string absolute_path(const std::string& path);

/// Adds `path` (made absolute) to the front of `state.recent` (at most 12, no duplicates) and
/// writes the list to `state.recent_file` when one is set (errors are ignored: a list that cannot
/// be kept is no reason to stop).
void remember_file(AppState& state, const std::string& path);
/// Drops `path` (made absolute) from `state.recent`, as a file that failed to open, and writes
/// the list. True when it was there.
bool forget_file(AppState& state, const std::string& path);
/// Reads `state.recent_file` into `state.recent` (a missing file: an empty list).
void load_recent_files(AppState& state);

/// The level the view shows: `view.level` if valid, else the selected one (or -1).
int shown_level(const ViewState& view, int selected, int levels);

}  // namespace pagor::studio
