#pragma once
// States the studio tests open, and where the shared data is.

#include <string>

#include "pagor/io/kitti.hpp"
#include "state/app_state.hpp"
#include "support/test_util.hpp"

namespace pagor::test {

inline std::string shared_data() {
  return PAGOR_SHARED_DATA;
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

inline studio::AppState kitti_state(const TempDir& tmp) {
  studio::AppState s = base_state(tmp);
  s.data.kind = PairSource::Kind::kitti;
  s.data.kitti_root = PAGOR_KITTI_DIR;
  s.data.sequence = "00";
  s.data.source_frame = 20;
  s.data.target_frame = 30;
  s.pairs_file = std::string(PAGOR_KITTI_DIR) + "/pairs_00_dev.txt";
  s.pairs = studio::read_step_pairs(s.pairs_file, PAGOR_KITTI_DIR, "00");
  s.pair_index = studio::index_of_pair(s.pairs, s.data);
  return s;
}

}  // namespace pagor::test
