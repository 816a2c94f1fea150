#pragma once
/// \file studio.hpp
/// One frame of Pagor Studio, the same in the window and headless: lays out the panels, renders
/// the 3D view and ImGui's draw data through the GL table.

#include <memory>
#include <string>

#include "app_state.hpp"
#include "gl.hpp"
#include "imgui_renderer.hpp"
#include "scene_view.hpp"
#include "worker.hpp"

namespace pagor::studio {

class Studio {
 public:
  /// Needs a current GL context and an ImGui context.
  Studio(const Gl& gl, AppState state);
  ~Studio();
  /// Loads the font, builds renderers. False with `error` on failure.
  bool init(std::string& error);

  /// Sends the current data and configuration to the worker.
  void submit_data();
  void submit_config();

  /// Builds and draws one frame of width x height pixels into the default framebuffer.
  void frame(int width, int height);
  /// Reads the default framebuffer and writes a PNG. False with `error` on failure.
  bool screenshot(const std::string& path, int width, int height, std::string& error) const;

  AppState& state() { return state_; }
  Worker& worker() { return worker_; }
  const SceneView& scene() const { return scene_; }
  double last_frame_ms() const { return frame_ms_; }

 private:
  const Gl& gl_;
  AppState state_;
  Worker worker_;
  ImGuiRenderer imgui_renderer_;
  SceneView scene_;
  std::shared_ptr<const Snapshot> snapshot_;
  double frame_ms_ = 0.0;
};

}  // namespace pagor::studio
