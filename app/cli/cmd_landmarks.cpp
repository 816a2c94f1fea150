// pagor landmarks: per-class landmark extraction on one cloud.

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "command.hpp"
#include "common/outputs.hpp"
#include "pagor/errors.hpp"
#include "pagor/front/landmarks.hpp"

namespace pagor::cli {
namespace {

// Centroids as the file has them: `origin` is the cloud's frame origin (types.hpp).
nlohmann::json landmarks_json(const LandmarkSet& set, const std::string& name, bool with_indices,
                              const Eigen::Vector3d& origin) {
  using nlohmann::json;
  json classes = json::array();
  for (const auto& c : set.classes)
    classes.push_back({{"name", c.name},
                       {"method", to_string(c.method)},
                       {"points", c.points},
                       {"voxels", c.voxels},
                       {"landmarks", c.landmarks},
                       {"time_ms", c.time_ms}});
  json items = json::array();
  for (const auto& lm : set.landmarks) {
    json cov = json::array();
    for (int r = 0; r < 3; ++r)
      cov.push_back({lm.covariance(r, 0), lm.covariance(r, 1), lm.covariance(r, 2)});
    const Eigen::Vector3d c = origin.isZero() ? lm.centroid : Eigen::Vector3d(lm.centroid + origin);
    json item = {{"class", set.classes[static_cast<std::size_t>(lm.class_index)].name},
                 {"kind", lm.kind == LandmarkKind::cluster ? "cluster" : "keypoint"},
                 {"centroid", {c.x(), c.y(), c.z()}},
                 {"covariance", cov},
                 {"point_count", lm.point_count}};
    if (with_indices) item["point_indices"] = lm.point_indices;
    items.push_back(item);
  }
  return {{"cloud", name},
          {"units", "m"},
          {"classes", classes},
          {"landmarks", items},
          {"warnings", set.warnings},
          {"time_ms", set.time_ms}};
}

}  // namespace

std::vector<Option> landmarks_options() {
  std::vector<Option> o = single_cloud_options();
  o.push_back({"config", 1, "FILE", "configuration JSON (default: built-in outdoor defaults)"});
  o.push_back({"json", 1, "OUT", "write the landmarks as JSON"});
  o.push_back({"with-indices", 0, "", "include each landmark's point indices in the JSON"});
  return o;
}

int run_landmarks(const Args& args) {
  if (args.has("json")) check_outputs({{"--json", args.get("json")}}, option_inputs(args));
  const Config config = config_from_args(args).config;
  std::string name;
  const auto t0 = std::chrono::steady_clock::now();
  const LoadedCloud loaded = load_single_cloud(args, name);
  const double load_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  for (const auto& w : loaded.warnings) warn(w);
  std::printf("cloud: %s\n", name.c_str());
  std::printf("loaded %zu points in %.1f ms (%zu dropped with NaN/Inf or corrupt coordinates)\n",
              loaded.cloud.size(), load_ms, loaded.dropped_nonfinite + loaded.dropped_far);
  LandmarkSet set;
  with_config_origin(args, [&] {
    set = extract_landmarks(loaded.cloud, config.label_scheme, config.landmarks);
    // One cloud alone: the class-agnostic keypoints as the pipeline would add them to a pair.
    if (needs_fallback(loaded.cloud, loaded.cloud, set, set, config.landmarks.fallback))
      add_fallback_landmarks(loaded.cloud, config.label_scheme, config.landmarks, set);
  });
  for (const auto& w : set.warnings) warn(name + ": " + w);
  std::printf("labels: %s\n", labels_text(set.labels).c_str());
  std::printf("\n%-14s %-8s %9s %11s %9s %9s %10s %10s\n", "class", "method", "points",
              "spacing [m]", "voxel [m]", "voxels", "landmarks", "time [ms]");
  for (const auto& c : set.classes)
    std::printf("%-14s %-8s %9zu %11.3f %9.2f %9zu %10zu %10.1f\n", c.name.c_str(),
                to_string(c.method), c.points, c.spacing, c.voxel_size, c.voxels, c.landmarks,
                c.time_ms);
  std::printf("%-14s %-8s %9s %11s %9s %9s %10zu %10.1f\n", "total", "", "", "", "", "",
              set.landmarks.size(), set.time_ms);
  if (config.landmarks.adapt_to_spacing)
    std::printf(
        "(voxels are never finer than a class's point spacing: landmarks.adapt_to_spacing)\n");

  if (args.has("json")) {
    write_text_file(args.get("json"),
                    landmarks_json(set, name, args.has("with-indices"), loaded.cloud.origin)
                            .dump(2, ' ', false, nlohmann::json::error_handler_t::replace) +
                        "\n");
    std::printf("wrote %s\n", args.get("json").c_str());
  }
  return 0;
}

}  // namespace pagor::cli
