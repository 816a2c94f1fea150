#include "render/imgui_renderer.hpp"

#include <cstddef>
#include <cstdint>

#include "render/shader_program.hpp"

namespace pagor::studio {

bool ImGuiRenderer::init(const Gl& gl, std::string& error) {
  gl_ = &gl;
  program_ = build_program(gl, "imgui.vert", "imgui.frag", error);
  if (!program_) return false;
  u_projection_ = gl.GetUniformLocation(program_, "u_projection");
  u_texture_ = gl.GetUniformLocation(program_, "u_texture");

  gl.GenVertexArrays(1, &vao_);
  gl.GenBuffers(1, &vbo_);
  gl.GenBuffers(1, &ebo_);
  gl.BindVertexArray(vao_);
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo_);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
  gl.EnableVertexAttribArray(0);
  gl.EnableVertexAttribArray(1);
  gl.EnableVertexAttribArray(2);
  const auto stride = static_cast<GLsizei>(sizeof(ImDrawVert));
  gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<void*>(offsetof(ImDrawVert, pos)));
  gl.VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<void*>(offsetof(ImDrawVert, uv)));
  gl.VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                         reinterpret_cast<void*>(offsetof(ImDrawVert, col)));
  gl.BindVertexArray(0);

  // Font atlas.
  ImGuiIO& io = ImGui::GetIO();
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  gl.GenTextures(1, &font_texture_);
  gl.BindTexture(GL_TEXTURE_2D, font_texture_);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(font_texture_)));
  io.BackendRendererName = "pagor_gl_table";
  return true;
}

void ImGuiRenderer::render(const ImDrawData* data, int fb_width, int fb_height) {
  if (!data || fb_width <= 0 || fb_height <= 0) return;
  const Gl& gl = *gl_;
  gl.Enable(GL_BLEND);
  gl.BlendEquation(GL_FUNC_ADD);
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.Disable(GL_CULL_FACE);
  gl.Disable(GL_DEPTH_TEST);
  gl.Enable(GL_SCISSOR_TEST);
  gl.Viewport(0, 0, fb_width, fb_height);

  // Orthographic projection of the display rectangle, y down.
  const float L = data->DisplayPos.x, R = data->DisplayPos.x + data->DisplaySize.x;
  const float T = data->DisplayPos.y, B = data->DisplayPos.y + data->DisplaySize.y;
  const float projection[16] = {
      2.0f / (R - L),    0, 0, 0, 0, 2.0f / (T - B), 0, 0, 0, 0, -1, 0, (R + L) / (L - R),
      (T + B) / (B - T), 0, 1};
  gl.UseProgram(program_);
  gl.Uniform1i(u_texture_, 0);
  gl.UniformMatrix4fv(u_projection_, 1, GL_FALSE, projection);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindVertexArray(vao_);
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo_);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);

  const ImVec2 scale = data->FramebufferScale;
  for (int n = 0; n < data->CmdListsCount; ++n) {
    const ImDrawList* list = data->CmdLists[n];
    gl.BufferData(GL_ARRAY_BUFFER,
                  static_cast<GLsizeiptr>(list->VtxBuffer.Size * sizeof(ImDrawVert)),
                  list->VtxBuffer.Data, GL_STREAM_DRAW);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER,
                  static_cast<GLsizeiptr>(list->IdxBuffer.Size * sizeof(ImDrawIdx)),
                  list->IdxBuffer.Data, GL_STREAM_DRAW);
    for (int c = 0; c < list->CmdBuffer.Size; ++c) {
      const ImDrawCmd& cmd = list->CmdBuffer[c];
      if (cmd.UserCallback == kOpaqueBegin || cmd.UserCallback == kOpaqueEnd) {
        if (cmd.UserCallback == kOpaqueBegin)
          gl.Disable(GL_BLEND);
        else
          gl.Enable(GL_BLEND);
        continue;
      }
      if (cmd.UserCallback) {
        cmd.UserCallback(list, &cmd);
        continue;
      }
      const float x0 = (cmd.ClipRect.x - L) * scale.x, y0 = (cmd.ClipRect.y - T) * scale.y;
      const float x1 = (cmd.ClipRect.z - L) * scale.x, y1 = (cmd.ClipRect.w - T) * scale.y;
      if (x1 <= x0 || y1 <= y0) continue;
      gl.Scissor(static_cast<GLint>(x0), static_cast<GLint>(fb_height - y1),
                 static_cast<GLsizei>(x1 - x0), static_cast<GLsizei>(y1 - y0));
      gl.BindTexture(GL_TEXTURE_2D,
                     static_cast<GLuint>(reinterpret_cast<std::intptr_t>(cmd.GetTexID())));
      gl.DrawElements(
          GL_TRIANGLES, static_cast<GLsizei>(cmd.ElemCount),
          sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT,
          reinterpret_cast<void*>(static_cast<std::uintptr_t>(cmd.IdxOffset * sizeof(ImDrawIdx))));
    }
  }
  gl.Disable(GL_SCISSOR_TEST);
  gl.BindVertexArray(0);
  gl.UseProgram(0);
}

void ImGuiRenderer::shutdown() {
  if (!gl_) return;
  gl_->DeleteTextures(1, &font_texture_);
  gl_->DeleteBuffers(1, &vbo_);
  gl_->DeleteBuffers(1, &ebo_);
  gl_->DeleteVertexArrays(1, &vao_);
  gl_->DeleteProgram(program_);
  gl_ = nullptr;
}

}  // namespace pagor::studio
