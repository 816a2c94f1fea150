// pagor-studio: the interactive studio (GLFW window) and its headless twin (OSMesa), one code path.

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "common/allocator.hpp"
#include "common/args.hpp"
#include "common/config_args.hpp"
#include "common/outputs.hpp"
#include "common/pair_args.hpp"
#include "pagor/config.hpp"
#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/kitti.hpp"
#include "render/headless.hpp"
#include "studio.hpp"
#include "widgets/timings.hpp"
#include "window_loop.hpp"

namespace pagor::studio {
namespace {

std::vector<cli::Option> studio_options() {
  return cli::joined(
      cli::pair_options(),
      {{
           {"pairs", 1, "FILE", "pairs file to step through"},
           {"correspondences", 1, "FILE",
            "a matcher's correspondences (px py pz qx qy qz [weight [inlier]] per line), as pagor "
            "register --correspondences: alone, or verified on --source/--target"},
           {"session", 1, "FILE", "session JSON (data, parameters, camera, layers, level)"},
           {"headless", 0, "", "render offscreen through OSMesa (no display needed)"},
           {"screenshot", 1, "PNG", "headless: write the rendered UI to this PNG"},
           {"size", 1, "WxH", "image or window size in pixels (default 1280x720)"},
           {"frames", 1, "N", "headless: also time N frames and print the frame time"},
           {"orbit", 0, "",
            "headless, with --frames: turn the camera 3 degrees before each timed frame (the frame "
            "time of an orbit; still frames reuse the last picture of the 3D view)"},
           {"timings", 0, "",
            "headless: show wall-clock times in the picture (hidden by default, so that two "
            "renders "
            "of the same inputs are equal byte for byte)"},
           {"json", 1, "OUT",
            "headless: write the result as pagor register --json does (schema pagor.register/1)"},
           {"timeout", 1, "S",
            "headless: give up waiting for the computation after S seconds (default 600)"},
       },
       cli::config_options_for("default, indoor when the target is a floor plan")});
}

AppState state_from_args(const cli::Args& args) {
  AppState s;
  if (args.has("session")) load_session(args.get("session"), s);
  const auto chosen = cli::pair_source_from_args(args);
  const bool named = chosen.has_value();  // a pair named on the command line
  if (chosen) {
    s.data = *chosen;
    s.have_data = true;
    s.base_dir.clear();  // paths given on the command line are relative to the working directory
  }
  // The benchmark view's KITTI pairs run on the KITTI root the user named, not on the default.
  if (args.has("kitti-root")) s.bench.kitti_root = absolute_path(args.get("kitti-root"));
  if (args.has("correspondences")) {
    if (s.have_data && s.data.kind != PairSource::Kind::files)
      throw cli::UsageError("--correspondences goes alone or with a file pair (--source --target)");
    if (s.data.kind != PairSource::Kind::files) {
      s.data = PairSource();
      s.data.kind = PairSource::Kind::files;
    }
    // Absolute: a session's relative paths are taken from its directory, these from here.
    if (args.has("ground-truth")) s.data.ground_truth = absolute_path(args.get("ground-truth"));
    s.data.correspondences = absolute_path(args.get("correspondences"));
    s.have_data = true;
  }
  if (args.has("pairs")) {
    s.pairs_file = args.get("pairs");
    s.pairs = read_step_pairs(s.pairs_file, resolve_path(s, s.data.kitti_root), s.data.sequence);
    s.pair_index = index_of_pair(s.pairs, resolved_data(s));
    if (!s.have_data) step_pair_index(s, 1);  // no pair named: the first of the file
  }
  // The configuration as pagor register chooses it (floor-plan targets without --config or
  // --preset: the indoor preset; the pair given, else the pairs file's), after the pairs file is
  // read: a car park's manifest opened alone ran its plans under the default classes and stopped
  // on "label scheme 'indoor' has no class 'car'". A session keeps its own unless one is given.
  if (args.has("config") || args.has("preset") || (!args.has("session") && s.have_data)) {
    std::vector<std::string> targets;
    if (named || s.pairs.pairs.empty()) {
      if (s.have_data && s.data.kind == PairSource::Kind::files && !s.data.target.empty())
        targets.push_back(s.data.target);
    } else {
      targets = cli::pair_targets(s.pairs);  // as pagor bench chooses for the file
    }
    cli::ChosenConfig c = cli::config_for_targets(args, targets);
    s.config = std::move(c.config);
    s.preset = std::move(c.preset);
  }
  if (!s.have_data && !args.has("session")) {
    // Nothing asked for: the shared KITTI pair 20 -> 30 when it is there, else the synthetic scene.
    std::error_code ec;
    if (std::filesystem::is_directory("../shared/data/kitti/sequences/00", ec)) {
      s.data.kind = PairSource::Kind::kitti;
      s.data.kitti_root = "../shared/data/kitti";
      s.data.source_frame = 20;
      s.data.target_frame = 30;
    } else {
      s.data.kind = PairSource::Kind::synthetic;
    }
    s.have_data = true;
  }
  if (args.has("size")) {
    int w = 0, h = 0;
    char rest = 0;
    if (std::sscanf(args.get("size").c_str(), "%dx%d%c", &w, &h, &rest) != 2 || w < kMinWidth ||
        h < kMinHeight || w > kMaxSide || h > kMaxSide)
      throw cli::UsageError("--size: expected WxH between " + std::to_string(kMinWidth) + "x" +
                            std::to_string(kMinHeight) + " and " + std::to_string(kMaxSide) + "x" +
                            std::to_string(kMaxSide) + ", got '" + args.get("size") + "'");
    s.width = w;
    s.height = h;
  }
  return s;
}

// A stage cannot be interrupted midway, and the workers' destructors would wait for the one
// running: on a timeout the headless run says why at once and exits without waiting for it.
[[noreturn]] void give_up(const std::string& message) {
  std::fprintf(stderr, "\r%-60s\rpagor-studio: error: %s\n", "", message.c_str());
  std::fflush(stdout);
  std::fflush(stderr);
  std::_Exit(1);
}

int run_headless(const cli::Args& args, AppState state) {
  if (!args.has("screenshot") && !args.has("frames") && !args.has("json"))
    throw cli::UsageError("--headless needs --screenshot OUT.png, --json OUT or --frames N");
  if (!state.have_data) throw Error("nothing to show: the session and the arguments name no data");
  if (args.has("screenshot")) {  // the picture never replaces an input
    std::vector<cli::NamedPath> inputs = cli::option_inputs(args);
    for (const auto& [what, path] : {std::pair{"the source", state.data.source},
                                     {"the target", state.data.target},
                                     {"the source labels", state.data.source_labels},
                                     {"the target labels", state.data.target_labels},
                                     {"the ground truth", state.data.ground_truth},
                                     {"the correspondences", state.data.correspondences}})
      if (!path.empty()) inputs.push_back({what, resolve_path(state, path)});
    cli::check_outputs({{"--screenshot", args.get("screenshot")}}, inputs);
  }
  const int w = state.width, h = state.height;
  ui::set_timings_shown(args.has("timings"));
  HeadlessContext context(w, h);
  Gl gl;
  std::string error;
  if (!gl.load(HeadlessContext::proc, error)) throw Error(error);
  ImGui::CreateContext();
  struct ImGuiGuard {
    ~ImGuiGuard() { ImGui::DestroyContext(); }
  } guard;
  Studio studio(gl, std::move(state));
  if (!studio.init(error)) throw Error(error);
  studio.submit_data();
  if (studio.state().bench.open) studio.open_benchmark_now();
  const double timeout =
      args.has("timeout") ? cli::parse_int(args.get("timeout"), "--timeout") : 600;
  // Wait for the pipeline, with a progress line on stderr, never past the timeout.
  const auto t0 = std::chrono::steady_clock::now();
  const auto wait = [&] {
    const double left =
        timeout - std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return std::clamp(left, 0.0, 0.5);
  };
  while (!studio.worker().wait_idle(wait())) {
    const WorkerStatus st = studio.worker().status();
    std::fprintf(stderr, "\r%-60s",
                 (st.activity + " " + std::to_string(int(st.fraction * 100)) + " %").c_str());
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > timeout)
      give_up("the computation did not finish within " + std::to_string(int(timeout)) +
              " s (--timeout)");
  }
  while (!studio.bench().wait_idle(wait())) {  // the benchmark view's pairs, when one is open
    const BenchStatus st = studio.bench().status();
    std::fprintf(stderr, "\rbenchmark: %-60s", progress_text(st.pass_progress()).c_str());
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > timeout)
      give_up("the benchmark did not finish within " + std::to_string(int(timeout)) +
              " s (--timeout)");
  }
  std::fprintf(stderr, "\r%-60s\r", "");
  // A picture of a failed run is no result: say why and exit non-zero.
  if (!studio.worker().status().error.empty()) throw Error(studio.worker().status().error);
  if (!studio.worker().snapshot()) throw Error("the run produced no result");
  // A few frames: ImGui sizes auto-fitted items over the first frames.
  for (int i = 0; i < 3; ++i) studio.frame(w, h);
  if (args.has("screenshot")) {
    if (!studio.screenshot(args.get("screenshot"), w, h, error)) throw Error(error);
    std::printf("wrote %s (%dx%d, %s)\n", args.get("screenshot").c_str(), w, h,
                gl.describe().c_str());
  }
  if (args.has("json")) {  // what the studio shows, in the CLI's schema
    write_file_atomic(args.get("json"), studio.worker().snapshot()->report_json);
    std::printf("wrote %s\n", args.get("json").c_str());
  }
  if (args.has("frames")) {
    const int n = std::max(1, cli::parse_int(args.get("frames"), "--frames"));
    const int uploads = studio.scene().cloud_uploads();
    const int renders = studio.scene().renders(), thinned = studio.scene().thinned_renders();
    std::vector<double> ms;
    for (int i = 0; i < n; ++i) {
      if (args.has("orbit")) studio.state().camera.yaw_deg += 3.0f;
      studio.frame(w, h);
      ms.push_back(studio.last_frame_ms());
    }
    std::sort(ms.begin(), ms.end());
    std::printf(
        "frame time at %dx%d over %d frames%s: median %.1f ms, min %.1f ms, max %.1f ms; "
        "cloud uploads during them: %d; 3D view drawn %d times (%d thinned)\n",
        w, h, n, args.has("orbit") ? " (orbit)" : "", ms[ms.size() / 2], ms.front(), ms.back(),
        studio.scene().cloud_uploads() - uploads, studio.scene().renders() - renders,
        studio.scene().thinned_renders() - thinned);
  }
  return 0;
}

}  // namespace
}  // namespace pagor::studio

int main(int argc, char** argv) {
  using namespace pagor;
  app::keep_freed_memory();
  const std::vector<std::string> words(argv + 1, argv + argc);
  const auto options = studio::studio_options();
  for (const auto& w : words)
    if (w == "--help" || w == "-h") {
      std::printf(
          "usage: pagor-studio [data] [--session S.json] [--headless --screenshot "
          "OUT.png]\n\noptions:\n%s",
          cli::format_options(options).c_str());
      return 0;
    }
  // A file-size limit makes a write fail with an error (the old file kept), not kill the process.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    const cli::Args args(words, options);
    studio::AppState state = studio::state_from_args(args);
    return args.has("headless") ? studio::run_headless(args, std::move(state))
                                : studio::run_window(std::move(state));
  } catch (const cli::UsageError& e) {
    std::fprintf(stderr, "pagor-studio: usage error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pagor-studio: error: %s\n", e.what());
    return 1;
  }
}
