#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>

#include "pagor/config.hpp"
#include "pagor/errors.hpp"
#include "pagor/front/landmarks.hpp"
#include "pagor/io/kitti.hpp"
#include "support/test_util.hpp"
#include "util/voxel_grid.hpp"

using namespace pagor;

namespace {

double rotation_deg(const Transform& T) {
  const double c = std::clamp((T.block<3, 3>(0, 0).trace() - 1.0) / 2.0, -1.0, 1.0);
  return std::acos(c) * 180.0 / 3.14159265358979323846;
}

// The cloud voxelised at `voxel` [m] the way a semantic pipeline would: one point per voxel at
// the mean of its points, carrying the label most of them have.
PointCloud voxelised(const PointCloud& in, double voxel) {
  const VoxelDownsample ds = voxel_downsample(in.points, voxel);
  std::vector<std::map<std::uint32_t, int>> votes(ds.points.size());
  for (std::size_t i = 0; i < in.size(); ++i)
    ++votes[static_cast<std::size_t>(ds.voxel_of[i])][semantic_id(in.labels[i])];
  PointCloud out;
  out.points = ds.points;
  for (const auto& v : votes)
    out.labels.push_back(std::max_element(v.begin(), v.end(), [](auto& a, auto& b) {
                           return a.second < b.second;
                         })->first);
  return out;
}

// Fraction of the landmarks of class `c` in `a` with a landmark of the same class in `b` within
// `distance` [m].
double matched_fraction(const LandmarkSet& a, const LandmarkSet& b, int c, double distance) {
  int total = 0, matched = 0;
  for (const auto& x : a.landmarks) {
    if (x.class_index != c) continue;
    ++total;
    for (const auto& y : b.landmarks)
      if (y.class_index == c && (x.centroid - y.centroid).norm() < distance) {
        ++matched;
        break;
      }
  }
  return total ? static_cast<double>(matched) / total : 1.0;
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

TEST_CASE("KITTI frames voxelised at 0.3 m give the landmarks of the full-resolution scans") {
  constexpr double kSameLandmark = 1.0;  // [m] centroid shift allowed by 0.3 m voxels
  const KittiSequence seq(test::kitti_root(), "00");
  // Measured: 80-100 % found, 0-42 % extra (small fragments of poles and trunks that pass the
  // rescaled minimum size) on frames 0, 20, 30.
  constexpr double kMinFound = 0.75, kMaxExtra = 0.5;
  const Config config = default_config();
  Config fixed = config;  // the parameters counted in voxels, as before spacing adaptation
  fixed.landmarks.adapt_to_spacing = false;
  double found_total = 0, found_fixed_total = 0;
  for (int frame : {0, 20, 30}) {
    const PointCloud full = seq.load_frame(frame).cloud;
    const PointCloud coarse = voxelised(full, 0.3);
    const LandmarkSet a = extract_landmarks(full, config.label_scheme, config.landmarks);
    const LandmarkSet b = extract_landmarks(coarse, config.label_scheme, config.landmarks);
    const LandmarkSet b_fixed = extract_landmarks(coarse, fixed.label_scheme, fixed.landmarks);
    CHECK(a.classes[0].spacing < 0.1);   // full-resolution cars: finer than their voxels
    CHECK(b.classes[0].spacing > 0.15);  // voxelised: coarser than the trunk and pole voxels
    for (int c = 0; c < 3; ++c) {        // car, trunk, pole
      const double found = matched_fraction(a, b, c, kSameLandmark);
      const double extra = 1.0 - matched_fraction(b, a, c, kSameLandmark);
      INFO("frame " << frame << " " << config.landmarks.classes[c].name << ": "
                    << a.classes[c].landmarks << " full, " << b.classes[c].landmarks
                    << " voxelised; found " << found << ", extra " << extra);
      CHECK(found >= kMinFound);
      CHECK(extra <= kMaxExtra);
      found_total += found;
      found_fixed_total += matched_fraction(a, b_fixed, c, kSameLandmark);
    }
  }
  CHECK(found_total > found_fixed_total + 1.0);  // adaptation finds what fixed sizes lose
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
  CHECK(set.classes[4].name == "building");
  CHECK(set.classes[4].landmarks >= 200);
  for (const auto& lm : set.landmarks) CHECK(lm.centroid.norm() < 120.0);  // within sensor range
}

TEST_CASE("the pairs file is read, and bad sequences and frames are reported") {
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

TEST_CASE("a sequence opened again sees its poses file as it is now") {
  // The poses are parsed once for each content of the file: rewritten with the same size (and
  // possibly the same time), the new poses are read.
  test::TempDir dir;
  std::filesystem::create_directories(dir.file("sequences/02"));
  std::ofstream(dir.file("sequences/02/calib.txt")) << "Tr: 1 0 0 0 0 1 0 0 0 0 1 0\n";
  std::ofstream(dir.file("sequences/02/poses.txt")) << "1 0 0 1 0 1 0 0 0 0 1 0\n";
  const KittiSequence first(dir.file(""), "02");
  CHECK(first.camera_pose(0)(0, 3) == 1.0);
  CHECK(KittiSequence(dir.file(""), "02").camera_pose(0)(0, 3) == 1.0);
  std::ofstream(dir.file("sequences/02/poses.txt")) << "1 0 0 2 0 1 0 0 0 0 1 0\n";
  CHECK(KittiSequence(dir.file(""), "02").camera_pose(0)(0, 3) == 2.0);
  CHECK(first.camera_pose(0)(0, 3) == 1.0);  // an opened sequence keeps what it read
  std::ofstream(dir.file("sequences/02/poses.txt")) << "1 0 0 2 0 1 0 0 0 0 1\n";
  CHECK_THROWS_WITH(KittiSequence(dir.file(""), "02"), Catch::Contains("poses.txt:1"));
}
