#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

#include "pagor/config.hpp"
#include "pagor/errors.hpp"
#include "pagor/kitti.hpp"
#include "pagor/landmarks.hpp"
#include "test_util.hpp"

using namespace pagor;

namespace {

double rotation_deg(const Transform& T) {
  const double c = std::clamp((T.block<3, 3>(0, 0).trace() - 1.0) / 2.0, -1.0, 1.0);
  return std::acos(c) * 180.0 / 3.14159265358979323846;
}

}  // namespace

TEST_CASE("ground truth of the shared pairs matches the README figures") {
  const KittiSequence seq(test::kitti_root(), "00");
  CHECK(seq.pose_count() == 4541);
  struct Expected {
    int s, t;
    double trans, rot;
  };
  for (const Expected e :
       {Expected{0, 20, 17.30, 2.7}, Expected{20, 30, 9.30, 0.6}, Expected{0, 30, 26.60, 2.5}}) {
    INFO("pair " << e.s << " -> " << e.t);
    const Transform T = seq.ground_truth(e.s, e.t);
    CHECK(T.block<3, 1>(0, 3).norm() == Approx(e.trans).margin(0.01));
    CHECK(rotation_deg(T) == Approx(e.rot).margin(0.05));
    // A rigid transform: orthonormal rotation.
    CHECK((T.block<3, 3>(0, 0) * T.block<3, 3>(0, 0).transpose() - Eigen::Matrix3d::Identity())
              .norm() < 1e-6);
  }
}

TEST_CASE("a KITTI frame loads with its labels") {
  const KittiSequence seq(test::kitti_root(), "00");
  const LoadedCloud c = seq.load_frame(0);
  CHECK(c.cloud.size() > 100000);
  CHECK(c.cloud.has_labels());
  CHECK(c.cloud.labels.size() == c.cloud.size());
}

TEST_CASE("landmarks of KITTI frame 0 have sensible per-class counts") {
  const KittiSequence seq(test::kitti_root(), "00");
  const LoadedCloud c = seq.load_frame(0);
  const Config config = default_config();
  const LandmarkSet set = extract_landmarks(c.cloud, config.label_scheme, config.landmarks);
  // A street scene: several parked cars, trees and poles, and building facades.
  CHECK(set.classes[0].landmarks >= 5);
  CHECK(set.classes[0].landmarks <= 40);
  CHECK(set.classes[1].landmarks >= 5);
  CHECK(set.classes[2].landmarks >= 3);
  CHECK(set.classes[3].landmarks >= 200);
  for (const auto& lm : set.landmarks) CHECK(lm.centroid.norm() < 120.0);  // within sensor range
}

TEST_CASE("the pairs file is read; bad sequences and frames are reported") {
  const auto pairs = read_pairs_file(test::kitti_root() + "/pairs_00_dev.txt");
  REQUIRE(pairs.size() == 3);
  CHECK(pairs[0] == std::make_pair(0, 20));
  CHECK_THROWS_WITH(KittiSequence(test::kitti_root(), "99"), Catch::Contains("sequences/99"));
  const KittiSequence seq(test::kitti_root(), "00");
  CHECK_THROWS_WITH(seq.load_frame(5), Catch::Contains("000005.bin"));
  CHECK_THROWS_WITH(seq.ground_truth(0, 99999), Catch::Contains("no pose for frame 99999"));

  test::TempDir dir;
  std::ofstream(dir.file("pairs.txt")) << "0 20\n# comment\n\n7 x\n";
  CHECK_THROWS_WITH(read_pairs_file(dir.file("pairs.txt")),
                    Catch::Contains("pairs.txt:4") && Catch::Contains("two frame numbers"));
}

TEST_CASE("a malformed poses.txt names the file and line") {
  test::TempDir dir;
  std::filesystem::create_directories(dir.file("sequences/01"));
  std::ofstream(dir.file("sequences/01/poses.txt")) << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0\n";
  std::ofstream(dir.file("sequences/01/calib.txt")) << "P0: 1 2 3\n";
  CHECK_THROWS_WITH(KittiSequence(dir.file(""), "01"), Catch::Contains("poses.txt:2"));
  std::ofstream(dir.file("sequences/01/poses.txt")) << "1 0 0 0 0 1 0 0 0 0 1 0\n";
  CHECK_THROWS_WITH(KittiSequence(dir.file(""), "01"), Catch::Contains("no 'Tr:' line"));
}
