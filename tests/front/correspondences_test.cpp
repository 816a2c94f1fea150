#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "pagor/config.hpp"
#include "pagor/eval/synthetic.hpp"
#include "pagor/front/correspondences.hpp"
#include "pagor/front/landmarks.hpp"

using namespace pagor;

namespace {

PointCloud transformed(const PointCloud& c, const Transform& T) {
  PointCloud out = c;
  for (auto& p : out.points)
    p = (T.block<3, 3>(0, 0) * p.cast<double>() + T.block<3, 1>(0, 3)).cast<float>();
  return out;
}

}  // namespace

TEST_CASE("cluster classes are matched all-to-all") {
  const SyntheticScene scene = make_synthetic_scene();
  Config config = default_config();
  config.correspondences.max_correspondences = 0;  // no cap
  const LandmarkSet s = extract_landmarks(scene.source, config.label_scheme, config.landmarks);
  const LandmarkSet t = extract_landmarks(scene.target, config.label_scheme, config.landmarks);
  const CorrespondenceSet c = match_landmarks(s, t, config.correspondences);
  CHECK_FALSE(c.capped);
  for (std::size_t ci = 0; ci < 3; ++ci) {
    INFO("class " << config.landmarks.classes[ci].name);
    CHECK(c.per_class[ci] == s.classes[ci].landmarks * t.classes[ci].landmarks);
  }
  for (const auto& x : c.items) {
    CHECK(s.landmarks[static_cast<std::size_t>(x.source)].class_index == x.class_index);
    CHECK(t.landmarks[static_cast<std::size_t>(x.target)].class_index == x.class_index);
    CHECK(x.score >= 0.0);
    CHECK(x.score <= 1.0);
  }
}

TEST_CASE("the cap keeps the best-scored correspondences and says so") {
  const SyntheticScene scene = make_synthetic_scene();
  Config config = default_config();
  config.correspondences.max_correspondences = 0;
  const LandmarkSet s = extract_landmarks(scene.source, config.label_scheme, config.landmarks);
  const LandmarkSet t = extract_landmarks(scene.target, config.label_scheme, config.landmarks);
  const CorrespondenceSet all = match_landmarks(s, t, config.correspondences);
  config.correspondences.max_correspondences = 40;
  const CorrespondenceSet capped = match_landmarks(s, t, config.correspondences);
  CHECK(capped.capped);
  CHECK(capped.items.size() == 40);
  CHECK(capped.candidates == all.items.size());
  REQUIRE_FALSE(capped.warnings.empty());
  double lowest_kept = 1.0;
  for (const auto& x : capped.items) lowest_kept = std::min(lowest_kept, x.score);
  std::size_t better_than_lowest = 0;
  for (const auto& x : all.items) better_than_lowest += x.score > lowest_kept;
  CHECK(better_than_lowest < 40);
}

TEST_CASE("true cluster correspondences score high: alike extents") {
  const SyntheticScene scene = make_synthetic_scene();
  Config config = default_config();
  const LandmarkSet s = extract_landmarks(scene.source, config.label_scheme, config.landmarks);
  const LandmarkSet t = extract_landmarks(scene.target, config.label_scheme, config.landmarks);
  const CorrespondenceSet c = match_landmarks(s, t, config.correspondences);
  const Transform& T = scene.T_target_source;
  double true_mean = 0, n_true = 0;
  for (const auto& x : c.items) {
    if (x.class_index > 2) continue;  // clustered classes: cars, trunks, poles
    const Eigen::Vector3d tp = T.block<3, 3>(0, 0) * x.p + T.block<3, 1>(0, 3);
    if ((tp - x.q).norm() < 0.3) {
      true_mean += x.score;
      ++n_true;
    }
  }
  REQUIRE(n_true >= 8);
  CHECK(true_mean / n_true > 0.8);
}

TEST_CASE("FPFH mutual matches on a scene moved by a known transform are mostly true") {
  const SyntheticScene scene = make_synthetic_scene();
  Config config = default_config();
  Transform T = Transform::Identity();
  T.block<3, 3>(0, 0) = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.block<3, 1>(0, 3) = Eigen::Vector3d(5.0, -3.0, 0.2);
  const PointCloud moved = transformed(scene.source, T);
  const LandmarkSet s = extract_landmarks(scene.source, config.label_scheme, config.landmarks);
  const LandmarkSet t = extract_landmarks(moved, config.label_scheme, config.landmarks);
  const CorrespondenceSet c = match_landmarks(s, t, config.correspondences);
  const int building = 4;
  REQUIRE(config.landmarks.classes[building].name == "building");
  const double voxel = config.landmarks.classes[building].voxel_size;
  std::size_t matches = 0, correct = 0;
  for (const auto& x : c.items) {
    if (x.class_index != building) continue;
    ++matches;
    const Eigen::Vector3d tp = T.block<3, 3>(0, 0) * x.p + T.block<3, 1>(0, 3);
    correct += (tp - x.q).norm() < 2 * voxel;
  }
  INFO(correct << " of " << matches << " FPFH matches are within two voxels of the truth");
  REQUIRE(matches >= 30);
  CHECK(static_cast<double>(correct) / matches > 0.5);
}

TEST_CASE("no landmarks give no correspondences and no crash") {
  const LandmarkSet empty;
  const CorrespondenceSet c = match_landmarks(empty, empty);
  CHECK(c.items.empty());
  CHECK(c.candidates == 0);
}
