#pragma once
// States the studio tests open, and where the shared data is.

#include <fstream>
#include <initializer_list>
#include <string>

#include "pagor/config.hpp"
#include "pagor/io/kitti.hpp"
#include "state/app_state.hpp"
#include "support/test_util.hpp"

namespace pagor::test {

inline std::string shared_data() {
  return PAGOR_SHARED_DATA;
}

/// semreg-dev pairs `names` ("03", ...) with their ground truths as a manifest in `tmp`.
inline std::string semreg_manifest(const TempDir& tmp, std::initializer_list<const char*> names) {
  const std::string d = shared_data() + "/semreg-dev/";
  const std::string path = tmp.file("pairs.txt");
  std::ofstream out(path);
  for (const char* n : names)
    out << d << n << "/source.pcd " << d << n << "/target.pcd gt=" << d << n
        << "/T_target_source.txt name=" << n << "\n";
  return path;
}

/// The configuration the semreg-dev benchmark runs with (its label scheme).
inline Config semreg_config() {
  return load_config(PAGOR_SOURCE_DIR "/bench/manifests/semreg-dev.json");
}

/// Keeps the dense clouds hidden: llvmpipe draws them in 25-100 ms a frame, the UI alone in
/// ~8 ms; the screenshot tests cover the cloud rendering.
inline void hide_clouds(studio::AppState& s) {
  s.view.layers.source = false;
  s.view.layers.target = false;
}

inline studio::AppState base_state(const TempDir& tmp) {
  studio::AppState s;
  s.session_path = tmp.file("session.json");
  s.screenshot_path = tmp.file("shot.png");
  hide_clouds(s);
  s.have_data = true;
  return s;
}

inline studio::AppState synthetic_state(const TempDir& tmp) {
  studio::AppState s = base_state(tmp);
  s.data.kind = PairSource::Kind::synthetic;
  s.data.synthetic_seed = 7;
  return s;
}

inline studio::AppState files_state(const TempDir& tmp) {
  studio::AppState s = base_state(tmp);
  s.data.kind = PairSource::Kind::files;
  s.data.source = shared_data() + "/semreg-dev/03/source.pcd";
  s.data.target = shared_data() + "/semreg-dev/03/target.pcd";
  return s;
}

/// files_state with the configuration of the semreg-dev benchmark.
inline studio::AppState semreg_files_state(const TempDir& tmp) {
  studio::AppState s = files_state(tmp);
  s.config = semreg_config();
  return s;
}

/// KITTI sequence 00, frames `source_frame` and `target_frame`, stepping through the dev pairs.
inline studio::AppState kitti_state(const TempDir& tmp, int source_frame = 20,
                                    int target_frame = 30) {
  studio::AppState s = base_state(tmp);
  s.data.kind = PairSource::Kind::kitti;
  s.data.kitti_root = PAGOR_KITTI_DIR;
  s.data.sequence = "00";
  s.data.source_frame = source_frame;
  s.data.target_frame = target_frame;
  s.pairs_file = std::string(PAGOR_KITTI_DIR) + "/pairs_00_dev.txt";
  s.pairs = studio::read_step_pairs(s.pairs_file, PAGOR_KITTI_DIR, "00");
  s.pair_index = studio::index_of_pair(s.pairs, s.data);
  return s;
}

}  // namespace pagor::test
