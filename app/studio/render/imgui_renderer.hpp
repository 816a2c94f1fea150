#pragma once
/// \file imgui_renderer.hpp
/// Draws Dear ImGui's draw data through the studio's GL table: the same path in the window and
/// headless (Debian's ImGui OpenGL3 backend loads libGL through GLX and fails under OSMesa).

#include <imgui.h>

#include <cstdint>
#include <string>

#include "render/gl.hpp"

namespace pagor::studio {

/// Draw-list callbacks the renderer acts on: the commands between kOpaqueBegin and kOpaqueEnd are
/// drawn without blending (an opaque picture, such as the 3D view's texture: the same pixels, and
/// no read of what is under it, which software GL pays for per pixel).
/// `ImGui::GetWindowDrawList()->AddCallback(kOpaqueBegin, nullptr)`.
/// Sentinel values, as ImGui's ImDrawCallback_ResetRenderState: never called, told apart by value.
inline const ImDrawCallback kOpaqueBegin = reinterpret_cast<ImDrawCallback>(std::intptr_t(-16)),
                            kOpaqueEnd = reinterpret_cast<ImDrawCallback>(std::intptr_t(-17));

class ImGuiRenderer {
 public:
  /// Builds the program, buffers and the font atlas texture. Returns false with `error` filled.
  bool init(const Gl& gl, std::string& error);
  /// Draws the frame's draw data into the bound framebuffer of size fb_width x fb_height.
  void render(const ImDrawData* data, int fb_width, int fb_height);
  void shutdown();

 private:
  const Gl* gl_ = nullptr;
  GLuint program_ = 0, vao_ = 0, vbo_ = 0, ebo_ = 0, font_texture_ = 0;
  GLint u_projection_ = -1, u_texture_ = -1;
};

}  // namespace pagor::studio
