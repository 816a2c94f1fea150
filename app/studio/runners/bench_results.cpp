// What the benchmark view reads from finished work: whether a sweep still matches the
// parameters and the set, the pairs that flipped between two of its settings, and the pair a row
// of results names.

#include <algorithm>
#include <filesystem>

#include "pagor/errors.hpp"
#include "runners/bench_worker.hpp"

namespace pagor::studio {

std::string sweep_stale_reason(const SweepRecord& record, const Config& config,
                               std::uint64_t set_generation) {
  if (record.set != set_generation) return "another pair set was opened since this sweep";
  // The swept parameters may differ ("apply" sets them); everything else must be the base's.
  std::vector<std::pair<std::string, std::string>> base_values;
  if (!record.result.settings.empty())
    for (const auto& [path, value] : record.result.settings.front().setting.values)
      base_values.push_back({path, field_json(record.base, path)});
  Config c = config;
  try {
    set_fields_json(c, base_values);
  } catch (const ConfigError&) {
    return "the parameters changed since this sweep";
  }
  if (config_to_json(c, -1) != config_to_json(record.base, -1))
    return "parameters other than the swept ones changed since this sweep";
  return {};
}

std::vector<std::size_t> flipped_pairs(const SweepResult& result, std::size_t a, std::size_t b) {
  std::vector<std::size_t> out;
  if (a >= result.settings.size() || b >= result.settings.size()) return out;
  const auto& x = result.settings[a].outcomes;
  const auto& y = result.settings[b].outcomes;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i)
    if (x[i].success != y[i].success || x[i].accepted != y[i].accepted ||
        x[i].diagnosis != y[i].diagnosis || x[i].loaded != y[i].loaded)
      out.push_back(i);
  return out;
}

namespace {

// A path a results file names: as written when it exists from here, else beside the file.
std::string beside_results(const std::string& path, const std::string& file) {
  const std::filesystem::path p(path);
  std::error_code ec;
  if (p.is_absolute() || std::filesystem::exists(p, ec)) return path;
  return (std::filesystem::path(file).parent_path() / p).string();
}

// A KITTI scan's path, sequences/SS/velodyne/NNNNNN.bin: its root, sequence and frame.
bool kitti_scan(const std::string& path, std::string& root, std::string& sequence, int& frame) {
  const std::filesystem::path p(path);
  if (p.extension() != ".bin" || p.parent_path().filename() != "velodyne") return false;
  const std::filesystem::path seq = p.parent_path().parent_path();
  if (seq.parent_path().filename() != "sequences") return false;
  const std::string stem = p.stem().string();
  if (stem.empty() || stem.find_first_not_of("0123456789") != std::string::npos) return false;
  root = seq.parent_path().parent_path().string();
  sequence = seq.filename().string();
  frame = std::stoi(stem);
  return true;
}

}  // namespace

std::optional<PairEntry> result_pair(const PairOutcome& o, const std::string& results_file) {
  PairEntry e;
  e.name = o.name;
  e.negative = o.negative;
  e.origin = results_file;
  const std::string source = beside_results(o.source_name, results_file);
  const std::string target = beside_results(o.target_name, results_file);
  std::string root, root2, seq, seq2;
  int a = 0, b = 0;
  if (kitti_scan(source, root, seq, a) && kitti_scan(target, root2, seq2, b) && root == root2 &&
      seq == seq2) {
    e.source.kind = PairSource::Kind::kitti;
    e.source.kitti_root = root;
    e.source.sequence = seq;
    e.source.source_frame = a;
    e.source.target_frame = b;
    return e;
  }
  std::error_code ec;
  if (!std::filesystem::exists(source, ec) || !std::filesystem::exists(target, ec))
    return std::nullopt;
  e.source.kind = PairSource::Kind::files;
  e.source.source = source;
  e.source.target = target;
  return e;
}

}  // namespace pagor::studio
