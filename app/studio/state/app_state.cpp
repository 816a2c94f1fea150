// The state's pairs to step through, the reference configuration and the recent files.

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"
#include "state/app_state.hpp"
#include "state/open_file.hpp"

namespace pagor::studio {
namespace {

constexpr std::size_t kMaxRecent = 12;

// The same file, though written differently (relative, through a symbolic link).
bool same_file(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  std::error_code ec;
  const bool same = std::filesystem::equivalent(a, b, ec);
  return ec ? absolute_path(a) == absolute_path(b) : same;
}

std::string resolve(const std::string& path, const std::filesystem::path& base) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (base / path).lexically_normal().string();
}

}  // namespace

bool is_indoor(const PairSource& data) {
  return data.kind == PairSource::Kind::files && is_floor_plan_path(data.target);
}

std::string resolve_path(const std::string& base_dir, const std::string& path) {
  return resolve(path, std::filesystem::path(base_dir));
}

std::string resolve_path(const AppState& s, const std::string& path) {
  return resolve_path(s.base_dir, path);
}

BenchPanelState bench_panel_state(AppState& s) {
  return {s.bench, s.config, s.preset, s.search.sweep, s.main_view, s.base_dir};
}

PairSource resolved_data(const AppState& s) {
  const std::filesystem::path base(s.base_dir);
  PairSource d = s.data;
  // Each kind of data keeps to its own fields: the files of files mode (a ground-truth file above
  // all) must not replace what a KITTI pair or the synthetic scene knows.
  if (d.kind != PairSource::Kind::files)
    d.source = d.source_labels = d.target = d.target_labels = d.ground_truth = d.correspondences =
        "";
  if (d.kind != PairSource::Kind::kitti) d.kitti_root = "";
  for (std::string* p : {&d.kitti_root, &d.source, &d.source_labels, &d.target, &d.target_labels,
                         &d.ground_truth, &d.correspondences})
    *p = resolve(*p, base);
  return d;
}

int shown_level(const ViewState& view, int selected, int levels) {
  if (view.level >= 0 && view.level < levels) return view.level;
  return selected < levels ? selected : -1;
}

PairSet read_step_pairs(const std::string& path, const std::string& kitti_root,
                        const std::string& sequence) {
  if (!is_kitti_pairs_file(path)) return read_pair_manifest(path);
  try {
    return kitti_pair_set(kitti_root, sequence, path);  // an empty root: the current directory
  } catch (const InputError& e) {
    if (!kitti_root.empty()) throw;
    throw InputError(std::string(e.what()) + " (" + path +
                     " is a KITTI pairs file: it needs the KITTI root, set under KITTI in the "
                     "data panel, or the studio started in that root)");
  }
}

int index_of_pair(const PairSet& pairs, const PairSource& data) {
  for (std::size_t i = 0; i < pairs.pairs.size(); ++i) {
    const PairSource& e = pairs.pairs[i].source;
    if (e.kind != data.kind) continue;
    const bool same =
        e.kind == PairSource::Kind::kitti
            ? e.source_frame == data.source_frame && e.target_frame == data.target_frame
            : same_file(e.source, data.source) && same_file(e.target, data.target);
    if (same) return static_cast<int>(i);
  }
  return -1;
}

std::string absolute_path(const std::string& path) {
  if (path.empty()) return path;
  std::error_code ec;
  const auto p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

void show_pair(AppState& state, const PairEntry& entry) {
  PairSource d = entry.source;
  for (std::string* p :
       {&d.source, &d.target, &d.source_labels, &d.target_labels, &d.ground_truth, &d.kitti_root})
    *p = absolute_path(*p);
  state.data = d;
  state.inline_truth.reset();
  state.have_data = true;
  state.camera_fitted = false;
  state.view.level = -1;
  state.picks.clear();
  state.main_view = MainView::pair;
}

bool step_pair_index(AppState& state, int delta) {
  const int n = static_cast<int>(state.pairs.pairs.size());
  if (n == 0) return false;
  state.pair_index = state.pair_index < 0 ? 0 : std::clamp(state.pair_index + delta, 0, n - 1);
  show_pair(state, state.pairs.pairs[static_cast<std::size_t>(state.pair_index)]);
  return true;
}

namespace {

void save_recent_files(const AppState& state) {
  if (state.recent_file.empty()) return;
  std::string text;
  for (const std::string& f : state.recent) text += f + "\n";
  try {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(state.recent_file).parent_path(), ec);
    write_file_atomic(state.recent_file, text);
  } catch (const Error&) {
  }
}

}  // namespace

void remember_file(AppState& state, const std::string& path) {
  const std::string p = absolute_path(path);
  auto& r = state.recent;
  r.erase(std::remove(r.begin(), r.end(), p), r.end());
  r.insert(r.begin(), p);
  if (r.size() > kMaxRecent) r.resize(kMaxRecent);
  save_recent_files(state);
}

bool forget_file(AppState& state, const std::string& path) {
  const std::string p = absolute_path(path);
  auto& r = state.recent;
  const auto end = std::remove(r.begin(), r.end(), p);
  if (end == r.end()) return false;
  r.erase(end, r.end());
  save_recent_files(state);
  return true;
}

void load_recent_files(AppState& state) {
  state.recent.clear();
  std::ifstream in(state.recent_file);
  std::string line;
  while (std::getline(in, line) && state.recent.size() < kMaxRecent)
    if (!line.empty()) state.recent.push_back(line);
}

}  // namespace pagor::studio
