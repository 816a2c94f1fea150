#include <catch2/catch.hpp>
#include <map>

#include "pagor/config.hpp"
#include "pagor/errors.hpp"
#include "pagor/eval/synthetic.hpp"
#include "pagor/front/landmarks.hpp"

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
                set.labels.scheme.ids_of(name)[0]);
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
  Config config = default_config();
  // One label value for every point says nothing of its numbering (auto reads it as unlabelled).
  config.label_scheme = builtin_label_scheme("semantickitti-train");
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
  REQUIRE(set.warnings.size() == 1);  // auto: not used, one warning for the cloud
  CHECK(set.warnings[0].find("labels not used: every point carries label 9999") !=
        std::string::npos);
  CHECK(set.labels.scheme.name == "none");
  // Configured by hand, the scheme is used and the warning says the labels do not fit it.
  const LabelScheme train = builtin_label_scheme("semantickitti-train");
  const LandmarkSet misread = extract_landmarks(cloud, train, config.landmarks);
  REQUIRE(misread.warnings.size() == config.landmarks.classes.size() + 1);
  CHECK(misread.warnings[0].find("labels do not fit scheme 'semantickitti-train'") !=
        std::string::npos);
}

TEST_CASE("labels numbered by another scheme are detected and that scheme is named") {
  const SyntheticScene scene = make_synthetic_scene();  // semantickitti-train labels
  const Config config = default_config();
  const LabelScheme train = builtin_label_scheme("semantickitti-train");
  const auto mismatch = [](const PointCloud& c, const LabelScheme& s) {
    return read_labels(c, s).mismatch;
  };
  CHECK(mismatch(scene.source, train).empty());

  // A class-poor street in the training numbering, as a segmentation network labels it:
  // vegetation 14, terrain 16, road 8, sidewalk 10, building 12, a few trunks 15 and poles 17.
  PointCloud street;
  for (const auto& [id, n] : std::map<std::uint32_t, int>{
           {14, 6000}, {16, 2500}, {8, 1200}, {10, 300}, {12, 200}, {15, 60}, {17, 50}})
    for (int i = 0; i < n; ++i) {
      street.points.emplace_back(0.1f * i, static_cast<float>(id), 0.0f);
      street.labels.push_back(id);
    }
  CHECK(mismatch(street, train).empty());
  PointCloud shifted = street;  // the learning map: the same classes, numbered from 1
  for (auto& l : shifted.labels) l = semantic_id(l) + 1;
  const std::string m = mismatch(shifted, train);
  CHECK_THAT(m, Catch::Contains("do not fit scheme 'semantickitti-train'") &&
                    Catch::Contains("look like 'semantickitti-learning'"));
  const LabelScheme learning = builtin_label_scheme("semantickitti-learning");
  CHECK(mismatch(shifted, learning).empty());
  CHECK(learning.ids_of("car") == std::vector<std::uint32_t>{1});
  CHECK(learning.ids_of("traffic-sign") == std::vector<std::uint32_t>{19});

  PointCloud instances = scene.source;  // raw labels carry an instance id in the upper 16 bits
  for (auto& l : instances.labels) l |= 7u << 16;
  CHECK(mismatch(instances, train).empty());
}

TEST_CASE("point spacing is estimated and class parameters follow it") {
  std::vector<Eigen::Vector3f> grid;  // a 0.3 m grid on a plane
  for (int x = 0; x < 60; ++x)
    for (int y = 0; y < 60; ++y) grid.emplace_back(0.3f * x, 0.3f * y, 0.0f);
  CHECK(estimate_spacing(grid) == Approx(0.3).margin(1e-4));
  CHECK(estimate_spacing({}) == 0.0);
  const std::vector<int> row{0, 1, 2, 3};  // a subset along one grid line
  CHECK(estimate_spacing(grid, &row) == Approx(0.3).margin(1e-4));

  LandmarkParams all;
  ClassParams trunk{"trunk", LandmarkMethod::cluster};
  trunk.voxel_size = 0.1;
  trunk.cluster_tolerance = 0.3;
  trunk.min_points = 8;
  trunk.max_points = 1000;
  const ClassParams finer = params_for_spacing(trunk, 0.05, all);  // data finer: unchanged
  CHECK(finer.voxel_size == trunk.voxel_size);
  CHECK(finer.min_points == trunk.min_points);
  const ClassParams coarse = params_for_spacing(trunk, 0.3, all);
  CHECK(coarse.voxel_size == Approx(0.3));
  CHECK(coarse.cluster_tolerance == Approx(all.tolerance_spacings * 0.3));
  CHECK(coarse.min_points == all.min_cluster_voxels);  // 8 * (0.1/0.3)^2 < 3
  CHECK(coarse.max_points == 112);                     // 1000 * (0.1/0.3)^2, rounded up
  all.adapt_to_spacing = false;
  CHECK(params_for_spacing(trunk, 0.3, all).voxel_size == trunk.voxel_size);
}

TEST_CASE("an unlabelled cloud gets class-agnostic keypoints above the ground") {
  const SyntheticScene scene = make_synthetic_scene();
  const Config config = default_config();
  PointCloud cloud = scene.source;
  cloud.labels.clear();
  LandmarkSet set = extract_landmarks(cloud, config.label_scheme, config.landmarks);
  CHECK(needs_fallback(cloud, cloud, set, set, config.landmarks.fallback));
  add_fallback_landmarks(cloud, config.label_scheme, config.landmarks, set);
  REQUIRE(set.classes.size() == config.landmarks.classes.size() + 1);
  CHECK(set.classes.back().name == "structure");
  CHECK(set.classes.back().landmarks > 100);
  // the keypoint budget of a cloud without labels
  CHECK(set.classes.back().landmarks <=
        static_cast<std::size_t>(config.landmarks.fallback.unlabelled_keypoints));
  CHECK(set.classes.back().one_way_matches == config.landmarks.fallback.unlabelled_matches);
  const float ground = ground_layer_top(cloud.points, 0.0f);
  for (const auto& lm : set.landmarks) {
    CHECK(lm.class_index == static_cast<int>(set.classes.size()) - 1);
    CHECK(lm.centroid.z() > ground);
  }
  // A labelled, class-rich scene does not need them; "never" turns them off.
  const LandmarkSet rich = extract_landmarks(scene.source, config.label_scheme, config.landmarks);
  FallbackParams never = config.landmarks.fallback;
  never.mode = FallbackMode::never;
  CHECK_FALSE(needs_fallback(cloud, cloud, set, set, never));
  FallbackParams always = never;
  always.mode = FallbackMode::always;
  CHECK(needs_fallback(scene.source, scene.source, rich, rich, always));
}

TEST_CASE("classes whose ids are large or shared pick the same points as small distinct ids") {
  // Points are sorted into classes in one pass when every id is small and in one class; other
  // schemes take a pass per class. Both must pick the same points.
  const SyntheticScene scene = make_synthetic_scene();
  const Config config = default_config();
  const LandmarkSet plain = extract_landmarks(scene.source, config.label_scheme, config.landmarks);
  // The same labels moved to ids above 4000 (the upper 16 bits, the instance, kept).
  LabelScheme big = builtin_label_scheme("semantickitti-train");
  for (auto& c : big.classes)
    for (auto& id : c.ids) id += 4000;
  PointCloud moved = scene.source;
  for (auto& l : moved.labels) l = (l & 0xFFFF0000u) | (semantic_id(l) + 4000);
  const LandmarkSet large = extract_landmarks(moved, big, config.landmarks);
  // A scheme where a second class (an extra landmark class) shares the car's ids.
  LandmarkParams twice = config.landmarks;
  twice.classes.push_back(twice.classes[0]);
  const LandmarkSet shared = extract_landmarks(scene.source, config.label_scheme, twice);
  for (const LandmarkSet* set : {&large, &shared}) {
    REQUIRE(set->classes.size() >= plain.classes.size());
    for (std::size_t c = 0; c < plain.classes.size(); ++c) {
      INFO("class " << plain.classes[c].name);
      CHECK(set->classes[c].points == plain.classes[c].points);
      CHECK(set->classes[c].landmarks == plain.classes[c].landmarks);
    }
  }
  CHECK(shared.classes.back().points == plain.classes[0].points);
  CHECK(shared.classes.back().landmarks == plain.classes[0].landmarks);
}
