// Clouds far from their file's origin (georeferenced: 300 km out) keep their precision in a frame
// near their points, doubles included; corrupt points (1e30) are dropped with a warning naming
// the file; near the origin nothing changes. Poses move between the frames exactly.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cstring>
#include <fstream>

#include "pagor/errors.hpp"
#include "pagor/io/clouds.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

// A binary PCD of double (F 8) coordinates.
void write_pcd_f8(const std::string& path, const std::vector<Eigen::Vector3d>& points) {
  std::ofstream out(path, std::ios::binary);
  out << "VERSION .7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\nWIDTH " << points.size()
      << "\nHEIGHT 1\nPOINTS " << points.size() << "\nDATA binary\n";
  for (const auto& p : points) out.write(reinterpret_cast<const char*>(p.data()), 24);
}

// A KITTI .bin scan (float32 x, y, z, reflectance).
void write_bin(const std::string& path, const std::vector<Eigen::Vector3d>& points) {
  std::ofstream out(path, std::ios::binary);
  for (const auto& p : points) {
    const float v[4] = {float(p.x()), float(p.y()), float(p.z()), 0.0f};
    out.write(reinterpret_cast<const char*>(v), sizeof(v));
  }
}

// A 40 m patch of points with millimetre detail, around `centre`.
std::vector<Eigen::Vector3d> patch(const Eigen::Vector3d& centre) {
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < 400; ++i)
    out.push_back(
        centre + Eigen::Vector3d(0.1 * i - 20 + 0.001 * (i % 7), 0.05 * (i % 13), 0.002 * (i % 5)));
  return out;
}

}  // namespace

TEST_CASE("a double cloud 300 km out keeps millimetres in its own frame") {
  test::TempDir dir;
  const Eigen::Vector3d far(300000.0, 4500000.0, 120.0);
  const auto points = patch(far);
  write_pcd_f8(dir.file("far.pcd"), points);
  const LoadedCloud c = load_cloud(dir.file("far.pcd"));
  CHECK(c.cloud.origin == Eigen::Vector3d(300000, 4500000, 120));  // the median, in whole metres
  REQUIRE(c.cloud.size() == points.size());
  double worst = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    worst = std::max(
        worst,
        (c.cloud.points[i].cast<double>() + c.cloud.origin - points[i]).cwiseAbs().maxCoeff());
  CHECK(worst < 1e-5);  // float32 at 300 km alone would be off by up to 25 cm here
  CHECK(c.warnings.empty());
}

TEST_CASE("a float cloud far out moves to its own frame exactly, one near stays as it is") {
  test::TempDir dir;
  write_bin(dir.file("far.bin"), patch({300000.0, 0.0, 0.0}));
  const LoadedCloud far = load_cloud(dir.file("far.bin"));
  CHECK_FALSE(far.cloud.origin.isZero());
  const auto raw = read_kitti_bin(dir.file("far.bin"));
  for (std::size_t i = 0; i < raw.size(); ++i)
    CHECK((far.cloud.points[i].cast<double>() + far.cloud.origin) == raw.points[i].cast<double>());
  write_bin(dir.file("near.bin"), patch({15.0, -3.0, 1.0}));
  const LoadedCloud near = load_cloud(dir.file("near.bin"));
  CHECK(near.cloud.origin.isZero());
  CHECK(near.cloud.points == read_kitti_bin(dir.file("near.bin")).points);
}

TEST_CASE("a point at 1e30 is dropped with a warning naming the file") {
  test::TempDir dir;
  auto points = patch({10.0, 0.0, 0.0});
  points.insert(points.begin() + 17, Eigen::Vector3d(1e30, 0.0, 0.0));
  write_bin(dir.file("spike.bin"), points);
  const LoadedCloud c = load_cloud(dir.file("spike.bin"));
  CHECK(c.cloud.size() == points.size() - 1);
  CHECK(c.dropped_far == 1);
  REQUIRE(c.warnings.size() == 1);
  CHECK_THAT(c.warnings[0], Catch::Contains("spike.bin: dropped 1 points lying more than 1e6 m"));
  write_bin(dir.file("all.bin"), {Eigen::Vector3d(1e30, 0, 0), Eigen::Vector3d(1e30, -1e30, 0)});
  CHECK_THROWS_WITH(load_cloud(dir.file("all.bin")),
                    Catch::Contains("all.bin: no finite points within 1e6 m"));
}

TEST_CASE("doubles spanning too far for float32 say what was lost") {
  test::TempDir dir;
  std::vector<Eigen::Vector3d> points = patch({0.0, 0.0, 0.0});
  points.push_back({900000.123456, 0.0, 0.0});  // 900 km from the rest: 6 cm float steps there
  write_pcd_f8(dir.file("wide.pcd"), points);
  const LoadedCloud c = load_cloud(dir.file("wide.pcd"));
  REQUIRE(c.warnings.size() == 1);
  CHECK_THAT(c.warnings[0], Catch::Contains("wide.pcd: coordinates stored as float32 lose up to"));
}

TEST_CASE("poses move between the files' frames and the clouds' frames exactly") {
  Transform T = Transform::Identity();
  T.block<3, 3>(0, 0) = Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.1, 0.2, 1).normalized()).matrix();
  T.block<3, 1>(0, 3) = Eigen::Vector3d(12, -3, 0.5);
  const Eigen::Vector3d os(300000, 4500000, 100), ot(300020, 4500010, 99);
  const Transform local = to_cloud_frames(T, os, ot);
  // A point maps the same either way: p_file = p + o_s, q_file = q + o_t.
  const Eigen::Vector3d p(3, 4, 5);
  const Eigen::Vector3d q_file = T.block<3, 3>(0, 0) * (p + os) + T.block<3, 1>(0, 3);
  const Eigen::Vector3d q = local.block<3, 3>(0, 0) * p + local.block<3, 1>(0, 3);
  CHECK((q + ot - q_file).norm() < 1e-6);
  CHECK(to_file_frames(local, os, ot).isApprox(T, 1e-12));
  CHECK(to_cloud_frames(T, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()) == T);
}
