#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <limits>

#include "pagor/errors.hpp"
#include "pagor/io/clouds.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

PointCloud sample_cloud(bool labels, bool intensities) {
  PointCloud c;
  for (int i = 0; i < 50; ++i) {
    c.points.emplace_back(0.5f * i, -0.25f * i, 1.0f + 0.125f * i);
    if (labels) c.labels.push_back(static_cast<std::uint32_t>((i % 5) | (i << 16)));
    if (intensities) c.intensities.push_back(0.01f * i);
  }
  return c;
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace

TEST_CASE("KITTI .bin and .label round trip") {
  test::TempDir dir;
  const PointCloud c = sample_cloud(true, true);
  save_cloud(c, dir.file("scan.bin"));
  const LoadedCloud r = load_cloud(dir.file("scan.bin"), dir.file("scan.label"));
  REQUIRE(r.cloud.size() == c.size());
  CHECK(r.dropped_nonfinite == 0);
  for (std::size_t i = 0; i < c.size(); ++i) {
    CHECK(r.cloud.points[i] == c.points[i]);
    CHECK(r.cloud.intensities[i] == c.intensities[i]);
    CHECK(r.cloud.labels[i] == c.labels[i]);
  }
  CHECK(semantic_id(r.cloud.labels[7]) == 2);
}

TEST_CASE("a KITTI scan and its labels longer than one read come back whole") {
  // 10,001 points: 160 kB of points and 40 kB of labels, read in pieces of 64 kB.
  test::TempDir dir;
  PointCloud c;
  for (int i = 0; i < 10001; ++i) {
    c.points.emplace_back(0.5f * i, -0.25f * i, 1.0f + 1e-3f * i);
    c.intensities.push_back(static_cast<float>(i % 256) / 255.0f);
    c.labels.push_back(static_cast<std::uint32_t>(i * 2654435761u));
  }
  save_cloud(c, dir.file("long.bin"));
  const PointCloud r = read_kitti_bin(dir.file("long.bin"));
  const std::vector<std::uint32_t> labels = read_kitti_labels(dir.file("long.label"));
  REQUIRE(r.size() == c.size());
  CHECK(r.points == c.points);
  CHECK(r.intensities == c.intensities);
  CHECK(labels == c.labels);
  write_bytes(dir.file("long_odd.bin"), std::string(160016 + 3, '\0'));
  CHECK_THROWS_WITH(read_kitti_bin(dir.file("long_odd.bin")),
                    Catch::Contains("160019 bytes is not a multiple of 16"));
}

TEST_CASE("PCD and PLY round trip, with and without labels") {
  test::TempDir dir;
  for (const char* ext : {".pcd", ".ply"}) {
    for (bool labels : {false, true}) {
      INFO(ext << (labels ? " with labels" : " without labels"));
      const PointCloud c = sample_cloud(labels, true);
      const std::string path = dir.file(std::string("cloud") + (labels ? "_l" : "") + ext);
      save_cloud(c, path);
      const LoadedCloud r = load_cloud(path);
      REQUIRE(r.cloud.size() == c.size());
      CHECK(r.cloud.has_labels() == labels);
      REQUIRE(r.cloud.has_intensities());
      for (std::size_t i = 0; i < c.size(); ++i) {
        CHECK(r.cloud.points[i] == c.points[i]);
        CHECK(r.cloud.intensities[i] == c.intensities[i]);
        if (labels) CHECK(r.cloud.labels[i] == c.labels[i]);
      }
    }
  }
}

TEST_CASE("a .label file supplies labels to a PCD cloud") {
  test::TempDir dir;
  PointCloud c = sample_cloud(false, false);
  save_cloud(c, dir.file("c.pcd"));
  std::vector<std::uint32_t> labels(c.size(), 71u);
  write_kitti_labels(labels, dir.file("c.label"));
  const LoadedCloud r = load_cloud(dir.file("c.pcd"), dir.file("c.label"));
  REQUIRE(r.cloud.labels.size() == c.size());
  CHECK(r.cloud.labels.front() == 71u);
}

TEST_CASE("non-finite points are dropped and counted, labels stay aligned") {
  test::TempDir dir;
  PointCloud c = sample_cloud(true, true);
  c.points[3].x() = std::numeric_limits<float>::quiet_NaN();
  c.points[10].z() = std::numeric_limits<float>::infinity();
  save_cloud(c, dir.file("nan.bin"));
  const LoadedCloud r = load_cloud(dir.file("nan.bin"), dir.file("nan.label"));
  CHECK(r.dropped_nonfinite == 2);
  REQUIRE(r.cloud.size() == c.size() - 2);
  CHECK(r.cloud.labels[3] == c.labels[4]);  // point 3 was dropped, 4 moved up
  CHECK(r.cloud.labels[9] == c.labels[11]);
  REQUIRE(r.warnings.size() == 1);
  CHECK_THAT(r.warnings[0], Catch::Contains("dropped 2 points"));
}

TEST_CASE("bad input gives an InputError naming the file") {
  test::TempDir dir;
  SECTION("missing file") {
    CHECK_THROWS_WITH(load_cloud(dir.file("missing.bin")),
                      Catch::Contains("missing.bin") && Catch::Contains("does not exist"));
  }
  SECTION(".bin size not a multiple of 16") {
    write_bytes(dir.file("odd.bin"), std::string(20, '\0'));
    CHECK_THROWS_AS(load_cloud(dir.file("odd.bin")), InputError);
    CHECK_THROWS_WITH(load_cloud(dir.file("odd.bin")),
                      Catch::Contains("odd.bin") && Catch::Contains("not a multiple of 16"));
  }
  SECTION("label count differs from point count") {
    save_cloud(sample_cloud(false, true), dir.file("c.bin"));
    write_kitti_labels(std::vector<std::uint32_t>(49, 1u), dir.file("short.label"));
    CHECK_THROWS_WITH(load_cloud(dir.file("c.bin"), dir.file("short.label")),
                      Catch::Contains("short.label") && Catch::Contains("49 labels for 50 points"));
  }
  SECTION("label file size not a multiple of 4") {
    save_cloud(sample_cloud(false, true), dir.file("c.bin"));
    write_bytes(dir.file("bad.label"), std::string(7, '\0'));
    CHECK_THROWS_WITH(load_cloud(dir.file("c.bin"), dir.file("bad.label")),
                      Catch::Contains("bad.label"));
  }
  SECTION("empty cloud") {
    write_bytes(dir.file("empty.bin"), "");
    CHECK_THROWS_WITH(load_cloud(dir.file("empty.bin")),
                      Catch::Contains("empty.bin") && Catch::Contains("empty"));
  }
  SECTION("only non-finite points") {
    PointCloud c;
    c.points.assign(3, Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN()));
    save_cloud(c, dir.file("nan.bin"));
    CHECK_THROWS_WITH(load_cloud(dir.file("nan.bin")), Catch::Contains("no finite points"));
  }
  SECTION("unknown extension") {
    write_bytes(dir.file("cloud.xyz"), "1 2 3\n");
    CHECK_THROWS_WITH(load_cloud(dir.file("cloud.xyz")),
                      Catch::Contains("unknown point-cloud extension"));
  }
  SECTION("garbage PCD and PLY") {
    write_bytes(dir.file("bad.pcd"), "this is not a point cloud\n");
    CHECK_THROWS_WITH(load_cloud(dir.file("bad.pcd")), Catch::Contains("bad.pcd"));
    write_bytes(dir.file("bad.ply"), "this is not a point cloud\n");
    CHECK_THROWS_WITH(load_cloud(dir.file("bad.ply")), Catch::Contains("bad.ply"));
  }
  SECTION("truncated binary PCD") {
    save_cloud(sample_cloud(true, true), dir.file("full.pcd"));
    std::ifstream in(dir.file("full.pcd"), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Keep the header and half of the 50 x 20 byte body.
    const std::size_t body = bytes.find("DATA binary\n") + 12;
    write_bytes(dir.file("cut.pcd"), bytes.substr(0, body + 500));
    CHECK_THROWS_WITH(load_cloud(dir.file("cut.pcd")),
                      Catch::Contains("cut.pcd") && Catch::Contains("truncated"));
  }
  SECTION("a directory instead of a file") {
    CHECK_THROWS_WITH(read_kitti_bin(dir.file("")), Catch::Contains("directory"));
  }
}
