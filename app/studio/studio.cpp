#include "studio.hpp"

#include <imgui.h>
#include <stb/stb_image_write.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "panels.hpp"
#include "resources.hpp"

namespace pagor::studio {
namespace {

constexpr float kFontSize = 15.0f;  // [px]
constexpr float kLeftWidth = 320.0f, kStatusHeight = 28.0f;
constexpr float kSceneShare = 0.6f;  // of the height right of the left panel
constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;

// Latin-1 (degree sign), Greek (epsilon, mu, sigma) and arrows.
const ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2190, 0x21FF, 0};

void place(float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
}

}  // namespace

Studio::Studio(const Gl& gl, AppState state) : gl_(gl), state_(std::move(state)) {}

Studio::~Studio() {
  scene_.shutdown();
  imgui_renderer_.shutdown();
}

bool Studio::init(std::string& error) {
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is fixed; sessions hold what matters
  const Resource font = resource("ui_font.ttf");
  ImFontConfig cfg;
  cfg.FontDataOwnedByAtlas = false;
  if (!io.Fonts->AddFontFromMemoryTTF(const_cast<unsigned char*>(font.data),
                                      static_cast<int>(font.size), kFontSize, &cfg, kGlyphRanges)) {
    error = "cannot load the embedded UI font";
    return false;
  }
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 0.0f;
  style.FrameRounding = 3.0f;
  style.ItemSpacing = ImVec2(6, 4);
  return imgui_renderer_.init(gl_, error) && scene_.init(gl_, error);
}

void Studio::submit_data() {
  if (state_.have_data) worker_.submit(resolved_data(state_), state_.config);
}

void Studio::submit_config() {
  worker_.submit(std::nullopt, state_.config);
}

void Studio::frame(int width, int height) {
  const auto t0 = std::chrono::steady_clock::now();
  state_.width = width;
  state_.height = height;
  snapshot_ = worker_.snapshot();
  const WorkerStatus status = worker_.status();

  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  ImGui::NewFrame();
  UiContext ui{
      state_, snapshot_.get(), status, [this] { submit_data(); }, [this] { submit_config(); },
      scene_, frame_ms_};
  const float W = static_cast<float>(width), H = static_cast<float>(height) - kStatusHeight;

  place(0, 0, kLeftWidth, H);
  if (ImGui::Begin("Pagor Studio", nullptr, kPanelFlags)) {
    ImGui::PushItemWidth(-120.0f);  // room for the labels
    if (ImGui::CollapsingHeader("Data", ImGuiTreeNodeFlags_DefaultOpen)) data_panel(ui);
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) parameters_panel(ui);
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) view_panel(ui);
    if (ImGui::CollapsingHeader("Session")) session_panel(ui);
    ImGui::PopItemWidth();
  }
  ImGui::End();

  const float scene_h = std::floor(H * kSceneShare);
  place(kLeftWidth, 0, W - kLeftWidth, scene_h);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  const int level = snapshot_ ? shown_level(state_.view, snapshot_->selected,
                                            static_cast<int>(snapshot_->levels.size()))
                              : -1;
  std::string title = "3D view";
  if (snapshot_)
    title +=
        " | " + snapshot_->description + (level >= 0 ? " | level " + std::to_string(level) : "");
  title += "###scene";
  if (ImGui::Begin(title.c_str(), nullptr,
                   kPanelFlags | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse))
    scene_window(ui);
  ImGui::End();
  ImGui::PopStyleVar();

  place(kLeftWidth, scene_h, W - kLeftWidth, H - scene_h);
  if (ImGui::Begin("Pyramid", nullptr, kPanelFlags)) pyramid_panel(ui);
  ImGui::End();

  place(0, H, W, kStatusHeight);
  if (ImGui::Begin("##status", nullptr,
                   kPanelFlags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar))
    status_bar(ui);
  ImGui::End();

  ImGui::Render();
  gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl_.Viewport(0, 0, width, height);
  gl_.ClearColor(0.08f, 0.08f, 0.09f, 1.0f);
  gl_.Clear(GL_COLOR_BUFFER_BIT);
  imgui_renderer_.render(ImGui::GetDrawData(), width, height);
  gl_.Finish();
  frame_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

bool Studio::screenshot(const std::string& path, int width, int height, std::string& error) const {
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 4);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  // GL rows go bottom-up; PNG rows top-down. Opaque alpha.
  std::vector<unsigned char> flipped(pixels.size());
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(pixels.data() + static_cast<std::size_t>(height - 1 - y) * row, row,
                flipped.data() + y * row);
  for (std::size_t i = 3; i < flipped.size(); i += 4) flipped[i] = 255;
  if (!stbi_write_png(path.c_str(), width, height, 4, flipped.data(), static_cast<int>(row))) {
    error = path + ": cannot write PNG";
    return false;
  }
  return true;
}

}  // namespace pagor::studio
