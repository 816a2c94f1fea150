#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "common/config_args.hpp"
#include "pagor/errors.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/file_input.hpp"
#include "pagor/io/json_input.hpp"
#include "pagor/io/kitti.hpp"
#include "pagor/report.hpp"  // matrix_json: a transform as the report writes it
#include "render/headless.hpp"
#include "state/app_state.hpp"
#include "state/camera_views.hpp"
#include "state/session_json.hpp"
#include "widgets/number_format.hpp"

namespace pagor::studio {
namespace {

using json = nlohmann::json;
using namespace session_json;

constexpr long long kMaxFrame = 999999;           // KITTI frame numbers have six digits
constexpr long long kMaxSeed = 9007199254740991;  // 2^53 - 1: exact in every JSON reader

constexpr const char* kColorNames[] = {"class", "cloud", "height", "intensity", "residual"};

const char* color_name(ColorMode c) {
  return kColorNames[static_cast<int>(c)];
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

json data_json(const PairSource& d, const std::optional<Transform>& inline_truth) {
  switch (d.kind) {
    case PairSource::Kind::kitti:
      return {{"kind", "kitti"},
              {"kitti_root", d.kitti_root},
              {"sequence", d.sequence},
              {"pair", {d.source_frame, d.target_frame}}};
    case PairSource::Kind::files: {
      json j = {{"kind", "files"},
                {"source", d.source},
                {"source_labels", d.source_labels},
                {"target", d.target},
                {"target_labels", d.target_labels},
                {"ground_truth", d.ground_truth},
                {"correspondences", d.correspondences}};
      if (inline_truth) j["ground_truth_T"] = matrix_json(*inline_truth);
      return j;
    }
    case PairSource::Kind::synthetic:
      return {{"kind", "synthetic"}, {"seed", d.synthetic_seed}};
  }
  return {};
}

std::string resolve(const std::string& path, const std::filesystem::path& base) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (base / path).lexically_normal().string();
}

// A 4x4 rigid transform written as rows; an error names the key.
Transform read_matrix(const json& m, const std::string& where) {
  Transform T;
  if (!m.is_array() || m.size() != 4) throw InputError(where + ": expected 4 rows of 4 numbers");
  for (int r = 0; r < 4; ++r) {
    const json& row = m[static_cast<std::size_t>(r)];
    if (!row.is_array() || row.size() != 4)
      throw InputError(where + "[" + std::to_string(r) + "]: expected 4 numbers");
    for (int c = 0; c < 4; ++c) {
      const json& x = row[static_cast<std::size_t>(c)];
      if (!x.is_number())
        throw InputError(where + "[" + std::to_string(r) + "][" + std::to_string(c) +
                         "]: expected a number, got " + x.dump());
      T(r, c) = x.get<double>();
    }
  }
  check_rigid(T, where);
  return T;
}

PairSource read_data(const json& d, const std::string& where,
                     std::optional<Transform>& inline_truth) {
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
                    "correspondences", "ground_truth_T"});
    inline_truth.reset();
    if (const json* m = find(d, "ground_truth_T"))
      inline_truth = read_matrix(*m, where + ".ground_truth_T");
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
  view.color = static_cast<ColorMode>(get_choice(
      v, "color", where, std::vector<std::string>(std::begin(kColorNames), std::end(kColorNames))));
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

namespace {

// The configuration with the preset it starts from (the reference of resets and marks).
json session_config(const SessionState& s) {
  json c = json::parse(config_to_json(s.config));
  c["preset"] = s.preset;
  return c;
}

}  // namespace

void save_session(const SessionState& s, const std::string& path) {
  json j = {{"schema", "pagor.session/1"},
            {"data", s.have_data ? data_json(s.data, s.inline_truth) : json()},
            {"pairs_file", s.pairs_file},
            {"export_path", s.export_path},
            {"config", session_config(s)},
            {"camera", camera_json(s.camera)},
            {"camera_views", camera_views_json(s.camera_views)},
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
                 {"schema", "data", "pairs_file", "export_path", "config", "camera", "camera_views",
                  "view", "layout", "window", "benchmark"});
  const std::string schema = get_string(j, "schema", path + ":", "pagor.session/1");
  if (schema != "pagor.session/1")
    throw InputError(path + ": schema: expected \"pagor.session/1\", got \"" + schema + "\"");
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  AppState next = s;

  if (const json* c = find(j, "config")) {
    next.config = parse_config(c->dump(), path + " (config)");
    next.preset = cli::preset_of(c->dump());
  }
  if (const json* d = find(j, "data")) {
    next.data = read_data(*d, path + ": data", next.inline_truth);
    next.have_data = true;
  }
  next.pairs_file = get_string(j, "pairs_file", path + ":", "");
  next.export_path = get_string(j, "export_path", path + ":", next.export_path);
  next.base_dir = base.string();
  next.pairs = PairSet{};
  next.pair_index = -1;
  if (!next.pairs_file.empty()) {
    next.pairs = read_step_pairs(resolve(next.pairs_file, base),
                                 resolve(next.data.kitti_root, base), next.data.sequence);
    next.pair_index = index_of_pair(next.pairs, resolved_data(next));
  }
  if (const json* c = find(j, "camera")) {
    read_camera(*c, path + ": camera", next.camera);
    next.camera_fitted = true;
  } else {
    next.camera_fitted = false;
  }
  next.camera_views.clear();  // a session without views has none (not the previous session's)
  if (const json* v = find(j, "camera_views"))
    next.camera_views = read_camera_views(*v, path + ": camera_views");
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
