#pragma once
/// \file panels.hpp
/// The studio's panels. Each draws from and edits the app state; none runs an algorithm (changes
/// go to the worker through `UiContext::submit_*`).

#include <functional>
#include <memory>

#include "app_state.hpp"
#include "scene_view.hpp"
#include "worker.hpp"

namespace pagor::studio {

/// What a panel may read and do during one frame.
struct UiContext {
  AppState& state;
  const Snapshot* snapshot;  ///< latest results (may be null)
  const WorkerStatus& status;
  std::function<void()> submit_data;    ///< open state.data (and the current config)
  std::function<void()> submit_config;  ///< re-run with state.config
  SceneView& scene;
  double frame_ms = 0.0;  ///< last frame's time
};

void data_panel(UiContext& ui);
void parameters_panel(UiContext& ui);
void view_panel(UiContext& ui);
void session_panel(UiContext& ui);
void pyramid_panel(UiContext& ui);
void status_bar(UiContext& ui);
/// The 3D view: renders the scene into its framebuffer, shows it, handles camera input and hover.
void scene_window(UiContext& ui);

/// The transform the source cloud is drawn under, per `view.pose`.
Transform shown_source_pose(const AppState& state, const Snapshot& snapshot);

}  // namespace pagor::studio
