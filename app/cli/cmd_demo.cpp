// pagor demo: the main job on whatever data is at hand, with no download.

#include <cstdio>

#include "command.hpp"

namespace pagor::cli {

std::vector<Option> demo_options() {
  return {{"kitti-root", 1, "DIR", "KITTI root (default: ../shared/data/kitti when present)"},
          {"config", 1, "FILE", "configuration JSON"}};
}

int run_demo(const Args& args) {
  const std::string root = args.has("kitti-root") ? args.get("kitti-root") : find_shared_kitti();
  std::vector<std::string> words;
  if (!root.empty()) {
    std::printf("demo: KITTI data at %s, pair 20 -> 30\n\n", root.c_str());
    words = {"--kitti-root", root, "--sequence", "00", "--pair", "20", "30"};
  } else {
    std::printf("demo: no KITTI data found; using the generated synthetic scene (seed 7)\n\n");
    words = {"--synthetic", "7"};
  }
  if (args.has("config")) {
    words.push_back("--config");
    words.push_back(args.get("config"));
  }
  return run_register(Args(words, register_options()));
}

}  // namespace pagor::cli
