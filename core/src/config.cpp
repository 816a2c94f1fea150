#include "pagor/config.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <type_traits>
#include <utility>

#include "pagor/errors.hpp"
#include "io/json_input.hpp"

namespace pagor {
namespace {

using json = nlohmann::json;

// ---- enum names -------------------------------------------------------------------------------

template <class E>
struct EnumNames;
template <>
struct EnumNames<LandmarkMethod> {
  static constexpr std::pair<const char*, LandmarkMethod> table[] = {
      {"cluster", LandmarkMethod::cluster}, {"fpfh", LandmarkMethod::fpfh}};
};
template <>
struct EnumNames<FallbackMode> {
  static constexpr std::pair<const char*, FallbackMode> table[] = {
      {"automatic", FallbackMode::automatic},
      {"always", FallbackMode::always},
      {"never", FallbackMode::never}};
};
template <>
struct EnumNames<TrimKind> {
  static constexpr std::pair<const char*, TrimKind> table[] = {{"difference", TrimKind::difference},
                                                               {"ratio", TrimKind::ratio}};
};
template <>
struct EnumNames<AffinityKind> {
  static constexpr std::pair<const char*, AffinityKind> table[] = {
      {"binary", AffinityKind::binary}, {"gaussian", AffinityKind::gaussian}};
};
template <>
struct EnumNames<CliqueSolver> {
  static constexpr std::pair<const char*, CliqueSolver> table[] = {
      {"cascaded", CliqueSolver::cascaded},
      {"independent", CliqueSolver::independent},
      {"exact", CliqueSolver::exact}};
};
template <>
struct EnumNames<PoseModel> {
  static constexpr std::pair<const char*, PoseModel> table[] = {
      {"se3", PoseModel::se3}, {"se2", PoseModel::se2}, {"four_dof", PoseModel::four_dof}};
};
template <>
struct EnumNames<ScoreKind> {
  static constexpr std::pair<const char*, ScoreKind> table[] = {{"truncated", ScoreKind::truncated},
                                                                {"trimmed", ScoreKind::trimmed},
                                                                {"nearest", ScoreKind::nearest}};
};

template <class E>
const char* enum_name(E v) {
  for (const auto& [name, value] : EnumNames<E>::table)
    if (value == v) return name;
  return "?";
}

// ---- one field list per struct, used both to write and to read --------------------------------

template <class V, class P>
void fields_of_class(V& v, P& p) {
  v("name", p.name);
  v("method", p.method);
  v("voxel_size", p.voxel_size);
  v("cluster_tolerance", p.cluster_tolerance);
  v("min_points", p.min_points);
  v("max_points", p.max_points);
  v("normal_radius", p.normal_radius);
  v("feature_radius", p.feature_radius);
  v("max_keypoints", p.max_keypoints);
}
template <class V, class P>
void fields_of_fallback(V& v, P& p) {
  v("mode", p.mode);
  v("class_poor_below", p.class_poor_below);
  v("ground_classes", p.ground_classes);
  v("ground_height", p.ground_height);
  v("keypoints", p.keypoints);
}
template <class V, class P>
void fields_of_landmarks(V& v, P& p) {
  v("classes", p.classes);
  v("adapt_to_spacing", p.adapt_to_spacing);
  v("tolerance_spacings", p.tolerance_spacings);
  v("min_cluster_voxels", p.min_cluster_voxels);
  v("fallback", p.fallback);
}
template <class V, class P>
void fields_of_correspondences(V& v, P& p) {
  v("max_correspondences", p.max_correspondences);
  v("fpfh_mutual", p.fpfh_mutual);
  v("fpfh_max_per_class", p.fpfh_max_per_class);
  v("shape_scale", p.shape_scale);
}
template <class V, class P>
void fields_of_graph(V& v, P& p) {
  v("trim", p.trim);
  v("thresholds", p.thresholds);
  v("affinity", p.affinity);
  v("sigma_ratio", p.sigma_ratio);
  v("min_length", p.min_length);
}
template <class V, class P>
void fields_of_clique(V& v, P& p) {
  v("solver", p.solver);
  v("prune", p.prune);
  v("tol_u", p.tol_u);
  v("tol_F", p.tol_F);
  v("max_inner_iterations", p.max_inner_iterations);
  v("max_outer_iterations", p.max_outer_iterations);
  v("beta", p.beta);
  v("max_line_search", p.max_line_search);
  v("eps", p.eps);
  v("support_tol", p.support_tol);
  v("seed", p.seed);
  v("warm_start_mix", p.warm_start_mix);
  v("warm_start_penalty", p.warm_start_penalty);
  v("exact_max_nodes", p.exact_max_nodes);
}
template <class V, class P>
void fields_of_gnc(V& v, P& p) {
  v("model", p.model);
  v("noise_bound", p.noise_bound);
  v("mu_factor", p.mu_factor);
  v("max_iterations", p.max_iterations);
  v("cost_tolerance", p.cost_tolerance);
}
template <class V, class P>
void fields_of_verification(V& v, P& p) {
  v("voxel_size", p.voxel_size);
  v("mu", p.mu);
  v("score", p.score);
}
template <class V, class P>
void fields_of_refinement(V& v, P& p) {
  v("enabled", p.enabled);
  v("max_iterations", p.max_iterations);
  v("max_points", p.max_points);
  v("max_distance", p.max_distance);
  v("min_distance", p.min_distance);
  v("robust_scale", p.robust_scale);
  v("normal_radius", p.normal_radius);
  v("max_translation", p.max_translation);
  v("max_rotation", p.max_rotation);
  v("free_roll_pitch", p.free_roll_pitch);
}
template <class V, class P>
void fields_of_acceptance(V& v, P& p) {
  v("inlier_distance", p.inlier_distance);
  v("ground_thickness", p.ground_thickness);
  v("min_overlap", p.min_overlap);
  v("min_inliers", p.min_inliers);
  v("minimal_support_overlap", p.minimal_support_overlap);
  v("min_margin", p.min_margin);
}
template <class V, class P>
void fields_of_evaluation(V& v, P& p) {
  v("max_translation_error", p.max_translation_error);
  v("max_rotation_error", p.max_rotation_error);
}

template <class V, class P>
void fields_of_columns(V& v, P& p) {
  v("cluster_tolerance", p.cluster_tolerance);
  v("min_radius", p.min_radius);
  v("max_radius", p.max_radius);
  v("max_rms", p.max_rms);
  v("min_points", p.min_points);
  v("min_arc_deg", p.min_arc_deg);
}
template <class V, class P>
void fields_of_indoor(V& v, P& p) {
  v("plan_spacing", p.plan_spacing);
  v("height_min", p.height_min);
  v("height_max", p.height_max);
  v("floor_voxel", p.floor_voxel);
  v("detect_columns", p.detect_columns);
  v("columns", p.columns);
}

template <class T>
struct IsParams : std::false_type {};
#define PAGOR_FIELDS(Type, fn)               \
  template <>                                \
  struct IsParams<Type> : std::true_type {}; \
  template <class V>                         \
  void fields(V& v, Type& p) {               \
    fn(v, p);                                \
  }                                          \
  template <class V>                         \
  void fields(V& v, const Type& p) {         \
    fn(v, p);                                \
  }
PAGOR_FIELDS(ClassParams, fields_of_class)
PAGOR_FIELDS(FallbackParams, fields_of_fallback)
PAGOR_FIELDS(LandmarkParams, fields_of_landmarks)
PAGOR_FIELDS(CorrespondenceParams, fields_of_correspondences)
PAGOR_FIELDS(GraphParams, fields_of_graph)
PAGOR_FIELDS(CliqueParams, fields_of_clique)
PAGOR_FIELDS(GncParams, fields_of_gnc)
PAGOR_FIELDS(VerificationParams, fields_of_verification)
PAGOR_FIELDS(RefinementParams, fields_of_refinement)
PAGOR_FIELDS(AcceptanceParams, fields_of_acceptance)
PAGOR_FIELDS(EvaluationParams, fields_of_evaluation)
PAGOR_FIELDS(ColumnDetectorParams, fields_of_columns)
PAGOR_FIELDS(IndoorParams, fields_of_indoor)
#undef PAGOR_FIELDS

// ---- writing ----------------------------------------------------------------------------------

json encode(double x) {
  return x;
}
json encode(int x) {
  return x;
}
json encode(long x) {
  return x;
}
json encode(std::uint64_t x) {
  return x;
}
json encode(bool x) {
  return x;
}
json encode(const std::string& x) {
  return x;
}
json encode(const std::vector<double>& x) {
  return x;
}
template <class E, std::enable_if_t<std::is_enum<E>::value, int> = 0>
json encode(E x) {
  return enum_name(x);
}
template <class P, std::enable_if_t<IsParams<P>::value, int> = 0>
json encode(const P& p);
template <class P>
json encode(const std::vector<P>& list) {
  json a = json::array();
  for (const auto& x : list) a.push_back(encode(x));
  return a;
}

struct Writer {
  json& out;
  template <class T>
  void operator()(const char* key, const T& value) {
    out[key] = encode(value);
  }
};

template <class P, std::enable_if_t<IsParams<P>::value, int>>
json encode(const P& p) {
  json j = json::object();
  Writer w{j};
  fields(w, p);
  return j;
}

json encode_scheme(const LabelScheme& s) {
  for (const auto& name : builtin_label_scheme_names()) {
    if (name != s.name) continue;
    const LabelScheme b = builtin_label_scheme(name);
    bool same = b.classes.size() == s.classes.size();
    for (std::size_t i = 0; same && i < b.classes.size(); ++i)
      same = b.classes[i].name == s.classes[i].name && b.classes[i].ids == s.classes[i].ids;
    if (same) return s.name;
  }
  json classes = json::object();
  for (const auto& c : s.classes) classes[c.name] = c.ids;
  return json{{"name", s.name}, {"classes", classes}};
}

json encode_config(const Config& c) {
  return json{{"label_scheme", encode_scheme(c.label_scheme)},
              {"landmarks", encode(c.landmarks)},
              {"correspondences", encode(c.correspondences)},
              {"graph", encode(c.graph)},
              {"clique", encode(c.clique)},
              {"gnc", encode(c.gnc)},
              {"verification", encode(c.verification)},
              {"refinement", encode(c.refinement)},
              {"acceptance", encode(c.acceptance)},
              {"evaluation", encode(c.evaluation)},
              {"indoor", encode(c.indoor)}};
}

// ---- reading ----------------------------------------------------------------------------------

struct Context {
  std::string origin;
};

[[noreturn]] void fail(const Context& ctx, const std::string& path, const std::string& what) {
  throw ConfigError(ctx.origin + ": " + path + ": " + what);
}

std::string type_name(const json& j) {
  return j.type_name();
}

// Numbers go through the checked getters of json_input.hpp: finite only, integer ranges checked
// before any conversion.
void decode(const Context& ctx, const json& j, const std::string& path, double& x) {
  x = json_finite(j, ctx.origin + ": " + path);
}
template <class I>
void decode_integer(const Context& ctx, const json& j, const std::string& path, I& x) {
  const std::string where = ctx.origin + ": " + path;
  if constexpr (std::is_unsigned<I>::value)
    x = static_cast<I>(json_unsigned(j, where, std::numeric_limits<I>::max()));
  else
    x = static_cast<I>(
        json_integer(j, where, std::numeric_limits<I>::min(), std::numeric_limits<I>::max()));
}
void decode(const Context& ctx, const json& j, const std::string& path, int& x) {
  decode_integer(ctx, j, path, x);
}
void decode(const Context& ctx, const json& j, const std::string& path, long& x) {
  decode_integer(ctx, j, path, x);
}
void decode(const Context& ctx, const json& j, const std::string& path, std::uint64_t& x) {
  decode_integer(ctx, j, path, x);
}
void decode(const Context& ctx, const json& j, const std::string& path, bool& x) {
  if (!j.is_boolean()) fail(ctx, path, "expected true or false, got " + type_name(j));
  x = j.get<bool>();
}
void decode(const Context& ctx, const json& j, const std::string& path, std::string& x) {
  if (!j.is_string()) fail(ctx, path, "expected a string, got " + type_name(j));
  x = j.get<std::string>();
}
void decode(const Context& ctx, const json& j, const std::string& path, std::vector<double>& x) {
  if (!j.is_array()) fail(ctx, path, "expected an array of numbers, got " + type_name(j));
  x.assign(j.size(), 0.0);
  for (std::size_t i = 0; i < j.size(); ++i)
    decode(ctx, j[i], path + "[" + std::to_string(i) + "]", x[i]);
}
template <class E, std::enable_if_t<std::is_enum<E>::value, int> = 0>
void decode(const Context& ctx, const json& j, const std::string& path, E& x) {
  std::string allowed;
  for (const auto& [name, value] : EnumNames<E>::table) {
    if (j.is_string() && j.get<std::string>() == name) {
      x = value;
      return;
    }
    allowed += (allowed.empty() ? "" : ", ") + std::string("\"") + name + "\"";
  }
  fail(ctx, path, "expected one of " + allowed + ", got " + json_excerpt(j));
}
template <class P, std::enable_if_t<IsParams<P>::value, int> = 0>
void decode(const Context& ctx, const json& j, const std::string& path, P& p);
template <class P>
void decode(const Context& ctx, const json& j, const std::string& path, std::vector<P>& list) {
  if (!j.is_array()) fail(ctx, path, "expected an array, got " + type_name(j));
  list.assign(j.size(), P{});
  for (std::size_t i = 0; i < j.size(); ++i)
    decode(ctx, j[i], path + "[" + std::to_string(i) + "]", list[i]);
}

struct Reader {
  const Context& ctx;
  const json& in;
  std::string path;
  std::set<std::string> known;
  template <class T>
  void operator()(const char* key, T& value) {
    known.insert(key);
    const auto it = in.find(key);
    if (it != in.end()) decode(ctx, *it, path.empty() ? key : path + "." + key, value);
  }
  void reject_unknown() const {
    for (const auto& item : in.items())
      if (!known.count(item.key()))
        fail(ctx, path.empty() ? item.key() : path + "." + item.key(), "unknown key");
  }
};

template <class P, std::enable_if_t<IsParams<P>::value, int>>
void decode(const Context& ctx, const json& j, const std::string& path, P& p) {
  if (!j.is_object()) fail(ctx, path, "expected an object, got " + type_name(j));
  Reader r{ctx, j, path, {}};
  fields(r, p);
  r.reject_unknown();
}

void decode_scheme(const Context& ctx, const json& j, LabelScheme& s) {
  const std::string path = "label_scheme";
  if (j.is_string()) {
    try {
      s = builtin_label_scheme(j.get<std::string>());
    } catch (const ConfigError& e) {
      fail(ctx, path, e.what());
    }
    return;
  }
  if (!j.is_object()) fail(ctx, path, "expected a scheme name or an object, got " + type_name(j));
  s = LabelScheme{};
  for (const auto& item : j.items()) {
    if (item.key() == "name") {
      decode(ctx, item.value(), path + ".name", s.name);
    } else if (item.key() == "classes") {
      if (!item.value().is_object())
        fail(ctx, path + ".classes", "expected an object {\"class\": [ids]}");
      for (const auto& c : item.value().items()) {
        SemanticClass sc{c.key(), {}};
        const std::string cpath = path + ".classes." + c.key();
        if (!c.value().is_array()) fail(ctx, cpath, "expected an array of label ids");
        for (std::size_t i = 0; i < c.value().size(); ++i) {
          std::uint64_t id = 0;
          decode(ctx, c.value()[i], cpath + "[" + std::to_string(i) + "]", id);
          if (id > 0xFFFFu) fail(ctx, cpath, "label ids are 16-bit (0..65535)");
          sc.ids.push_back(static_cast<std::uint32_t>(id));
        }
        s.classes.push_back(std::move(sc));
      }
    } else {
      fail(ctx, path + "." + item.key(), "unknown key");
    }
  }
  if (s.name.empty()) fail(ctx, path + ".name", "missing");
  if (s.classes.empty()) fail(ctx, path + ".classes", "missing or empty");
}

// Smallest voxel a config may ask for: below a millimetre a voxel grid only costs memory.
constexpr double kMinVoxelSize = 1e-3;  // [m]

void check(const Context& ctx, bool ok, const std::string& path, const std::string& what) {
  if (!ok) fail(ctx, path, what);
}

}  // namespace

const char* to_string(LandmarkMethod v) {
  return enum_name(v);
}
const char* to_string(FallbackMode v) {
  return enum_name(v);
}
const char* to_string(TrimKind v) {
  return enum_name(v);
}
const char* to_string(AffinityKind v) {
  return enum_name(v);
}
const char* to_string(CliqueSolver v) {
  return enum_name(v);
}
const char* to_string(PoseModel v) {
  return enum_name(v);
}
const char* to_string(ScoreKind v) {
  return enum_name(v);
}

Config default_config() {
  Config c;
  c.label_scheme = builtin_label_scheme("semantickitti-train");
  ClassParams car{"car", LandmarkMethod::cluster};
  car.voxel_size = 0.2;
  car.cluster_tolerance = 0.5;
  car.min_points = 20;
  car.max_points = 2000;
  ClassParams trunk{"trunk", LandmarkMethod::cluster};
  trunk.voxel_size = 0.1;
  trunk.cluster_tolerance = 0.3;
  trunk.min_points = 8;
  trunk.max_points = 1000;
  ClassParams pole = trunk;
  pole.name = "pole";
  ClassParams sign = trunk;
  sign.name = "traffic-sign";
  ClassParams building{"building", LandmarkMethod::fpfh};
  building.voxel_size = 0.6;
  building.normal_radius = 1.2;
  building.feature_radius = 3.0;
  c.landmarks.classes = {car, trunk, pole, sign, building};
  c.gnc.model = PoseModel::four_dof;
  return c;
}

// The paper's car-park experiment: a scan against a floor plan. Columns (diameter 0.6 m) are the
// landmarks, represented on both sides by their outline (floor_projection.hpp) so that a cluster
// centroid is the column's centre; walls are the verification's points.
static Config indoor_config() {
  Config c;
  c.label_scheme = builtin_label_scheme("indoor");
  ClassParams column{"column", LandmarkMethod::cluster};
  column.voxel_size = 0.05;
  column.cluster_tolerance = 0.2;
  column.min_points = 5;
  column.max_points = 400;
  c.landmarks.classes = {column};
  c.landmarks.adapt_to_spacing = false;
  c.landmarks.fallback.mode = FallbackMode::never;
  c.correspondences.max_correspondences = 3000;
  c.graph.trim = TrimKind::difference;
  c.graph.thresholds = {0.05, 0.10, 0.15, 0.20, 0.25};
  c.graph.min_length = 0.5;
  c.gnc.model = PoseModel::se2;
  c.gnc.noise_bound = 0.3;
  c.verification.voxel_size = 0.1;
  c.verification.mu = 0.5;
  c.acceptance.inlier_distance = 0.2;
  c.acceptance.min_overlap = 0.3;
  c.acceptance.min_inliers = 3;
  c.acceptance.min_margin = 0.0;  // calibrated on the generated car parks without it
  c.refinement.enabled = false;   // not measured on scan-vs-plan pairs (planar points)
  c.evaluation.max_translation_error = 1.0;
  c.evaluation.max_rotation_error = 3.0;
  return c;
}

std::vector<std::string> preset_names() {
  return {"default", "paper", "indoor"};
}

Config preset_config(const std::string& name) {
  if (name == "default") return default_config();
  if (name == "paper") {
    Config c = default_config();
    c.landmarks.classes.erase(
        std::remove_if(c.landmarks.classes.begin(), c.landmarks.classes.end(),
                       [](const ClassParams& p) { return p.name == "traffic-sign"; }),
        c.landmarks.classes.end());
    c.landmarks.adapt_to_spacing = false;
    c.landmarks.fallback.mode = FallbackMode::never;
    c.graph = GraphParams{};
    c.gnc.model = PoseModel::se3;
    c.verification = VerificationParams{};
    c.refinement.enabled = false;
    return c;
  }
  if (name == "indoor") return indoor_config();
  std::string known;
  for (const auto& n : preset_names()) known += (known.empty() ? "" : ", ") + n;
  throw ConfigError("unknown preset '" + name + "' (presets: " + known + ")");
}

void validate(const Config& c, const std::string& origin) {
  const Context ctx{origin};
  check(ctx, !c.landmarks.classes.empty(), "landmarks.classes", "needs at least one class");
  std::set<std::string> names;
  for (std::size_t i = 0; i < c.landmarks.classes.size(); ++i) {
    const ClassParams& p = c.landmarks.classes[i];
    const std::string path = "landmarks.classes[" + std::to_string(i) + "]";
    check(ctx, c.label_scheme.find(p.name) >= 0, path + ".name",
          "class '" + p.name + "' is not in label scheme '" + c.label_scheme.name +
              "' (it has: " + c.label_scheme.class_list() + ")");
    check(ctx, names.insert(p.name).second, path + ".name", "class '" + p.name + "' listed twice");
    check(ctx, p.voxel_size == 0 || p.voxel_size >= kMinVoxelSize, path + ".voxel_size",
          "must be 0 (none) or at least 0.001 [m]");
    check(ctx, p.cluster_tolerance > 0, path + ".cluster_tolerance", "must be > 0 [m]");
    check(ctx, p.min_points >= 1, path + ".min_points", "must be >= 1");
    check(ctx, p.max_points >= p.min_points, path + ".max_points", "must be >= min_points");
    check(ctx, p.normal_radius > 0, path + ".normal_radius", "must be > 0 [m]");
    check(ctx, p.feature_radius > p.normal_radius, path + ".feature_radius",
          "must be larger than normal_radius [m]");
    check(ctx, p.max_keypoints >= 1, path + ".max_keypoints", "must be >= 1");
  }
  check(ctx, c.landmarks.tolerance_spacings > 0, "landmarks.tolerance_spacings", "must be > 0");
  check(ctx, c.landmarks.min_cluster_voxels >= 1, "landmarks.min_cluster_voxels", "must be >= 1");
  const FallbackParams& fb = c.landmarks.fallback;
  check(ctx, fb.class_poor_below >= 0, "landmarks.fallback.class_poor_below", "must be >= 0");
  check(ctx, fb.ground_height >= 0, "landmarks.fallback.ground_height", "must be >= 0 [m]");
  check(ctx, fb.keypoints.voxel_size > 0, "landmarks.fallback.keypoints.voxel_size",
        "must be > 0 [m]");
  check(ctx,
        fb.keypoints.normal_radius > 0 && fb.keypoints.feature_radius > fb.keypoints.normal_radius,
        "landmarks.fallback.keypoints.feature_radius",
        "radii must be > 0 and feature > normal [m]");
  check(ctx, fb.keypoints.max_keypoints >= 1, "landmarks.fallback.keypoints.max_keypoints",
        "must be >= 1");
  check(ctx, c.correspondences.max_correspondences >= 0, "correspondences.max_correspondences",
        "must be >= 0 (0 = no cap)");
  check(ctx, c.correspondences.shape_scale > 0, "correspondences.shape_scale", "must be > 0 [m]");
  check(ctx, c.correspondences.fpfh_max_per_class >= 1, "correspondences.fpfh_max_per_class",
        "must be >= 1");
  const auto& th = c.graph.thresholds;
  check(ctx, !th.empty() && th.size() <= 32, "graph.thresholds", "needs 1 to 32 levels");
  for (std::size_t i = 0; i < th.size(); ++i) {
    const std::string path = "graph.thresholds[" + std::to_string(i) + "]";
    check(ctx, th[i] > 0, path, "must be > 0");
    check(ctx, i == 0 || th[i] > th[i - 1], path, "thresholds must increase strictly");
  }
  check(ctx, c.graph.sigma_ratio > 0, "graph.sigma_ratio", "must be > 0");
  check(ctx, c.graph.min_length >= 0, "graph.min_length", "must be >= 0 [m]");
  check(ctx, c.clique.tol_u > 0, "clique.tol_u", "must be > 0");
  check(ctx, c.clique.tol_F > 0, "clique.tol_F", "must be > 0");
  check(ctx, c.clique.beta > 0 && c.clique.beta < 1, "clique.beta", "must be in (0, 1)");
  check(ctx, c.clique.max_inner_iterations >= 1, "clique.max_inner_iterations", "must be >= 1");
  check(ctx, c.clique.max_outer_iterations >= 1, "clique.max_outer_iterations", "must be >= 1");
  check(ctx, c.clique.max_line_search >= 1, "clique.max_line_search", "must be >= 1");
  check(ctx, c.clique.eps > 0, "clique.eps", "must be > 0");
  check(ctx, c.clique.warm_start_mix >= 0, "clique.warm_start_mix", "must be >= 0");
  check(ctx, c.clique.warm_start_penalty >= 0 && c.clique.warm_start_penalty <= 1,
        "clique.warm_start_penalty", "must be in [0, 1]");
  check(ctx, c.clique.support_tol >= 0 && c.clique.support_tol < 1, "clique.support_tol",
        "must be in [0, 1)");
  check(ctx, c.clique.exact_max_nodes >= 1, "clique.exact_max_nodes", "must be >= 1");
  check(ctx, c.gnc.noise_bound > 0, "gnc.noise_bound", "must be > 0 [m]");
  check(ctx, c.gnc.mu_factor > 1, "gnc.mu_factor", "must be > 1");
  check(ctx, c.gnc.max_iterations >= 1, "gnc.max_iterations", "must be >= 1");
  check(ctx, c.gnc.cost_tolerance > 0, "gnc.cost_tolerance", "must be > 0");
  check(ctx, c.verification.voxel_size == 0 || c.verification.voxel_size >= kMinVoxelSize,
        "verification.voxel_size", "must be 0 (none) or at least 0.001 [m]");
  check(ctx, c.verification.mu > 0, "verification.mu", "must be > 0 [m]");
  const RefinementParams& r = c.refinement;
  check(ctx, r.max_iterations >= 1 && r.max_iterations <= 1000, "refinement.max_iterations",
        "must be in [1, 1000]");
  check(ctx, r.max_points >= 10 && r.max_points <= 1000000, "refinement.max_points",
        "must be in [10, 1000000]");
  check(ctx, r.min_distance > 0, "refinement.min_distance", "must be > 0 [m]");
  check(ctx, r.max_distance >= r.min_distance, "refinement.max_distance",
        "must be >= refinement.min_distance [m]");
  check(ctx, r.robust_scale > 0, "refinement.robust_scale", "must be > 0 [m]");
  check(ctx, r.normal_radius > 0, "refinement.normal_radius", "must be > 0 [m]");
  check(ctx, r.max_translation > 0, "refinement.max_translation", "must be > 0 [m]");
  check(ctx, r.max_rotation > 0 && r.max_rotation <= 180, "refinement.max_rotation",
        "must be in (0, 180] [deg]");
  check(ctx, c.acceptance.inlier_distance > 0, "acceptance.inlier_distance", "must be > 0 [m]");
  check(ctx, c.acceptance.ground_thickness >= 0, "acceptance.ground_thickness", "must be >= 0 [m]");
  check(ctx, c.acceptance.min_overlap >= 0 && c.acceptance.min_overlap <= 1,
        "acceptance.min_overlap", "must be in [0, 1]");
  check(ctx, c.acceptance.minimal_support_overlap >= 0 && c.acceptance.minimal_support_overlap <= 1,
        "acceptance.minimal_support_overlap", "must be in [0, 1]");
  check(ctx, c.acceptance.min_inliers >= 0, "acceptance.min_inliers", "must be >= 0");
  check(ctx, c.acceptance.min_margin >= 0 && c.acceptance.min_margin <= 1, "acceptance.min_margin",
        "must be in [0, 1]");
  check(ctx, c.evaluation.max_translation_error > 0, "evaluation.max_translation_error",
        "must be > 0 [m]");
  check(ctx, c.evaluation.max_rotation_error > 0, "evaluation.max_rotation_error",
        "must be > 0 [deg]");
  const IndoorParams& in = c.indoor;
  check(ctx, in.plan_spacing >= kMinVoxelSize, "indoor.plan_spacing", "must be >= 0.001 [m]");
  check(ctx, in.height_max > in.height_min, "indoor.height_max", "must be > height_min [m]");
  check(ctx, in.floor_voxel >= kMinVoxelSize, "indoor.floor_voxel", "must be >= 0.001 [m]");
  const ColumnDetectorParams& cd = in.columns;
  check(ctx, cd.cluster_tolerance > 0, "indoor.columns.cluster_tolerance", "must be > 0 [m]");
  check(ctx, cd.min_radius > 0, "indoor.columns.min_radius", "must be > 0 [m]");
  check(ctx, cd.max_radius > cd.min_radius, "indoor.columns.max_radius",
        "must be > min_radius [m]");
  check(ctx, cd.max_rms > 0, "indoor.columns.max_rms", "must be > 0 [m]");
  check(ctx, cd.min_points >= 3, "indoor.columns.min_points", "must be >= 3");
  check(ctx, cd.min_arc_deg >= 0 && cd.min_arc_deg <= 360, "indoor.columns.min_arc_deg",
        "must be in [0, 360] [deg]");
}

Config parse_config(const std::string& json_text, const std::string& origin,
                    const std::string& base_preset) {
  const Context ctx{origin};
  const json j = parse_json_limited(json_text, origin);
  if (!j.is_object()) throw ConfigError(origin + ": expected a JSON object at the top level");
  std::string preset = base_preset;
  if (const auto it = j.find("preset"); it != j.end()) decode(ctx, *it, "preset", preset);
  Config c;
  try {
    c = preset_config(preset);
  } catch (const ConfigError& e) {
    fail(ctx, "preset", e.what());
  }
  for (const auto& item : j.items()) {
    const std::string& key = item.key();
    const json& v = item.value();
    if (key == "preset")
      continue;
    else if (key == "label_scheme")
      decode_scheme(ctx, v, c.label_scheme);
    else if (key == "landmarks")
      decode(ctx, v, key, c.landmarks);
    else if (key == "correspondences")
      decode(ctx, v, key, c.correspondences);
    else if (key == "graph")
      decode(ctx, v, key, c.graph);
    else if (key == "clique")
      decode(ctx, v, key, c.clique);
    else if (key == "gnc")
      decode(ctx, v, key, c.gnc);
    else if (key == "verification")
      decode(ctx, v, key, c.verification);
    else if (key == "refinement")
      decode(ctx, v, key, c.refinement);
    else if (key == "acceptance")
      decode(ctx, v, key, c.acceptance);
    else if (key == "evaluation")
      decode(ctx, v, key, c.evaluation);
    else if (key == "indoor")
      decode(ctx, v, key, c.indoor);
    else
      fail(ctx, key, "unknown key");
  }
  validate(c, origin);
  return c;
}

Config load_config(const std::string& path, const std::string& base_preset) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": is a directory, expected a config file");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open config file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_config(ss.str(), path, base_preset);
}

std::string config_to_json(const Config& config, int indent) {
  return encode_config(config).dump(indent);
}

std::string section_json(const Config& config, const std::string& section) {
  const json j = encode_config(config);
  const auto it = j.find(section);
  assert(it != j.end() && "unknown config section");
  return it == j.end() ? std::string() : it->dump();
}

}  // namespace pagor
