#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "command.hpp"
#include "pagor/errors.hpp"
#include "pagor/eval/synthetic.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/kitti.hpp"

namespace pagor::cli {

Option threads_option() {
  return {"threads", 1, "N",
          "threads inside a pair: loading, landmarks, matching, graph, verification, acceptance "
          "(default 1)"};
}

std::vector<Option> single_cloud_options() {
  return {
      {"source", 1, "FILE", "cloud to read (.bin, .pcd, .ply)"},
      {"source-labels", 1, "FILE", "SemanticKITTI .label file for --source"},
      kitti_root_option("instead of --source"),
      sequence_option(),
      {"frame", 1, "N", "KITTI frame number"},
      {"synthetic", 1, "SEED", "use the generated scene's source scan (instead of --source)"},
  };
}

LoadedCloud load_single_cloud(const Args& args, std::string& name) {
  const int chosen = args.has("source") + args.has("kitti-root") + args.has("synthetic");
  if (chosen != 1)
    throw UsageError(
        "choose exactly one input: --source FILE, --kitti-root DIR --frame N, "
        "or --synthetic SEED");
  if (args.has("source")) {
    name = args.get("source");
    return load_cloud(name, args.get("source-labels"));
  }
  if (args.has("source-labels")) throw UsageError("--source-labels goes with --source");
  if (args.has("kitti-root")) {
    if (!args.has("frame")) throw UsageError("--kitti-root needs --frame N");
    const KittiSequence seq(args.get("kitti-root"), sequence_from_args(args));
    const int frame = args.get_int("frame", 0);
    name = seq.scan_path(frame);
    return seq.load_frame(frame);
  }
  SyntheticParams p;
  p.seed = static_cast<std::uint64_t>(parse_int(args.get("synthetic"), "--synthetic"));
  name = "synthetic scene (seed " + std::to_string(p.seed) + "), source scan";
  LoadedCloud out;
  out.cloud = make_synthetic_scene(p).source;
  return out;
}

void with_config_origin(const Args& args, const std::function<void()>& stage) {
  try {
    stage();
  } catch (const ConfigError& e) {
    throw ConfigError((args.has("config") ? args.get("config") : "built-in defaults") + ": " +
                      e.what());
  }
}

void warn(const std::string& message) {
  std::cerr << "pagor: warning: " << message << "\n";
}

void warn_all(const std::vector<std::string>& warnings, bool verbose) {
  std::vector<std::string> benign;
  for (const std::string& w : warnings) {
    if (!verbose && w.find(" points but no landmark") != std::string::npos)
      benign.push_back(w.substr(0, w.find(" points but no landmark")));
    else
      warn(w);
  }
  if (benign.empty()) return;
  std::string list;
  for (const std::string& b : benign) list += (list.empty() ? "" : "; ") + b;
  std::cerr << "pagor: note: " << benign.size()
            << (benign.size() == 1 ? " class has" : " classes have") << " points but no landmark ("
            << list << " points); --verbose for the details\n";
}

void write_text_file(const std::string& path, const std::string& text) {
  write_file_atomic(path, text);
}

std::string find_shared_kitti() {
  for (const char* candidate :
       {"../shared/data/kitti", "../../shared/data/kitti", "shared/data/kitti"}) {
    std::error_code ec;
    if (std::filesystem::is_directory(std::filesystem::path(candidate) / "sequences", ec))
      return candidate;
  }
  return {};
}

}  // namespace pagor::cli
