#include "widgets/plot_export.hpp"

#include <stb/stb_image_write.h>

#include <algorithm>

#include "render/headless.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/errors.hpp"
#include "render/resources.hpp"

namespace pagor::studio {
namespace {

constexpr float kPlotFontSize = 15.0f;  // [px], as the studio's UI
// Latin-1 (degree sign), Greek (epsilon, mu, sigma) and arrows.
const ImWchar kGlyphs[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2190, 0x21FF, 0};

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::string*>(context);
  out->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

bool load_ui_font(float size, std::string& error) {
  const Resource font = resource("ui_font.ttf");
  ImFontConfig cfg;
  cfg.FontDataOwnedByAtlas = false;
  if (!ImGui::GetIO().Fonts->AddFontFromMemoryTTF(const_cast<unsigned char*>(font.data),
                                                  static_cast<int>(font.size), size, &cfg,
                                                  kGlyphs)) {
    error = "cannot load the embedded UI font";
    return false;
  }
  return true;
}

std::vector<unsigned char> render_plot_rgba(const Gl& gl, ImGuiRenderer& renderer, const Plot& plot,
                                            int width, int height) {
  ImDrawList list(ImGui::GetDrawListSharedData());
  list._ResetForNewFrame();
  list.PushTextureID(ImGui::GetIO().Fonts->TexID);
  list.PushClipRect(ImVec2(0, 0), ImVec2(float(width), float(height)));
  draw_plot(&list, ImVec2(0, 0), ImVec2(float(width), float(height)), plot, kPlotFontSize);
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
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 4);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  // GL rows go bottom-up; PNG rows top-down. Opaque alpha.
  std::vector<unsigned char> rgba(pixels.size());
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(pixels.data() + static_cast<std::size_t>(height - 1 - y) * row, row,
                rgba.data() + y * row);
  for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
  return rgba;
}

void write_png_file(const std::string& path, const std::vector<unsigned char>& rgba, int width,
                    int height) {
  std::string png;
  if (!stbi_write_png_to_func(append_bytes, &png, width, height, 4, rgba.data(), width * 4))
    throw InputError(path + ": cannot encode the PNG");
  write_file_atomic(path, png);
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
  if (!load_ui_font(kPlotFontSize, error)) throw Error(error);
  ImGuiRenderer renderer;
  if (!renderer.init(gl, error)) throw Error(error);
  ImGui::NewFrame();  // sets the frame's font, which the draw list uses
  const std::vector<unsigned char> rgba = render_plot_rgba(gl, renderer, plot, width, height);
  ImGui::EndFrame();
  renderer.shutdown();
  write_png_file(path, rgba, width, height);
}

}  // namespace pagor::studio
