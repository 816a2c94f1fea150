#pragma once
/// \file panels.hpp
/// The studio's panels. Each draws from and edits the part of the app state it is given; none runs
/// an algorithm (runs, files and messages go through StudioActions). The 3D view's window is in
/// scene/scene_window.hpp.

#include <string>
#include <utility>
#include <vector>

#include "panels/exports.hpp"
#include "panels/studio_actions.hpp"
#include "runners/worker.hpp"
#include "scene/scene_window.hpp"
#include "state/app_state.hpp"
#include "state/history.hpp"

namespace pagor::studio {

class BenchWorker;

/// The files the Session panel names.
struct SessionFiles {
  std::string& session_path;     ///< the session file saved and loaded
  std::string& screenshot_path;  ///< where a screenshot is written (PNG)
  std::string& export_path;      ///< where the pair view's exports go: <export path>-<name>
};

/// Moves through the pairs file or manifest by `delta` (clamped) and opens that pair.
void step_pair(AppState& state, int delta, StudioActions& actions);
/// Opens the file browser for `purpose`, in the directory of `current` (a path the user wrote).
void open_file_dialog(AppState& state, FilePurpose purpose, const std::string& current);
/// The file browser, while `dialog.open`: directories and the files of its purpose; a pick
/// goes to StudioActions::open_file.
void file_dialog(FileDialogState& dialog, StudioActions& actions);
/// The range the epsilon sliders span for a TRIM kind (fixed, log scale).
std::pair<double, double> epsilon_range(TrimKind trim);

/// What data is open: its kind, paths or frames, the pairs file; opening it and the benchmark.
void data_panel(AppState& state, StudioActions& actions);
/// For indoor data or sets (`indoor`) run with parameters of another kind: a line saying so and a
/// button that applies the `indoor` preset to `config`. Nothing otherwise. `id` tells two apart.
void indoor_preset_hint(Config& config, std::string& preset, bool indoor, const char* id,
                        StudioActions& actions);
/// Undo and redo buttons on one line (disabled when there is no step); `id` tells two apart.
void undo_redo_buttons(const ParamHistory& params, StudioActions& actions, const char* id);
/// Every parameter of `config` (re-run on change): the preset it starts from, the label scheme,
/// the pyramid's levels, then every field of the configuration's table (param_editor.hpp); why
/// it is invalid, undo/redo and "defaults" (the preset, keeping the label scheme).
void parameters_panel(Config& config, std::string& preset, std::string& search,
                      const ParamHistory& params, const std::string& config_error,
                      StudioActions& actions);
/// Layers, sizes, colours, the source pose, the camera buttons. `has_plan`: the result has a
/// floor plan (its layer can be toggled).
void view_panel(ViewState& view, CameraControl camera, bool& show_help, bool has_plan);
/// Camera views: "save view" keeps the camera under a name, a click on the name restores it (kept
/// in the session); "copy view" / "paste view" move it through the clipboard as JSON.
void camera_views_panel(std::vector<CameraView>& views, CameraControl camera,
                        StudioActions& actions);
/// The session and screenshot files, with save and load.
void session_panel(SessionFiles files, StudioActions& actions);
/// Undo/redo and the last runs with their outcome.
void history_panel(const ParamHistory& params, const RunHistory& runs, StudioActions& actions);
/// One row per pyramid level of `snapshot` (null: none yet), the candidate details and a bar chart
/// of D; `stale_reason` says why it is not a run of the parameters shown. A row click sets
/// `view.level`.
void pyramid_panel(const Snapshot* snapshot, const RunChanges& changes,
                   const std::string& stale_reason, ViewState& view, const Exports& exports);
/// The diagnosis against the ground truth (diagnosis_panel.cpp) and the 3D view's diagnosis items.
void diagnosis_panel(const Snapshot* snapshot, const std::string& stale_reason, ViewState& view,
                     const Exports& exports);
/// Radio buttons choosing what the bottom panel shows: the pyramid or the diagnosis (the panel's
/// first line continues on their line).
void bottom_panel_switch(DiagnosisView& diagnosis);
/// The worker's progress or the last run's stage times, the frame time, the run's warnings, and
/// the worker's error or else the last message for the user.
void status_bar(const WorkerStatus& status, const Snapshot* snapshot, const Message& message,
                double frame_ms);
/// What the last run computed, for the status bar: "last run 12 ms: graph, clique, ..."; without
/// clouds the stages that had nothing to work on are listed apart as skipped, and verification is
/// named as the selection it was (by S over the correspondences).
std::string run_stages_text(const Snapshot& snapshot);
/// The benchmark view: the open pairs set, its table, rates and plots, and sweeps; a row opens its
/// pair through StudioActions::open_pair.
void benchmark_view(BenchPanelState state, BenchWorker& bench, StudioActions& actions);

}  // namespace pagor::studio
