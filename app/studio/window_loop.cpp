#include "window_loop.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "pagor/errors.hpp"
#include "studio.hpp"

namespace pagor::studio {
namespace {

// Frames drawn after the last input event: ImGui settles hover, layout and a click's effect over
// the frames after it.
constexpr int kSettleFrames = 3;
// While a run or the benchmark is in progress: the progress bar's refresh period [s].
constexpr double kBusyPeriod = 0.1;
// Idle: the longest wait for an event before looking at the workers again [s].
constexpr double kIdleWait = 0.5;

Studio* g_studio = nullptr;
unsigned long g_events = 0;  // input and window events seen: a frame is due when it moves

void* glfw_proc(const char* name) {
  return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

// Where the window keeps its recent files: $XDG_CONFIG_HOME/pagor-studio/recent.txt (else
// ~/.config/...); empty without a home.
std::string recent_files_path() {
  if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x)
    return std::string(x) + "/pagor-studio/recent.txt";
  if (const char* h = std::getenv("HOME"); h && *h)
    return std::string(h) + "/.config/pagor-studio/recent.txt";
  return {};
}

// Keys and characters go to the studio's queue (not ImGui's backend, which would set key states
// at once: a tap between two frames, or a chord's order, would be lost); the mouse goes through
// the backend. Installed after the backend's, replacing its key and character callbacks.
void install_callbacks(GLFWwindow* window) {
  glfwSetKeyCallback(window, [](GLFWwindow*, int key, int, int action, int) {
    ++g_events;
    if (g_studio && action != GLFW_REPEAT) g_studio->input().key(key, action == GLFW_PRESS);
  });
  glfwSetCharCallback(window, [](GLFWwindow*, unsigned int c) {
    ++g_events;
    if (g_studio) g_studio->input().character(c);
  });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) {
    ++g_events;
    ImGui_ImplGlfw_MouseButtonCallback(w, button, action, mods);
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double x, double y) {
    ++g_events;
    ImGui_ImplGlfw_ScrollCallback(w, x, y);
  });
  glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int entered) {
    ++g_events;
    ImGui_ImplGlfw_CursorEnterCallback(w, entered);
  });
  glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int focused) {
    ++g_events;
    ImGui_ImplGlfw_WindowFocusCallback(w, focused);
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow*, double, double) { ++g_events; });
  glfwSetWindowRefreshCallback(window, [](GLFWwindow*) { ++g_events; });
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow*, int, int) { ++g_events; });
  // Files dropped on the window are opened by their kind.
  glfwSetDropCallback(window, [](GLFWwindow*, int count, const char** paths) {
    ++g_events;
    if (g_studio) g_studio->open_files(std::vector<std::string>(paths, paths + count));
  });
}

// Renders on events and while work is pending: input draws kSettleFrames frames, a run in
// progress redraws its progress every kBusyPeriod, and an idle window sleeps in glfwWaitEvents.
void event_loop(GLFWwindow* window, Studio& studio) {
  int settle = kSettleFrames;  // the first frames
  unsigned long seen = g_events;
  while (!glfwWindowShouldClose(window)) {
    const bool work = studio.wants_frame();
    if (settle > 0 || studio.input().pending())
      glfwPollEvents();
    else
      glfwWaitEventsTimeout(work ? kBusyPeriod : kIdleWait);
    if (g_events != seen) settle = kSettleFrames;
    seen = g_events;
    if (settle == 0 && !work && !studio.input().pending()) continue;  // nothing to draw
    settle = settle > 0 ? settle - 1 : 0;
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    if (w <= 0 || h <= 0) continue;
    ImGui_ImplGlfw_NewFrame();
    studio.frame(w, h);
    glfwSwapBuffers(window);
  }
}

}  // namespace

int run_window(AppState state) {
  glfwSetErrorCallback(
      [](int code, const char* text) { std::fprintf(stderr, "GLFW error %d: %s\n", code, text); });
  if (!glfwInit()) throw Error("cannot initialise GLFW (no display? use --headless)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  GLFWwindow* window =
      glfwCreateWindow(state.width, state.height, "Pagor Studio", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    throw Error("cannot open a window with OpenGL 3.3 core");
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  Gl gl;
  std::string error;
  if (!gl.load(glfw_proc, error)) throw Error(error);
  ImGui::CreateContext();
  ImGui_ImplGlfw_InitForOpenGL(window, true);  // platform: mouse, time, cursor, clipboard
  install_callbacks(window);
  {
    state.recent_file = recent_files_path();
    load_recent_files(state);
    Studio studio(gl, std::move(state));
    g_studio = &studio;
    struct Reset {
      ~Reset() { g_studio = nullptr; }
    } reset;
    if (!studio.init(error)) throw Error(error);
    studio.submit_data();
    if (studio.state().bench.open) studio.open_benchmark_now();
    event_loop(window, studio);
  }
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return 0;
}

}  // namespace pagor::studio
