#include <catch2/catch.hpp>
#include <map>

#include "pagor/config.hpp"
#include "pagor/errors.hpp"
#include "pagor/landmarks.hpp"
#include "pagor/synthetic.hpp"

using namespace pagor;

namespace {
constexpr double kCentroidTolerance = 0.1;  // [m] voxel means vs. exact surface means, plus noise
}

TEST_CASE("clusters of a synthetic scene are its objects, at their known centroids") {
  const SyntheticScene scene = make_synthetic_scene();
  const Config config = default_config();
  const LandmarkSet set = extract_landmarks(scene.source, config.label_scheme, config.landmarks);
  REQUIRE(set.classes.size() == config.landmarks.classes.size());

  for (std::size_t ci = 0; ci < 3; ++ci) {  // car, trunk, pole: clustered classes
    const std::string name = config.landmarks.classes[ci].name;
    INFO("class " << name);
    std::vector<const Landmark*> found;
    for (const auto& lm : set.landmarks)
      if (lm.class_index == static_cast<int>(ci)) found.push_back(&lm);
    std::vector<const SyntheticObject*> expected;
    for (const auto& o : scene.objects)
      if (o.class_name == name && o.in_source) expected.push_back(&o);
    REQUIRE(!expected.empty());
    REQUIRE(found.size() == expected.size());
    CHECK(set.classes[ci].landmarks == expected.size());
    // Every object has exactly one landmark at its centroid (the source frame is the world frame).
    for (const auto* o : expected) {
      int hits = 0;
      for (const auto* lm : found)
        if ((lm->centroid - o->centroid_world).norm() < kCentroidTolerance) ++hits;
      CHECK(hits == 1);
    }
    for (const auto* lm : found) {
      CHECK(lm->kind == LandmarkKind::cluster);
      CHECK(lm->point_count == lm->point_indices.size());
      for (int idx : lm->point_indices)
        REQUIRE(semantic_id(scene.source.labels[static_cast<std::size_t>(idx)]) ==
                config.label_scheme.ids_of(name)[0]);
    }
  }
  // Buildings become FPFH keypoints with a descriptor each.
  const int building = config.label_scheme.find("building") >= 0 ? 4 : -1;
  REQUIRE(config.landmarks.classes[static_cast<std::size_t>(building)].name == "building");
  CHECK(set.classes[static_cast<std::size_t>(building)].landmarks > 50);
  for (std::size_t i = 0; i < set.landmarks.size(); ++i)
    CHECK(set.descriptors[i].size() ==
          (set.landmarks[i].kind == LandmarkKind::keypoint ? 33u : 0u));
}

TEST_CASE("a cluster's covariance describes its shape") {
  const SyntheticScene scene = make_synthetic_scene();
  const Config config = default_config();
  const LandmarkSet set = extract_landmarks(scene.source, config.label_scheme, config.landmarks);
  for (const auto& lm : set.landmarks) {
    if (lm.class_index != 2) continue;  // poles: thin vertical cylinders 6 m high
    CHECK(lm.covariance(2, 2) > 2.0);   // uniform on 6 m: variance 3 m^2
    CHECK(lm.covariance(0, 0) < 0.02);
  }
}

TEST_CASE("a class with no points warns, a cloud without labels gives no semantic landmarks") {
  const Config config = default_config();
  PointCloud cloud;
  for (int i = 0; i < 100; ++i) {
    cloud.points.emplace_back(0.05f * i, 0.0f, 0.0f);
    cloud.labels.push_back(0);  // all cars
  }
  const LandmarkSet set = extract_landmarks(cloud, config.label_scheme, config.landmarks);
  CHECK(set.classes[0].landmarks == 1);
  CHECK(set.classes[1].landmarks == 0);
  bool warned = false;
  for (const auto& w : set.warnings)
    warned = warned || w.find("'trunk': no points") != std::string::npos;
  CHECK(warned);

  cloud.labels.clear();
  const LandmarkSet unlabelled = extract_landmarks(cloud, config.label_scheme, config.landmarks);
  CHECK(unlabelled.landmarks.empty());
  REQUIRE(unlabelled.warnings.size() == 1);  // one for the cloud, not one per class
  CHECK(unlabelled.warnings[0].find("no semantic labels") != std::string::npos);
}

TEST_CASE("clusters outside the size limits are dropped with a warning") {
  Config config = default_config();
  config.landmarks.classes[0].max_points = 10;  // every car is larger
  const SyntheticScene scene = make_synthetic_scene();
  const LandmarkSet set = extract_landmarks(scene.source, config.label_scheme, config.landmarks);
  CHECK(set.classes[0].landmarks == 0);
  bool warned = false;
  for (const auto& w : set.warnings) warned = warned || w.find("'car'") != std::string::npos;
  CHECK(warned);
}

TEST_CASE(
    "a cloud of unknown labels gives no landmarks, a warning per class and one on the scheme") {
  const Config config = default_config();
  PointCloud cloud;
  cloud.points.emplace_back(0.f, 0.f, 0.f);
  cloud.labels.push_back(9999);
  const LandmarkSet set = extract_landmarks(cloud, config.label_scheme, config.landmarks);
  CHECK(set.landmarks.empty());
  REQUIRE(set.warnings.size() == config.landmarks.classes.size() + 1);
  CHECK(set.warnings[0].find("labels do not fit scheme 'semantickitti-train'") !=
        std::string::npos);
}
