#include "state/open_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/config_args.hpp"
#include "pagor/errors.hpp"
#include "pagor/indoor/floor_plan.hpp"

namespace pagor::studio {
namespace {

namespace fs = std::filesystem;

std::string lower_extension(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

bool is_number(const std::string& w) {
  char* end = nullptr;
  std::strtod(w.c_str(), &end);
  return !w.empty() && end && *end == '\0';
}

FilePurpose classify_text(const std::string& path) {
  const std::vector<std::string> w = first_words(path);
  const bool numbers = std::all_of(w.begin(), w.end(), is_number);
  if (numbers && w.size() == 2) return FilePurpose::pairs;         // a KITTI pairs file
  if (numbers && w.size() == 4) return FilePurpose::ground_truth;  // a 4x4 matrix, row by row
  if (numbers && (w.size() == 12 || w.size() == 16)) return FilePurpose::ground_truth;
  if (numbers && w.size() >= 6 && w.size() <= 8) return FilePurpose::correspondences;
  if (!numbers && w.size() >= 2) return FilePurpose::pairs;  // a manifest: SOURCE TARGET ...
  throw InputError(path + ": not a pairs file, manifest, correspondences file or 4x4 transform");
}

FilePurpose classify_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  const auto j = nlohmann::json::parse(text.str(), nullptr, false);
  if (!j.is_object()) throw InputError(path + ": not a JSON object");
  const auto str = [&](const char* key) {
    return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
  };
  if (str("schema") == "pagor.session/1") return FilePurpose::session;
  if (str("format") == "pagor.floor_plan/1") return FilePurpose::target_cloud;
  if (str("schema") == "pagor.register/1") return FilePurpose::bench;  // one result line
  return FilePurpose::config;
}

// The cloud a label file belongs to: the one whose file stem it shares (000020.bin and
// 000020.label), else the source when it has none yet.
FilePurpose labels_for(const AppState& s, const std::string& path) {
  const std::string stem = fs::path(path).stem().string();
  if (!s.data.target.empty() && fs::path(s.data.target).stem().string() == stem)
    return FilePurpose::target_labels;
  if (!s.data.source.empty() && fs::path(s.data.source).stem().string() == stem)
    return FilePurpose::source_labels;
  return s.data.source_labels.empty() ? FilePurpose::source_labels : FilePurpose::target_labels;
}

// Files mode, keeping what files mode already names.
PairSource& files_data(AppState& s) {
  if (s.data.kind != PairSource::Kind::files) {
    s.data.kind = PairSource::Kind::files;
    s.data.source = s.data.source_labels = s.data.target = s.data.target_labels = "";
    s.data.ground_truth = s.data.correspondences = "";
  }
  s.inline_truth.reset();
  return s.data;
}

}  // namespace

bool is_kitti_pairs_file(const std::string& path) {
  const std::vector<std::string> w = first_words(path, "the pairs file");
  const auto digits = [](const std::string& s) {
    return std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  };
  return w.size() == 2 && digits(w[0]) && digits(w[1]);
}

std::vector<std::string> first_words(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open " + what);
  std::string line;
  while (std::getline(in, line)) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream s(line);
    std::vector<std::string> words;
    for (std::string w; s >> w;) words.push_back(w);
    if (!words.empty()) return words;
  }
  throw InputError(path + ": " + what + " has nothing but blank lines and comments");
}

bool data_ready(const PairSource& d) {
  return d.kind != PairSource::Kind::files || !d.correspondences.empty() ||
         (!d.source.empty() && !d.target.empty());
}

FilePurpose classify_file(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    if (fs::is_directory(fs::path(path) / "sequences", ec)) return FilePurpose::kitti_root;
    throw InputError(path + ": a directory (a KITTI root holds sequences/)");
  }
  if (!fs::exists(path, ec)) throw InputError(path + ": no such file");
  const std::string e = lower_extension(path);
  if (e == ".pcd" || e == ".ply" || e == ".bin") return FilePurpose::source_cloud;
  if (e == ".label") return FilePurpose::source_labels;
  if (e == ".svg") return FilePurpose::target_cloud;  // a floor plan
  if (e == ".jsonl") return FilePurpose::bench;
  if (e == ".json") return classify_json(path);
  if (e == ".txt" || e.empty()) return classify_text(path);
  throw InputError(path +
                   ": the studio opens clouds (.pcd .ply .bin), .label files, 4x4 "
                   "transforms, configurations and sessions (.json), pairs files and "
                   "manifests (.txt), pagor bench results (.jsonl) and floor plans");
}

Opened open_file_into(AppState& s, const std::string& path, FilePurpose purpose) {
  if (purpose == FilePurpose::any) {
    purpose = classify_file(path);
    const bool plan = is_floor_plan_path(path);
    if (purpose == FilePurpose::source_cloud && !plan && s.data.kind == PairSource::Kind::files &&
        !s.data.source.empty() && s.data.target.empty())
      purpose = FilePurpose::target_cloud;
    if (purpose == FilePurpose::source_labels) purpose = labels_for(s, path);
  }
  const std::string p = absolute_path(path);
  Opened o;
  switch (purpose) {
    case FilePurpose::source_cloud:
      files_data(s).source = p, o.what = "source cloud: " + p;
      break;
    case FilePurpose::target_cloud:
      files_data(s).target = p, o.what = "target: " + p;
      break;
    case FilePurpose::source_labels:
      files_data(s).source_labels = p, o.what = "source labels: " + p;
      break;
    case FilePurpose::target_labels:
      files_data(s).target_labels = p, o.what = "target labels: " + p;
      break;
    case FilePurpose::ground_truth:
      read_transform_file(p);  // a file that is not a rigid transform is an error now
      files_data(s).ground_truth = p, o.what = "ground truth: " + p;
      break;
    case FilePurpose::correspondences:
      files_data(s).correspondences = p, o.what = "correspondences: " + p;
      break;
    case FilePurpose::kitti_root:
      s.data.kind = PairSource::Kind::kitti, s.data.kitti_root = p, o.what = "KITTI root: " + p;
      break;
    case FilePurpose::pairs:
      s.pairs = read_step_pairs(p, resolve_path(s, s.data.kitti_root), s.data.sequence);
      s.pairs_file = p;
      s.pair_index = -1;
      step_pair_index(s, 1);
      o.what = std::to_string(s.pairs.pairs.size()) + " pairs from " + p + " (Left/Right)";
      o.data = true;
      return o;
    case FilePurpose::config: {
      std::ifstream in(p);
      std::ostringstream text;
      text << in.rdbuf();
      s.config = load_config(p);
      s.preset = cli::preset_of(text.str());
      o.config = true, o.what = "parameters from " + p;
      return o;
    }
    case FilePurpose::session:
      s.session_path = p, o.session = true, o.what = "session " + p;
      return o;
    case FilePurpose::bench:
      s.bench.path = p;
      s.bench.source = lower_extension(p) == ".jsonl" || lower_extension(p) == ".json"
                           ? BenchSource::results
                       : is_kitti_pairs_file(p) ? BenchSource::kitti_pairs
                                                : BenchSource::manifest;
      if (s.bench.source == BenchSource::kitti_pairs) s.bench.kitti_root = s.data.kitti_root;
      o.bench = true, o.what = "benchmark: " + p;
      return o;
    case FilePurpose::any:
      break;
  }
  o.data = data_ready(s.data);
  return o;
}

Opened open_files_into(AppState& s, const std::vector<std::string>& paths,
                       std::vector<std::string>& errors) {
  Opened all;
  // Two clouds dropped together are a new pair: the first the source, the second the target.
  int clouds = 0;
  for (const std::string& p : paths) {
    const std::string e = lower_extension(p);
    clouds += e == ".pcd" || e == ".ply" || e == ".bin";
  }
  int cloud = 0;
  for (const std::string& p : paths) {
    try {
      FilePurpose purpose = FilePurpose::any;
      const std::string e = lower_extension(p);
      if (clouds >= 2 && (e == ".pcd" || e == ".ply" || e == ".bin"))
        purpose = cloud++ == 0 ? FilePurpose::source_cloud : FilePurpose::target_cloud;
      const Opened o = open_file_into(s, p, purpose);
      all.data |= o.data, all.config |= o.config, all.session |= o.session, all.bench |= o.bench;
      all.what += (all.what.empty() ? "" : "; ") + o.what;
      remember_file(s, p);
    } catch (const Error& ex) {
      errors.push_back(ex.what());
      forget_file(s, p);  // the recent list holds files that open
    }
  }
  all.data = all.data && data_ready(s.data);
  return all;
}

namespace {

/// What the file browser says of each purpose, and which extensions it lists (none: all).
struct PurposeEntry {
  FilePurpose purpose;
  const char* name;
  std::vector<std::string> extensions;
};

const std::vector<PurposeEntry>& purpose_table() {
  static const std::vector<PurposeEntry> table = {
      {FilePurpose::any, "a file", {}},
      {FilePurpose::source_cloud, "the source cloud", {".pcd", ".ply", ".bin"}},
      {FilePurpose::target_cloud,
       "the target cloud or floor plan",
       {".pcd", ".ply", ".bin", ".json", ".svg"}},
      {FilePurpose::source_labels, "the source labels", {".label"}},
      {FilePurpose::target_labels, "the target labels", {".label"}},
      {FilePurpose::ground_truth, "a ground truth (4x4 T_target_source)", {".txt"}},
      {FilePurpose::correspondences,
       "a matcher's correspondences (px py pz qx qy qz [weight [inlier]])",
       {".txt"}},
      {FilePurpose::pairs, "a pairs file or manifest", {".txt"}},
      {FilePurpose::config, "a configuration", {".json"}},
      {FilePurpose::session, "a session", {".json"}},
      {FilePurpose::bench, "a benchmark set or results", {".txt", ".jsonl", ".json"}},
      {FilePurpose::kitti_root, "a KITTI root (a directory)", {}},
  };
  return table;
}

const PurposeEntry& purpose_entry(FilePurpose purpose) {
  for (const PurposeEntry& e : purpose_table())
    if (e.purpose == purpose) return e;
  return purpose_table().front();
}

}  // namespace

std::vector<std::string> purpose_extensions(FilePurpose purpose) {
  return purpose_entry(purpose).extensions;
}

const char* purpose_name(FilePurpose purpose) {
  return purpose_entry(purpose).name;
}

}  // namespace pagor::studio
