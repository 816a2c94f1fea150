#pragma once
/// \file studio.hpp
/// One frame of Pagor Studio, the same in the window and headless: lays out the panels and
/// splitters, handles the keyboard shortcuts, renders the 3D view and ImGui's draw data through
/// the GL table.

#include <memory>
#include <string>
#include <vector>

#include "panels/studio_actions.hpp"
#include "render/gl.hpp"
#include "render/imgui_renderer.hpp"
#include "runners/bench_worker.hpp"
#include "runners/worker.hpp"
#include "scene/scene_view.hpp"
#include "scene/scene_window.hpp"
#include "state/app_state.hpp"
#include "state/history.hpp"
#include "state/input_queue.hpp"
#include "widgets/plot.hpp"

namespace pagor::studio {

/// A keyboard shortcut, as the help overlay lists it.
struct Shortcut {
  const char* keys;
  const char* action;
};
/// Every shortcut of the studio.
const std::vector<Shortcut>& shortcuts();

/// The studio: owns the state, the workers and the renderers, lays out the panels each frame and
/// carries out what they ask (StudioActions).
class Studio : public StudioActions {
 public:
  /// Needs a current GL context and an ImGui context.
  Studio(const Gl& gl, AppState state);
  ~Studio() override;
  /// Loads the font, builds renderers, maps ImGui's named keys when no backend did. False with
  /// `error` on failure.
  bool init(std::string& error);

  /// Sends the current data and configuration to the worker.
  void submit_data() override;
  /// Re-runs with the current configuration; does nothing while it is invalid (the UI says why).
  void submit_config() override;
  /// One step back in the parameter history and a re-run; the status bar says how many remain.
  void undo() override;
  /// One step forward in the parameter history and a re-run.
  void redo() override;
  /// Saves the state to `state().session_path`; the outcome goes to the status bar.
  void save_session_now() override;
  /// Loads `state().session_path` and opens its data; the outcome goes to the status bar.
  void load_session_now() override;
  /// Writes the window to `state().screenshot_path` at the end of this frame.
  void save_screenshot() override;
  /// Queues a plot for PNG export; rendered and written at the next frame.
  void export_plot(const Plot& plot, const std::string& path) override;
  /// Keeps the message in `state().message`, which the status bar shows.
  void notify(Message message) override;
  /// Opens a user's file (state/open_file.hpp) and re-runs what it changed.
  void open_file(const std::string& path, FilePurpose purpose) override;
  /// Opens the studio's file browser (panels/file_dialog.cpp).
  void browse(FilePurpose purpose, const std::string& current) override;
  /// Makes `entry` the data (show_pair), with `truth` as its inline ground truth, and runs it.
  void open_pair(const PairEntry& entry, const std::optional<Transform>& truth) override;
  /// Puts text on ImGui's clipboard (the system's in the window) and says so.
  void copy_text(const std::string& text, const std::string& what) override;
  /// Files dropped on the window (the window's drop callback; the tests call it the same way):
  /// each opened by its kind, two clouds as source and target.
  void open_files(const std::vector<std::string>& paths);

  /// A key press (GLFW key code) for the shortcuts alone, handled at the next frame (the tests'
  /// shortcut presses; the window's keys go through input()).
  void queue_key(int key, bool ctrl, bool shift);
  /// The keyboard's events in the order they came (the window's GLFW callbacks fill it; the
  /// driven-UI tests may): each frame feeds ImGui one logical event of it and reads its key
  /// press as a shortcut.
  InputQueue& input() { return input_; }

  /// Whether another frame is needed without new input: a run or the benchmark's pairs in
  /// progress, a result not yet shown, a plot export or screenshot to write, queued keys. The
  /// window waits for events while it is false.
  bool wants_frame() const;

  /// Builds and draws one frame of width x height pixels into the default framebuffer, and writes
  /// the screenshot the user asked for.
  void frame(int width, int height);
  /// Reads the default framebuffer and writes a PNG. False with `error` on failure.
  bool screenshot(const std::string& path, int width, int height, std::string& error) const;

  AppState& state() { return state_; }
  Worker& worker() { return worker_; }
  BenchWorker& bench() { return bench_; }
  /// Opens the benchmark set the state names (after a session load), keeping the view the state
  /// names (pair or benchmark); errors go to the status bar.
  void open_benchmark_now();
  const SceneView& scene() const { return scene_; }
  const ParamHistory& param_history() const { return params_; }
  const RunHistory& run_history() const { return runs_; }
  double last_frame_ms() const { return frame_ms_; }
  /// Empty when the configuration is valid, else the reason.
  const std::string& config_error() const { return config_error_; }
  /// Why the results shown do not match the parameters shown (empty when they do).
  const std::string& stale_reason() const { return stale_reason_; }

 private:
  void handle_shortcuts();
  bool bench_busy() const;
  void layout_windows(const WorkerStatus& status, float width, float height);
  void left_panel(float left, float height);
  void pair_view(float x, float width, float height);
  std::string scene_title() const;
  void help_overlay(float width, float height);
  void update_staleness(const WorkerStatus& status);
  void write_plot_exports(int width, int height);
  void report_duplicate_ids();
  CameraControl camera_control();

  const Gl& gl_;
  AppState state_;
  Worker worker_;
  BenchWorker bench_;
  struct PlotExport {
    Plot plot;
    std::string path;
  };
  std::vector<PlotExport> plot_exports_;  // rendered at the next frame
  ImGuiRenderer imgui_renderer_;
  SceneView scene_;
  std::shared_ptr<const Snapshot> snapshot_;
  ParamHistory params_;
  RunHistory runs_;
  std::string config_error_, stale_reason_;
  struct KeyPress {
    int key;
    bool ctrl, shift;
  };
  std::vector<KeyPress> keys_;
  InputQueue input_;
  // Frames still to draw after a result or a pass arrived (ImGui fits tables over a few frames).
  static constexpr int kSettleFrames = 3;
  int settle_frames_ = 0;
  std::uint64_t finished_seen_ = 0;
  bool bench_was_busy_ = false;
  double frame_ms_ = 0.0;
  std::uint64_t fit_request_ = 0;  // the data request the camera is to be fitted to (0: any)
  // Files just opened as data, and the worker request that reads them: one the worker fails to
  // read leaves the recent list as one that failed to open at once does.
  std::vector<std::string> opened_paths_;
  std::uint64_t opened_request_ = 0;
  void forget_unreadable(const WorkerStatus& status);
};

}  // namespace pagor::studio
