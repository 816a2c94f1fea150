// Detecting the numbering of a cloud's labels from their values: synthetic histograms of known
// numbering, and the shared real clouds in their own numbering and rewritten into the others.

#include <catch2/catch.hpp>
#include <map>

#include "pagor/front/label_detection.hpp"
#include "pagor/io/clouds.hpp"
#include "pagor/io/kitti.hpp"
#include "support/label_variants.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

// A cloud whose labels follow `counts` (label value -> points); positions do not matter.
PointCloud cloud_of(const std::map<std::uint32_t, int>& counts) {
  PointCloud c;
  for (const auto& [label, n] : counts)
    for (int i = 0; i < n; ++i) {
      c.points.emplace_back(0.1f * static_cast<float>(i), 0.0f, 0.0f);
      c.labels.push_back(label);
    }
  return c;
}

// A class-poor street in the learning map: vegetation 15, terrain 17, road 9, sidewalk 11,
// building 13, a few trunks 16 and poles 18, some unlabeled 0.
const std::map<std::uint32_t, int> kStreet = {{15, 6000}, {17, 2500}, {9, 1200}, {11, 300},
                                              {13, 200},  {16, 60},   {18, 50},  {0, 40}};

}  // namespace

TEST_CASE("a street's labels are detected in each SemanticKITTI numbering") {
  const PointCloud learning = cloud_of(kStreet);
  const LabelDetection l = detect_label_scheme(learning);
  CHECK(l.scheme == "semantickitti-learning");
  CHECK(l.known == Approx(1.0));
  CHECK(l.margin > 1.0);
  CHECK(l.instances == 0);
  const LabelDetection t = detect_label_scheme(test::learning_to_train(learning));
  CHECK(t.scheme == "semantickitti-train");
  CHECK(t.margin > 1.0);
  const LabelDetection r = detect_label_scheme(test::learning_to_raw(learning));
  CHECK(r.scheme == "semantickitti");
  CHECK(r.instances > learning.size() / 2);  // random instance ids, almost all non-zero
  CHECK(r.margin > 5.0);
}

TEST_CASE("an indoor scan's labels are the indoor scheme") {
  const LabelDetection d = detect_label_scheme(cloud_of({{1, 3000}, {2, 400}, {3, 100}, {4, 900}}));
  CHECK(d.scheme == "indoor");
  CHECK(d.runner_up == "semantickitti-learning");  // reads them as cars and bicycles
}

TEST_CASE("no labels, one label value or unknown ids detect no numbering") {
  PointCloud bare = cloud_of(kStreet);
  bare.labels.clear();
  CHECK(detect_label_scheme(bare).scheme == "none");
  CHECK(detect_label_scheme(bare).reason == "no labels");
  const LabelDetection one = detect_label_scheme(cloud_of({{0, 500}}));
  CHECK(one.scheme == "none");
  CHECK(one.reason == "every point carries label 0");
  const LabelDetection unknown = detect_label_scheme(cloud_of({{5000, 300}, {7000, 300}, {9, 10}}));
  CHECK(unknown.scheme == "none");
  CHECK_THAT(unknown.reason, Catch::Contains("ids of no known numbering"));
  CHECK(detect_label_scheme(PointCloud{}).scheme == "none");
}

TEST_CASE("read_labels: auto takes the detected numbering, none and missing labels read none") {
  const PointCloud street = cloud_of(kStreet);
  const LabelReading a = read_labels(street, builtin_label_scheme("auto"));
  CHECK(a.automatic);
  CHECK(a.scheme.name == "semantickitti-learning");
  CHECK(a.scheme.ids_of("vegetation") == std::vector<std::uint32_t>{15});
  CHECK(a.mismatch.empty());
  const LabelReading n = read_labels(street, builtin_label_scheme("none"));
  CHECK(n.scheme.ignores_labels());
  CHECK(n.detection.scheme == "semantickitti-learning");  // still said what they look like
  // A scheme set by hand is used as it is; labels that do not fit it are named, with the
  // numbering they look like.
  const LabelReading raw = read_labels(street, builtin_label_scheme("semantickitti"));
  CHECK(raw.scheme.name == "semantickitti");
  CHECK_THAT(raw.mismatch, Catch::Contains("do not fit scheme 'semantickitti'") &&
                               Catch::Contains("look like 'semantickitti-learning'"));
  CHECK(read_labels(street, builtin_label_scheme("semantickitti-learning")).mismatch.empty());
  // A custom scheme with the learning map's ids under the same names fits as well.
  LabelScheme custom = builtin_label_scheme("semantickitti-learning");
  custom.name = "mine";
  CHECK(read_labels(street, custom).mismatch.empty());
}

TEST_CASE("a numbering another explains almost as well is a warning, not a silent guess") {
  // A corridor in the training numbering whose pillars (trunk 15) are half the points (the
  // self-similar generator's): read as the learning map, trunk becomes vegetation, the commonest
  // class of a driving scan, and the floor (road 8) a motorcyclist; the two nearly tie.
  const PointCloud corridor =
      cloud_of({{15, 7400}, {12, 4400}, {8, 1100}, {13, 240}, {0, 1280}, {18, 170}});
  const LabelReading r = read_labels(corridor, builtin_label_scheme("auto"));
  CHECK(r.scheme.name == "semantickitti-learning");
  CHECK(r.detection.runner_up == "semantickitti-train");
  CHECK(r.detection.margin < 1.0);
  CHECK_THAT(numbering_doubt(r),
             Catch::Contains("read in numbering 'semantickitti-learning'") &&
                 Catch::Contains("'semantickitti-train' fits them almost as well") &&
                 Catch::Contains("set label_scheme"));
  // Set by hand, the numbering is the user's word; a street is far from a close call.
  CHECK(
      numbering_doubt(read_labels(corridor, builtin_label_scheme("semantickitti-train"))).empty());
  CHECK(numbering_doubt(read_labels(cloud_of(kStreet), builtin_label_scheme("auto"))).empty());
}

#ifdef PAGOR_HAVE_SEMREG_DATA
TEST_CASE("every semreg-dev cloud is detected as the learning map, and rewritten, as the others") {
  for (const char* pair : {"03", "04", "05", "06", "07", "08", "09", "10", "11", "12"})
    for (const char* side : {"source", "target"}) {
      const std::string path = std::string(PAGOR_SEMREG_DIR) + "/" + pair + "/" + side + ".pcd";
      INFO(path);
      const PointCloud c = load_cloud(path).cloud;
      const LabelDetection d = detect_label_scheme(c);
      CHECK(d.scheme == "semantickitti-learning");
      CHECK(d.margin > 1.5);
      CHECK(detect_label_scheme(test::learning_to_raw(c)).scheme == "semantickitti");
      CHECK(detect_label_scheme(test::learning_to_train(c)).scheme == "semantickitti-train");
      CHECK(read_labels(c, builtin_label_scheme("semantickitti-train")).mismatch != "");
    }
}
#endif

#ifdef PAGOR_HAVE_KITTI_DATA
TEST_CASE("the shared KITTI labels are detected as the training numbering") {
  const KittiSequence seq(test::kitti_root(), "00");
  for (int frame : {0, 20, 30}) {
    const LabelDetection d = detect_label_scheme(seq.load_frame(frame).cloud);
    CHECK(d.scheme == "semantickitti-train");
    CHECK(d.runner_up == "semantickitti-learning");
    CHECK(d.margin > 1.5);
  }
}
#endif
