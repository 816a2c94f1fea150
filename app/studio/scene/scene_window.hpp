#pragma once
/// \file scene_window.hpp
/// The 3D view's window: the scene image, camera input (orbit, pan, zoom), hover tooltips over
/// landmarks and correspondence lines, and the legends.

#include <cstdint>

#include "runners/worker.hpp"
#include "scene/scene_view.hpp"
#include "state/app_state.hpp"
#include "state/camera.hpp"

namespace pagor::studio {

/// The camera as the View panel, the 3D view and the shortcuts move it.
struct CameraControl {
  Camera& camera;
  bool& fitted;  ///< cleared: fit the camera to everything shown at the next frame
  /// The fit waits for the result of this worker request (newly opened data), so that the camera
  /// frames the new data, not the result still shown before it arrives; 0: fit what is shown.
  std::uint64_t fit_request = 0;
  /// Back to the default camera, keeping top-down, and fitted at the next frame.
  void reset() const;
};

/// Renders `snapshot` (null: nothing yet) through `scene` into the current window's free area,
/// draws the overlays, and handles camera input, hover and picking: a click picks the point
/// under the mouse into `picks` (Shift+click adds a second one to measure to; a click on nothing
/// clears them).
void scene_window(SceneView& scene, const Snapshot* snapshot, const ViewState& view,
                  CameraControl camera, std::vector<Pick>& picks);

/// The transform the source cloud is drawn under, per `view.pose`.
Transform shown_source_pose(const ViewState& view, const Snapshot& snapshot);

}  // namespace pagor::studio
