#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/json_input.hpp"
#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/file_input.hpp"
#include "pagor/io/kitti.hpp"
#include "render/headless.hpp"
#include "state/app_state.hpp"
#include "widgets/number_format.hpp"

namespace pagor::studio {
namespace {

using json = nlohmann::json;

constexpr long long kMaxFrame = 999999;           // KITTI frame numbers have six digits
constexpr long long kMaxSeed = 9007199254740991;  // 2^53 - 1: exact in every JSON reader
constexpr double kMaxCoordinate = 1e7;            // [m]
constexpr float kMinDistance = 0.5f, kMaxDistance = 5000.0f;  // as Camera::zoom clamps [m]

const char* color_name(ColorMode c) {
  return c == ColorMode::by_class ? "class" : "cloud";
}
const char* pose_name(PoseShown p) {
  return p == PoseShown::selected       ? "selected"
         : p == PoseShown::ground_truth ? "ground_truth"
         : p == PoseShown::refined      ? "refined"
                                        : "identity";
}

const char* truth_name(TruthFilter t) {
  return t == TruthFilter::inliers ? "inliers" : t == TruthFilter::outliers ? "outliers" : "all";
}
const char* contribution_name(Contribution c) {
  return c == Contribution::candidate      ? "candidate"
         : c == Contribution::ground_truth ? "ground_truth"
                                           : "off";
}

json diagnosis_view_json(const DiagnosisView& d) {
  return {{"panel", d.panel},
          {"color_by_residual", d.color_by_residual},
          {"class", d.class_name},
          {"truth", truth_name(d.truth)},
          {"edges_on_hover", d.edges_on_hover},
          {"contribution", contribution_name(d.contribution)}};
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
              {"target_labels", d.target_labels},
              {"ground_truth", d.ground_truth},
              {"correspondences", d.correspondences}};
    case PairSource::Kind::synthetic:
      return {{"kind", "synthetic"}, {"seed", d.synthetic_seed}};
  }
  return {};
}

// Typed readers: each names the file and key path of a wrong value, and never converts out of
// range.
std::string key_path(const std::string& where, const char* key) {
  return where + "." + key;
}

const json* find(const json& j, const char* key) {
  const auto it = j.find(key);
  return it == j.end() || it->is_null() ? nullptr : &*it;
}

std::string get_string(const json& j, const char* key, const std::string& where,
                       const std::string& fallback) {
  const json* v = find(j, key);
  if (!v) return fallback;
  if (!v->is_string())
    throw InputError(key_path(where, key) + ": expected a string, got " + v->dump());
  return v->get<std::string>();
}

bool get_bool(const json& j, const char* key, const std::string& where, bool fallback) {
  const json* v = find(j, key);
  if (!v) return fallback;
  if (!v->is_boolean())
    throw InputError(key_path(where, key) + ": expected true or false, got " + v->dump());
  return v->get<bool>();
}

// An integer in [lo, hi]; a float or a value out of range is an error, never converted.
long long integer_value(const json& v, const std::string& path, long long lo, long long hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!v.is_number_integer())
    throw InputError(path + ": expected an integer in " + range + ", got " + v.dump());
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(hi))
    throw InputError(path + ": " + v.dump() + " is outside " + range);
  const long long x =
      v.is_number_unsigned() ? static_cast<long long>(v.get<std::uint64_t>()) : v.get<long long>();
  if (x < lo || x > hi) throw InputError(path + ": " + v.dump() + " is outside " + range);
  return x;
}

int get_int(const json& j, const char* key, const std::string& where, int fallback, int lo,
            int hi) {
  const json* v = find(j, key);
  return v ? static_cast<int>(integer_value(*v, key_path(where, key), lo, hi)) : fallback;
}

float get_float(const json& j, const char* key, const std::string& where, float fallback, float lo,
                float hi) {
  const json* v = find(j, key);
  if (!v) return fallback;
  const std::string path = key_path(where, key);
  if (!v->is_number()) throw InputError(path + ": expected a number, got " + v->dump());
  const double x = v->get<double>();
  if (!(x >= lo && x <= hi))
    throw InputError(path + ": " + v->dump() + " is outside [" + json(lo).dump() + ", " +
                     json(hi).dump() + "]");
  return static_cast<float>(x);
}

void reject_unknown(const json& j, const std::string& where,
                    std::initializer_list<const char*> known) {
  for (const auto& item : j.items()) {
    bool ok = false;
    for (const char* k : known) ok = ok || item.key() == k;
    if (!ok) throw InputError(where + "." + item.key() + ": unknown key");
  }
}

// A float as the double its shortest decimal names, for writing.
json number(float f) {
  return shortest(f);
}

std::string resolve(const std::string& path, const std::filesystem::path& base) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (base / path).lexically_normal().string();
}

PairSource read_data(const json& d, const std::string& where) {
  if (!d.is_object()) throw InputError(where + ": expected an object");
  const std::string kind = get_string(d, "kind", where, "");
  PairSource src;
  if (kind == "kitti") {
    reject_unknown(d, where, {"kind", "kitti_root", "sequence", "pair"});
    src.kind = PairSource::Kind::kitti;
    src.kitti_root = get_string(d, "kitti_root", where, "");
    src.sequence = get_string(d, "sequence", where, "00");
    const json* pair = find(d, "pair");
    if (!pair || !pair->is_array() || pair->size() != 2)
      throw InputError(where + ".pair: expected [source, target] frame numbers");
    src.source_frame =
        static_cast<int>(integer_value((*pair)[0], where + ".pair[0]", 0, kMaxFrame));
    src.target_frame =
        static_cast<int>(integer_value((*pair)[1], where + ".pair[1]", 0, kMaxFrame));
  } else if (kind == "files") {
    reject_unknown(d, where,
                   {"kind", "source", "source_labels", "target", "target_labels", "ground_truth",
                    "correspondences"});
    src.kind = PairSource::Kind::files;
    src.source = get_string(d, "source", where, "");
    src.source_labels = get_string(d, "source_labels", where, "");
    src.target = get_string(d, "target", where, "");
    src.target_labels = get_string(d, "target_labels", where, "");
    src.ground_truth = get_string(d, "ground_truth", where, "");
    src.correspondences = get_string(d, "correspondences", where, "");
  } else if (kind == "synthetic") {
    reject_unknown(d, where, {"kind", "seed"});
    src.kind = PairSource::Kind::synthetic;
    const json* seed = find(d, "seed");
    src.synthetic_seed =
        seed ? static_cast<std::uint64_t>(integer_value(*seed, where + ".seed", 0, kMaxSeed)) : 7;
  } else {
    throw InputError(where + ".kind: expected \"kitti\", \"files\" or \"synthetic\", got \"" +
                     kind + "\"");
  }
  return src;
}

void read_camera(const json& c, const std::string& where, Camera& cam) {
  if (!c.is_object()) throw InputError(where + ": expected an object");
  reject_unknown(c, where, {"target", "distance", "yaw_deg", "pitch_deg", "top_down"});
  if (const json* t = find(c, "target")) {
    if (!t->is_array() || t->size() != 3) throw InputError(where + ".target: expected [x, y, z]");
    for (int i = 0; i < 3; ++i) {
      const json& x = (*t)[static_cast<std::size_t>(i)];
      if (!x.is_number() || !(std::abs(x.get<double>()) <= kMaxCoordinate))
        throw InputError(where + ".target[" + std::to_string(i) + "]: expected a number within " +
                         "+-1e7 m, got " + x.dump());
      cam.target[i] = static_cast<float>(x.get<double>());
    }
  }
  cam.distance = get_float(c, "distance", where, cam.distance, kMinDistance, kMaxDistance);
  cam.yaw_deg = get_float(c, "yaw_deg", where, cam.yaw_deg, -3600.0f, 3600.0f);
  cam.pitch_deg = get_float(c, "pitch_deg", where, cam.pitch_deg, -89.9f, 89.9f);
  cam.top_down = get_bool(c, "top_down", where, cam.top_down);
}

// One of `names` (their index), naming the file and key when it is none of them.
int get_choice(const json& j, const char* key, const std::string& where,
               const std::vector<std::string>& names) {
  const std::string value = get_string(j, key, where, names.front());
  const auto it = std::find(names.begin(), names.end(), value);
  if (it != names.end()) return static_cast<int>(it - names.begin());
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "\"" : ", \"") + n + "\"";
  throw InputError(key_path(where, key) + ": expected one of " + list + ", got \"" + value + "\"");
}

void read_diagnosis_view(const json& d, const std::string& where, ViewState& view) {
  if (!d.is_object()) throw InputError(where + ": expected an object");
  reject_unknown(
      d, where, {"panel", "color_by_residual", "class", "truth", "edges_on_hover", "contribution"});
  DiagnosisView& dv = view.diagnosis;
  dv.panel = get_bool(d, "panel", where, false);
  dv.color_by_residual = get_bool(d, "color_by_residual", where, false);
  dv.class_name = get_string(d, "class", where, "");
  dv.truth =
      static_cast<TruthFilter>(get_choice(d, "truth", where, {"all", "inliers", "outliers"}));
  dv.edges_on_hover = get_bool(d, "edges_on_hover", where, true);
  dv.contribution = static_cast<Contribution>(
      get_choice(d, "contribution", where, {"off", "candidate", "ground_truth"}));
}

void read_view(const json& v, const std::string& where, ViewState& view) {
  if (!v.is_object()) throw InputError(where + ": expected an object");
  reject_unknown(v, where,
                 {"layers", "point_size", "landmark_size", "line_width", "grid", "legend", "color",
                  "pose", "level", "diagnosis"});
  if (const json* l = find(v, "layers")) {
    const std::string lw = where + ".layers";
    if (!l->is_object()) throw InputError(lw + ": expected an object");
    reject_unknown(
        *l, lw,
        {"source", "target", "landmarks", "correspondences", "all_correspondences", "plan"});
    Layers& ly = view.layers;
    ly.source = get_bool(*l, "source", lw, true);
    ly.target = get_bool(*l, "target", lw, true);
    ly.landmarks = get_bool(*l, "landmarks", lw, true);
    ly.correspondences = get_bool(*l, "correspondences", lw, true);
    ly.all_correspondences = get_bool(*l, "all_correspondences", lw, false);
    ly.plan = get_bool(*l, "plan", lw, true);
  }
  using L = ViewLimits;
  view.point_size =
      get_float(v, "point_size", where, view.point_size, L::min_point_size, L::max_point_size);
  view.landmark_size = get_float(v, "landmark_size", where, view.landmark_size,
                                 L::min_landmark_size, L::max_landmark_size);
  view.line_width =
      get_float(v, "line_width", where, view.line_width, L::min_line_width, L::max_line_width);
  view.grid = get_bool(v, "grid", where, view.grid);
  view.legend = get_bool(v, "legend", where, view.legend);
  const std::string color = get_string(v, "color", where, "class");
  if (color != "class" && color != "cloud")
    throw InputError(where + ".color: expected \"class\" or \"cloud\", got \"" + color + "\"");
  view.color = color == "cloud" ? ColorMode::by_cloud : ColorMode::by_class;
  const std::string pose = get_string(v, "pose", where, "selected");
  if (pose != "selected" && pose != "ground_truth" && pose != "identity" && pose != "refined")
    throw InputError(where +
                     ".pose: expected \"selected\", \"refined\", \"ground_truth\" or "
                     "\"identity\", got \"" +
                     pose + "\"");
  view.pose = pose == "ground_truth" ? PoseShown::ground_truth
              : pose == "identity"   ? PoseShown::identity
              : pose == "refined"    ? PoseShown::refined
                                     : PoseShown::selected;
  view.level = get_int(v, "level", where, -1, -1, 31);
  if (const json* d = find(v, "diagnosis")) read_diagnosis_view(*d, where + ".diagnosis", view);
}

}  // namespace

bool is_indoor(const PairSource& data) {
  return data.kind == PairSource::Kind::files && is_floor_plan_path(data.target);
}

std::string resolve_path(const AppState& s, const std::string& path) {
  return resolve(path, std::filesystem::path(s.base_dir));
}

PairSource resolved_data(const AppState& s) {
  const std::filesystem::path base(s.base_dir);
  PairSource d = s.data;
  for (std::string* p :
       {&d.kitti_root, &d.source, &d.source_labels, &d.target, &d.target_labels, &d.ground_truth,
        &d.correspondences})
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

namespace {

json bench_json(const AppState& s) {
  const BenchViewState& b = s.bench;
  return {{"shown", s.main_view == MainView::benchmark},
          {"open", b.open},
          {"source", b.source == BenchSource::kitti_pairs ? "kitti_pairs"
                     : b.source == BenchSource::results   ? "results"
                                                          : "manifest"},
          {"path", b.path},
          {"kitti_root", b.kitti_root},
          {"sequence", b.sequence},
          {"config_path", b.config_path},
          {"filter", b.filter},
          {"show", static_cast<int>(b.show)},
          {"sort", b.sort},
          {"descending", b.descending},
          {"budget_mib", b.budget_mib},
          {"plot_path", b.plot_path},
          {"sweep_mu", b.sweep_mu},
          {"sweep_thresholds", b.sweep_thresholds}};
}

void read_bench(const json& j, const std::string& where, AppState& s) {
  if (!j.is_object()) throw InputError(where + ": expected an object");
  reject_unknown(
      j, where,
      {"shown", "open", "source", "path", "kitti_root", "sequence", "config_path", "filter", "show",
       "sort", "descending", "budget_mib", "plot_path", "sweep_mu", "sweep_thresholds"});
  BenchViewState& b = s.bench;
  const std::string source = get_string(j, "source", where, "manifest");
  if (source != "manifest" && source != "kitti_pairs" && source != "results")
    throw InputError(where + ": source: expected manifest, kitti_pairs or results, got \"" +
                     source + "\"");
  b.source = source == "kitti_pairs" ? BenchSource::kitti_pairs
             : source == "results"   ? BenchSource::results
                                     : BenchSource::manifest;
  b.path = get_string(j, "path", where, b.path);
  b.kitti_root = get_string(j, "kitti_root", where, b.kitti_root);
  b.sequence = get_string(j, "sequence", where, b.sequence);
  b.config_path = get_string(j, "config_path", where, b.config_path);
  b.open = get_bool(j, "open", where, false) && !b.path.empty();
  b.filter = get_string(j, "filter", where, "");
  b.show = static_cast<RowFilter>(
      get_int(j, "show", where, 0, 0, static_cast<int>(RowFilter::rejected)));
  b.sort = get_int(j, "sort", where, 0, 0, 9);  // a column of the benchmark table
  b.descending = get_bool(j, "descending", where, false);
  b.budget_mib = get_int(j, "budget_mib", where, b.budget_mib, 64, 8192);
  b.plot_path = get_string(j, "plot_path", where, b.plot_path);
  b.sweep_mu = get_string(j, "sweep_mu", where, b.sweep_mu);
  b.sweep_thresholds = get_string(j, "sweep_thresholds", where, b.sweep_thresholds);
  s.main_view = get_bool(j, "shown", where, false) && b.open ? MainView::benchmark : MainView::pair;
}

}  // namespace

void save_session(const AppState& s, const std::string& path) {
  const Camera& c = s.camera;
  json j = {{"schema", "pagor.session/1"},
            {"data", s.have_data ? data_json(s.data) : json()},
            {"pairs_file", s.pairs_file},
            {"config", json::parse(config_to_json(s.config))},
            {"camera",
             {{"target", {number(c.target.x()), number(c.target.y()), number(c.target.z())}},
              {"distance", number(c.distance)},
              {"yaw_deg", number(c.yaw_deg)},
              {"pitch_deg", number(c.pitch_deg)},
              {"top_down", c.top_down}}},
            {"view",
             {{"layers",
               {{"source", s.view.layers.source},
                {"target", s.view.layers.target},
                {"landmarks", s.view.layers.landmarks},
                {"correspondences", s.view.layers.correspondences},
                {"all_correspondences", s.view.layers.all_correspondences},
                {"plan", s.view.layers.plan}}},
              {"point_size", number(s.view.point_size)},
              {"landmark_size", number(s.view.landmark_size)},
              {"line_width", number(s.view.line_width)},
              {"grid", s.view.grid},
              {"legend", s.view.legend},
              {"color", color_name(s.view.color)},
              {"pose", pose_name(s.view.pose)},
              {"level", s.view.level},
              {"diagnosis", diagnosis_view_json(s.view.diagnosis)}}},
            {"layout",
             {{"left_width", number(s.layout.left_width)},
              {"scene_share", number(s.layout.scene_share)}}},
            {"window", {{"width", s.width}, {"height", s.height}}},
            {"benchmark", bench_json(s)}};
  std::string text;
  try {
    text = j.dump(2) + "\n";
  } catch (const json::type_error&) {  // JSON holds UTF-8 only
    throw InputError(path + ": a path in the session is not valid UTF-8; it cannot be saved");
  }
  // A failed write (disk full, a size limit) leaves the previous session file intact.
  write_file_atomic(path, text);
}

void load_session(const std::string& path, AppState& s) {
  const std::string text = read_file(path, "session file", kMaxTextFileBytes);
  json j;
  try {  // nesting limited while parsing; numbers beyond a double rejected
    j = parse_json_limited(text, path);
  } catch (const ConfigError& e) {
    throw InputError(std::string(e.what()) + " (not a valid session file)");
  }
  if (!j.is_object()) throw InputError(path + ": expected a JSON object");
  reject_unknown(j, path + ":",
                 {"schema", "data", "pairs_file", "config", "camera", "view", "layout", "window",
                  "benchmark"});
  const std::string schema = get_string(j, "schema", path + ":", "pagor.session/1");
  if (schema != "pagor.session/1")
    throw InputError(path + ": schema: expected \"pagor.session/1\", got \"" + schema + "\"");
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  AppState next = s;

  if (const json* c = find(j, "config")) next.config = parse_config(c->dump(), path + " (config)");
  if (const json* d = find(j, "data")) {
    next.data = read_data(*d, path + ": data");
    next.have_data = true;
  }
  next.pairs_file = get_string(j, "pairs_file", path + ":", "");
  next.base_dir = base.string();
  next.pairs.clear();
  next.pair_index = -1;
  if (!next.pairs_file.empty()) {
    next.pairs = read_pairs_file(resolve(next.pairs_file, base));
    next.pair_index = index_of_pair(next.pairs, next.data);
  }
  if (const json* c = find(j, "camera")) {
    read_camera(*c, path + ": camera", next.camera);
    next.camera_fitted = true;
  } else {
    next.camera_fitted = false;
  }
  if (const json* v = find(j, "view")) read_view(*v, path + ": view", next.view);
  if (const json* l = find(j, "layout")) {
    const std::string where = path + ": layout";
    if (!l->is_object()) throw InputError(where + ": expected an object");
    reject_unknown(*l, where, {"left_width", "scene_share"});
    using L = ViewLimits;
    next.layout.left_width = get_float(*l, "left_width", where, next.layout.left_width,
                                       L::min_left_width, L::max_left_width);
    next.layout.scene_share = get_float(*l, "scene_share", where, next.layout.scene_share,
                                        L::min_scene_share, L::max_scene_share);
  }
  if (const json* w = find(j, "window")) {
    const std::string where = path + ": window";
    if (!w->is_object()) throw InputError(where + ": expected an object");
    reject_unknown(*w, where, {"width", "height"});
    next.width = get_int(*w, "width", where, next.width, kMinWidth, kMaxSide);
    next.height = get_int(*w, "height", where, next.height, kMinHeight, kMaxSide);
  }
  if (const json* b = find(j, "benchmark")) read_bench(*b, path + ": benchmark", next);
  next.session_path = path;
  s = std::move(next);
}

}  // namespace pagor::studio
