#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app_state.hpp"
#include "pagor/errors.hpp"
#include "pagor/kitti.hpp"

namespace pagor::studio {
namespace {

using json = nlohmann::json;

const char* color_name(ColorMode c) {
  return c == ColorMode::by_class ? "class" : "cloud";
}
const char* pose_name(PoseShown p) {
  return p == PoseShown::selected       ? "selected"
         : p == PoseShown::ground_truth ? "ground_truth"
                                        : "identity";
}

json data_json(const PairSource& d) {
  switch (d.kind) {
    case PairSource::Kind::kitti:
      return {{"kind", "kitti"},
              {"kitti_root", d.kitti_root},
              {"sequence", d.sequence},
              {"pair", {d.source_frame, d.target_frame}}};
    case PairSource::Kind::files:
      return {{"kind", "files"},
              {"source", d.source},
              {"source_labels", d.source_labels},
              {"target", d.target},
              {"target_labels", d.target_labels}};
    case PairSource::Kind::synthetic:
      return {{"kind", "synthetic"}, {"seed", d.synthetic_seed}};
  }
  return {};
}

// Reads a typed value at a key path with a message naming the file and the path.
template <class T>
T get(const json& j, const char* key, const std::string& where, const T& fallback) {
  const auto it = j.find(key);
  if (it == j.end()) return fallback;
  try {
    return it->get<T>();
  } catch (const json::exception&) {
    throw InputError(where + "." + key + ": wrong type (" + it->type_name() + ")");
  }
}

std::string resolve(const std::string& path, const std::filesystem::path& base) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (base / path).lexically_normal().string();
}

}  // namespace

std::string resolve_path(const AppState& s, const std::string& path) {
  return resolve(path, std::filesystem::path(s.base_dir));
}

PairSource resolved_data(const AppState& s) {
  const std::filesystem::path base(s.base_dir);
  PairSource d = s.data;
  for (std::string* p : {&d.kitti_root, &d.source, &d.source_labels, &d.target, &d.target_labels})
    *p = resolve(*p, base);
  return d;
}

int index_of_pair(const std::vector<std::pair<int, int>>& pairs, const PairSource& data) {
  const auto it =
      std::find(pairs.begin(), pairs.end(), std::make_pair(data.source_frame, data.target_frame));
  return it == pairs.end() ? -1 : static_cast<int>(it - pairs.begin());
}

int shown_level(const ViewState& view, int selected, int levels) {
  if (view.level >= 0 && view.level < levels) return view.level;
  return selected < levels ? selected : -1;
}

void save_session(const AppState& s, const std::string& path) {
  const Camera& c = s.camera;
  json j = {{"schema", "pagor.session/1"},
            {"data", s.have_data ? data_json(s.data) : json()},
            {"pairs_file", s.pairs_file},
            {"config", json::parse(config_to_json(s.config))},
            {"camera",
             {{"target", {c.target.x(), c.target.y(), c.target.z()}},
              {"distance", c.distance},
              {"yaw_deg", c.yaw_deg},
              {"pitch_deg", c.pitch_deg},
              {"top_down", c.top_down}}},
            {"view",
             {{"layers",
               {{"source", s.view.layers.source},
                {"target", s.view.layers.target},
                {"landmarks", s.view.layers.landmarks},
                {"correspondences", s.view.layers.correspondences},
                {"all_correspondences", s.view.layers.all_correspondences}}},
              {"point_size", s.view.point_size},
              {"landmark_size", s.view.landmark_size},
              {"color", color_name(s.view.color)},
              {"pose", pose_name(s.view.pose)},
              {"level", s.view.level}}},
            {"window", {{"width", s.width}, {"height", s.height}}}};
  std::ofstream out(path, std::ios::trunc);
  if (!out) throw InputError(path + ": cannot open for writing");
  out << j.dump(2) << "\n";
  if (!out) throw InputError(path + ": write failed");
}

void load_session(const std::string& path, AppState& s) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open session file");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) {
    throw InputError(path + ": not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object()) throw InputError(path + ": expected a JSON object");
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  AppState next = s;

  if (j.contains("config") && !j["config"].is_null())
    next.config = parse_config(j["config"].dump(), path + " (config)");

  if (j.contains("data") && !j["data"].is_null()) {
    const json& d = j["data"];
    const std::string where = path + ": data";
    const std::string kind = get<std::string>(d, "kind", where, "");
    PairSource src;
    if (kind == "kitti") {
      src.kind = PairSource::Kind::kitti;
      src.kitti_root = get<std::string>(d, "kitti_root", where, "");
      src.sequence = get<std::string>(d, "sequence", where, "00");
      const auto pair = get<std::vector<int>>(d, "pair", where, {});
      if (pair.size() != 2)
        throw InputError(where + ".pair: expected [source, target] frame numbers");
      src.source_frame = pair[0];
      src.target_frame = pair[1];
    } else if (kind == "files") {
      src.kind = PairSource::Kind::files;
      src.source = get<std::string>(d, "source", where, "");
      src.source_labels = get<std::string>(d, "source_labels", where, "");
      src.target = get<std::string>(d, "target", where, "");
      src.target_labels = get<std::string>(d, "target_labels", where, "");
    } else if (kind == "synthetic") {
      src.kind = PairSource::Kind::synthetic;
      src.synthetic_seed = get<std::uint64_t>(d, "seed", where, 7);
    } else {
      throw InputError(where + ".kind: expected \"kitti\", \"files\" or \"synthetic\", got \"" +
                       kind + "\"");
    }
    next.data = src;
    next.have_data = true;
  }
  next.pairs_file = get<std::string>(j, "pairs_file", path, "");
  next.base_dir = base.string();
  next.pairs.clear();
  next.pair_index = -1;
  if (!next.pairs_file.empty()) {
    next.pairs = read_pairs_file(resolve(next.pairs_file, base));
    next.pair_index = index_of_pair(next.pairs, next.data);
  }

  if (j.contains("camera") && !j["camera"].is_null()) {
    const json& c = j["camera"];
    const std::string where = path + ": camera";
    const auto t = get<std::vector<float>>(c, "target", where, {0, 0, 0});
    if (t.size() != 3) throw InputError(where + ".target: expected [x, y, z]");
    next.camera.target = Eigen::Vector3f(t[0], t[1], t[2]);
    next.camera.distance = get<float>(c, "distance", where, next.camera.distance);
    next.camera.yaw_deg = get<float>(c, "yaw_deg", where, next.camera.yaw_deg);
    next.camera.pitch_deg = get<float>(c, "pitch_deg", where, next.camera.pitch_deg);
    next.camera.top_down = get<bool>(c, "top_down", where, next.camera.top_down);
    next.camera_fitted = true;
  } else {
    next.camera_fitted = false;
  }
  if (j.contains("view") && !j["view"].is_null()) {
    const json& v = j["view"];
    const std::string where = path + ": view";
    if (v.contains("layers")) {
      const json& l = v["layers"];
      const std::string lw = where + ".layers";
      next.view.layers.source = get<bool>(l, "source", lw, true);
      next.view.layers.target = get<bool>(l, "target", lw, true);
      next.view.layers.landmarks = get<bool>(l, "landmarks", lw, true);
      next.view.layers.correspondences = get<bool>(l, "correspondences", lw, true);
      next.view.layers.all_correspondences = get<bool>(l, "all_correspondences", lw, false);
    }
    next.view.point_size = get<float>(v, "point_size", where, next.view.point_size);
    next.view.landmark_size = get<float>(v, "landmark_size", where, next.view.landmark_size);
    const std::string color = get<std::string>(v, "color", where, "class");
    next.view.color = color == "cloud" ? ColorMode::by_cloud : ColorMode::by_class;
    const std::string pose = get<std::string>(v, "pose", where, "selected");
    next.view.pose = pose == "ground_truth" ? PoseShown::ground_truth
                     : pose == "identity"   ? PoseShown::identity
                                            : PoseShown::selected;
    next.view.level = get<int>(v, "level", where, -1);
  }
  if (j.contains("window") && j["window"].is_object()) {
    next.width = get<int>(j["window"], "width", path + ": window", next.width);
    next.height = get<int>(j["window"], "height", path + ": window", next.height);
  }
  next.session_path = path;
  s = std::move(next);
}

}  // namespace pagor::studio
