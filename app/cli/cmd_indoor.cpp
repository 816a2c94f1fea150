// pagor indoor: generates an indoor sequence (a car park, its floor plan, ray-cast scans, ground
// truth and a pairs manifest for `pagor bench`) and measures the column detector on it.

#include <cstdio>
#include <filesystem>

#include "command.hpp"
#include "pagor/errors.hpp"
#include "pagor/eval/indoor_synthetic.hpp"

namespace pagor::cli {

std::vector<Option> indoor_options() {
  std::vector<Option> o = {
      {"out", 1, "DIR", "directory to write the sequence into (created if needed)"},
      {"scans", 1, "N", "number of scans along the trajectory (default 120)"},
      {"seed", 1, "S", "seed of the building, trajectory and noise (default 1)"}};
  for (Option& c : config_options_for("indoor")) o.push_back(std::move(c));
  return o;
}

int run_indoor(const Args& args) {
  if (!args.has("out")) throw UsageError("indoor needs --out DIR");
  const std::string dir = args.get("out");
  const int scans = args.get_int("scans", 120);
  if (scans < 1 || scans > 100000) throw UsageError("--scans must be in [1, 100000]");
  IndoorSceneParams scene;
  scene.seed = static_cast<std::uint64_t>(parse_int(args.get("seed", "1"), "--seed"));
  const std::string preset = args.get("preset", "indoor");
  const Config config =
      args.has("config") ? load_config(args.get("config"), preset) : preset_config(preset);

  std::printf("writing %d scans to %s (seed %llu) ...\n", scans, dir.c_str(),
              static_cast<unsigned long long>(scene.seed));
  write_indoor_sequence(dir, scene, scans);
  const IndoorWorld world = make_indoor_world(scene, scans);
  std::printf("plan: %zu walls, %zu columns; built: %zu obstacles not in the plan\n",
              world.plan.walls.size(), world.plan.columns.size(), world.obstacles.size());

  // The detector on the scans as written (read back), against the columns as built.
  DetectionScore total;
  char name[32];
  for (int k = 0; k < scans; ++k) {
    std::snprintf(name, sizeof(name), "scans/%06d.bin", k);
    const PointCloud scan = load_cloud((std::filesystem::path(dir) / name).string()).cloud;
    total += score_scan_columns(world, world.trajectory[static_cast<std::size_t>(k)], scan,
                                config.indoor);
  }
  std::printf(
      "column detector: recall %.1f %% (%d of %d visible columns), precision %.1f %% (%d of %d "
      "detections)\n",
      100.0 * total.recall(), total.found, total.visible, 100.0 * total.precision(),
      total.true_detections, total.detections);
  std::printf("run: pagor bench --manifest %s/pairs.txt --preset indoor\n", dir.c_str());
  return 0;
}

}  // namespace pagor::cli
