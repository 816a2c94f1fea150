#include <catch2/catch.hpp>

#include "pagor/kitti.hpp"
#include "pagor/pipeline.hpp"
#include "test_util.hpp"

using namespace pagor;

namespace {

Pipeline run_pair(int source, int target) {
  const KittiSequence seq(test::kitti_root(), "00");
  Pipeline p;
  p.set_input(seq.load_frame(source).cloud, seq.load_frame(target).cloud);
  p.set_ground_truth(seq.ground_truth(source, target));
  p.run();
  return p;
}

}  // namespace

TEST_CASE("KITTI 0 -> 20 and 20 -> 30 succeed with the default config (2 m / 5 deg)") {
  for (const auto& [s, t] : {std::pair{0, 20}, std::pair{20, 30}}) {
    INFO("pair " << s << " -> " << t);
    const Pipeline p = run_pair(s, t);
    const auto err = p.selected_error();
    REQUIRE(err);
    INFO("errors " << err->translation << " m, " << err->rotation_deg << " deg");
    CHECK(err->success);
    CHECK(p.upper_bound_success());
  }
}

TEST_CASE("KITTI 0 -> 30 (26.6 m apart) runs and is reported") {
  const Pipeline p = run_pair(0, 30);
  REQUIRE(p.level_errors().size() == p.cliques().size());
  // Not required to succeed: the selection and its errors exist or the failure is explicit.
  if (p.selected_level() >= 0)
    CHECK(p.selected_error().has_value());
  else
    CHECK_FALSE(p.warnings().empty());
}

TEST_CASE("an unlabelled KITTI pair runs on class-agnostic keypoints and succeeds") {
  const KittiSequence seq(test::kitti_root(), "00");
  PointCloud source = seq.load_frame(20).cloud, target = seq.load_frame(30).cloud;
  source.labels.clear();
  target.labels.clear();
  Pipeline p;
  p.set_input(std::move(source), std::move(target));
  p.set_ground_truth(seq.ground_truth(20, 30));
  p.run();
  const auto& classes = p.source_landmarks().classes;
  REQUIRE(!classes.empty());
  CHECK(classes.back().name == "structure");
  CHECK(classes.back().landmarks > 100);
  const auto err = p.selected_error();
  REQUIRE(err);
  INFO("errors " << err->translation << " m, " << err->rotation_deg << " deg");
  CHECK(err->success);
}
