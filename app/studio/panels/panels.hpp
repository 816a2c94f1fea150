#pragma once
/// \file panels.hpp
/// The studio's panels. Each draws from and edits the app state; none runs an algorithm (changes
/// go to the worker through `UiContext::submit_*`).

#include <functional>
#include <memory>

#include "state/app_state.hpp"
#include "state/history.hpp"
#include "scene/scene_view.hpp"
#include "runners/worker.hpp"

namespace pagor::studio {

class BenchWorker;
struct Plot;

/// What a panel may read and do during one frame.
struct UiContext {
  AppState& state;
  const Snapshot* snapshot;  ///< latest results (may be null)
  const WorkerStatus& status;
  std::function<void()> submit_data;    ///< open state.data (and the current config)
  std::function<void()> submit_config;  ///< re-run with state.config
  SceneView& scene;
  double frame_ms = 0.0;     ///< last frame's time
  std::string config_error;  ///< why state.config is invalid (empty when valid)
  std::string stale_reason;  ///< why the results shown are not those of state.config (or empty)
  const RunHistory* runs = nullptr;
  const ParamHistory* params = nullptr;
  std::function<void()> undo, redo;
  std::function<void()> save_session, load_session;  ///< state.session_path
  BenchWorker* bench = nullptr;                      ///< the benchmark view's runner
  /// Writes a plot as PNG (rendered by the studio at the next frame) at the given path.
  std::function<void(const Plot&, const std::string&)> export_plot;
};

/// Moves through the pairs file by `delta` (clamped) and opens that pair.
void step_pair(UiContext& ui, int delta);
/// The range the epsilon sliders span for a TRIM kind (fixed, log scale).
std::pair<double, double> epsilon_range(TrimKind trim);

void data_panel(UiContext& ui);
/// For indoor data or sets (`indoor`) run with parameters of another kind: a line saying so and a
/// button that applies the `indoor` preset. Nothing otherwise.
void indoor_preset_hint(UiContext& ui, bool indoor, const char* id);
void parameters_panel(UiContext& ui);
void view_panel(UiContext& ui);
void session_panel(UiContext& ui);
/// Undo/redo and the last runs with their outcome.
void history_panel(UiContext& ui);
void pyramid_panel(UiContext& ui);
/// The diagnosis against the ground truth (diagnosis_panel.cpp) and the 3D view's diagnosis items.
void diagnosis_panel(UiContext& ui);
/// Radio buttons choosing what the bottom panel shows: the pyramid or the diagnosis (the panel's
/// first line continues on their line).
void bottom_panel_switch(UiContext& ui);
void status_bar(UiContext& ui);
/// The benchmark view: the open pairs set, its table, rates and plots, and sweeps.
void benchmark_view(UiContext& ui);
/// The 3D view: renders the scene into its framebuffer, shows it, handles camera input and hover.
void scene_window(UiContext& ui);

/// The transform the source cloud is drawn under, per `view.pose`.
Transform shown_source_pose(const AppState& state, const Snapshot& snapshot);

}  // namespace pagor::studio
