#include "widgets/plot_export.hpp"

#include "pagor/errors.hpp"
#include "render/headless.hpp"
#include "render/png.hpp"
#include "render/ui_font.hpp"

namespace pagor::studio {
void render_plot(const Gl& gl, ImGuiRenderer& renderer, const Plot& plot, int width, int height) {
  ImDrawList list(ImGui::GetDrawListSharedData());
  list._ResetForNewFrame();
  list.PushTextureID(ImGui::GetIO().Fonts->TexID);
  list.PushClipRect(ImVec2(0, 0), ImVec2(float(width), float(height)));
  draw_plot(&list, ImVec2(0, 0), ImVec2(float(width), float(height)), plot, kUiFontSize);
  ImDrawList* lists[] = {&list};
  ImDrawData data;
  data.Valid = true;
  data.CmdLists = lists;
  data.CmdListsCount = 1;
  data.TotalVtxCount = list.VtxBuffer.Size;
  data.TotalIdxCount = list.IdxBuffer.Size;
  data.DisplayPos = ImVec2(0, 0);
  data.DisplaySize = ImVec2(float(width), float(height));
  data.FramebufferScale = ImVec2(1, 1);

  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.Viewport(0, 0, width, height);
  gl.ClearColor(0, 0, 0, 1);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  renderer.render(&data, width, height);
  gl.Finish();
}

void export_plot_png(const Plot& plot, const std::string& path, int width, int height) {
  HeadlessContext context(width, height);
  Gl gl;
  std::string error;
  if (!gl.load(HeadlessContext::proc, error)) throw Error(error);
  ImGuiContext* previous = ImGui::GetCurrentContext();
  ImGuiContext* own = ImGui::CreateContext();
  struct Restore {
    ImGuiContext *own, *previous;
    ~Restore() {
      ImGui::DestroyContext(own);
      if (previous) ImGui::SetCurrentContext(previous);
    }
  } restore{own, previous};
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::GetIO().DisplaySize = ImVec2(float(width), float(height));
  if (!load_ui_font(kUiFontSize, error)) throw Error(error);
  ImGuiRenderer renderer;
  if (!renderer.init(gl, error)) throw Error(error);
  ImGui::NewFrame();  // sets the frame's font, which the draw list uses
  render_plot(gl, renderer, plot, width, height);
  const std::vector<unsigned char> rgba = read_framebuffer_rgba(gl, width, height);
  ImGui::EndFrame();
  renderer.shutdown();
  write_png(path, rgba, width, height);
}

}  // namespace pagor::studio
