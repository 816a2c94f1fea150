#include "common/outputs.hpp"

#include <cstdio>
#include <filesystem>

namespace pagor::cli {
namespace fs = std::filesystem;
namespace {

// Whether two paths name the same file: the same inode when both exist, else the same path
// once "." , ".." and symbolic links of the existing part are resolved.
bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
  const fs::path ca = fs::weakly_canonical(a, ec);
  if (ec) return false;
  const fs::path cb = fs::weakly_canonical(b, ec);
  return !ec && ca == cb;
}

}  // namespace

std::vector<NamedPath> option_inputs(const Args& args) {
  std::vector<NamedPath> in;
  for (const char* option : {"source", "target", "source-labels", "target-labels", "ground-truth",
                             "config", "correspondences", "manifest", "pairs", "session"})
    if (args.has(option) && !args.get(option).empty())
      in.push_back({std::string("--") + option, args.get(option)});
  return in;
}

std::vector<NamedPath> set_inputs(const PairSet& set) {
  std::vector<NamedPath> in;
  for (const PairEntry& e : set.pairs) {
    const PairSource& s = e.source;
    const std::string pair = "pair " + e.name + "'s ";
    if (s.kind == PairSource::Kind::kitti) {
      const fs::path dir = fs::path(s.kitti_root) / "sequences" / s.sequence;
      char frame[2][16];
      std::snprintf(frame[0], sizeof(frame[0]), "%06d", s.source_frame);
      std::snprintf(frame[1], sizeof(frame[1]), "%06d", s.target_frame);
      for (const char* f : frame) {
        in.push_back({pair + "scan", (dir / "velodyne" / (std::string(f) + ".bin")).string()});
        in.push_back({pair + "labels", (dir / "labels" / (std::string(f) + ".label")).string()});
      }
      in.push_back({"the poses", (dir / "poses.txt").string()});
      in.push_back({"the calibration", (dir / "calib.txt").string()});
    }
    for (const auto& [role, path] : {std::pair{"source", &s.source},
                                     {"target", &s.target},
                                     {"source labels", &s.source_labels},
                                     {"target labels", &s.target_labels},
                                     {"ground truth", &s.ground_truth}})
      if (!path->empty()) in.push_back({pair + role, *path});
  }
  return in;
}

void check_outputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& out = outputs[i];
    for (const NamedPath& in : inputs)
      if (same_file(out.path, in.path))
        throw UsageError(out.what + " " + out.path + " is also an input (" + in.what + " " +
                         in.path + "); writing it would destroy it: choose another file");
    for (std::size_t k = 0; k < i; ++k)
      if (same_file(out.path, outputs[k].path))
        throw UsageError(out.what + " " + out.path + " is also " + outputs[k].what +
                         "; each output needs its own file");
  }
}

}  // namespace pagor::cli
