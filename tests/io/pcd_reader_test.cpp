// The project's PCD reader and LZF decoder against known answers: hand-made files of every DATA
// kind, PCL's own binary_compressed writer, the real semreg-dev clouds, and malformed headers;
// and the project's PCD and PLY writers against PCL's readers.

#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <catch2/catch.hpp>
#include <cstring>
#include <fstream>
#include <sstream>

#include "pagor/errors.hpp"
#include "pagor/io/clouds.hpp"
#include "io/lzf.hpp"
#include "io/pcd_reader.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

std::string header(const std::string& fields, const std::string& sizes, const std::string& types,
                   int points, const std::string& data, const std::string& counts = "") {
  std::ostringstream h;
  h << "# .PCD v0.7\nVERSION 0.7\nFIELDS " << fields << "\nSIZE " << sizes << "\nTYPE " << types
    << "\n";
  if (!counts.empty()) h << "COUNT " << counts << "\n";
  h << "WIDTH " << points << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << points << "\nDATA "
    << data << "\n";
  return h.str();
}

template <class T>
void put(std::string& s, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  s.append(b, sizeof(T));
}

// An LZF stream of literal runs only (valid LZF, no compression).
std::string lzf_literals(const std::string& raw) {
  std::string out;
  for (std::size_t i = 0; i < raw.size(); i += 32) {
    const std::size_t n = std::min<std::size_t>(32, raw.size() - i);
    out += static_cast<char>(n - 1);
    out += raw.substr(i, n);
  }
  return out;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("LZF: literal runs and overlapping back-references decode to known bytes") {
  // 'a', then a back-reference of 9 bytes at distance 1: ten 'a's.
  const std::uint8_t in[] = {0x00, 'a', 0xE0, 0x00, 0x00};
  std::uint8_t out[10];
  REQUIRE(lzf_decompress(in, sizeof(in), out, sizeof(out)));
  CHECK(std::string(reinterpret_cast<char*>(out), 10) == "aaaaaaaaaa");
  // "abc" then a 3-byte copy from 3 back: "abcabc".
  const std::uint8_t in2[] = {0x02, 'a', 'b', 'c', 0x20, 0x02};
  std::uint8_t out2[6];
  REQUIRE(lzf_decompress(in2, sizeof(in2), out2, sizeof(out2)));
  CHECK(std::string(reinterpret_cast<char*>(out2), 6) == "abcabc");
}

TEST_CASE("LZF: malformed streams are rejected without reading or writing out of bounds") {
  std::uint8_t out[16];
  const std::uint8_t before_start[] = {0x00, 'a', 0x20, 0x05};  // reference 6 back after 1 byte
  CHECK_FALSE(lzf_decompress(before_start, sizeof(before_start), out, sizeof(out)));
  const std::uint8_t short_literal[] = {0x05, 'a', 'b'};  // run of 6 with 2 bytes left
  CHECK_FALSE(lzf_decompress(short_literal, sizeof(short_literal), out, sizeof(out)));
  const std::uint8_t too_long[] = {0x00, 'a', 0xE0, 0xFF, 0x00};  // 264 bytes into 16
  CHECK_FALSE(lzf_decompress(too_long, sizeof(too_long), out, sizeof(out)));
  const std::uint8_t cut[] = {0x00, 'a', 0xE0};  // length byte missing
  CHECK_FALSE(lzf_decompress(cut, sizeof(cut), out, sizeof(out)));
  const std::uint8_t exact[] = {0x00, 'a'};  // decodes to 1 byte, 16 expected
  CHECK_FALSE(lzf_decompress(exact, sizeof(exact), out, sizeof(out)));
  CHECK(lzf_decompress(exact, sizeof(exact), out, 1));
  CHECK(lzf_decompress(nullptr, 0, out, 0));
}

TEST_CASE("PCD ascii, binary and binary_compressed give the same known cloud") {
  const float xyz[3][3] = {{1.5f, -2.0f, 0.25f}, {3.0f, 4.0f, 5.0f}, {-1.0f, 0.0f, 1e6f}};
  const std::uint32_t labels[3] = {10, 40 | (7u << 16), 4294967295u};
  const float intensity[3] = {0.5f, 0.75f, 1.0f};

  std::string ascii = header("x y z intensity label", "4 4 4 4 4", "F F F F U", 3, "ascii");
  for (int i = 0; i < 3; ++i) {
    std::ostringstream row;
    row.precision(9);
    row << xyz[i][0] << " " << xyz[i][1] << " " << xyz[i][2] << " " << intensity[i] << " "
        << labels[i] << "\r\n";
    ascii += row.str();
  }
  std::string binary = header("x y z intensity label", "4 4 4 4 4", "F F F F U", 3, "binary");
  for (int i = 0; i < 3; ++i) {
    for (float v : xyz[i]) put(binary, v);
    put(binary, intensity[i]);
    put(binary, labels[i]);
  }
  std::string raw;  // binary_compressed bodies store field after field
  for (int f = 0; f < 3; ++f)
    for (int i = 0; i < 3; ++i) put(raw, xyz[i][f]);
  for (int i = 0; i < 3; ++i) put(raw, intensity[i]);
  for (int i = 0; i < 3; ++i) put(raw, labels[i]);
  const std::string packed = lzf_literals(raw);
  std::string compressed =
      header("x y z intensity label", "4 4 4 4 4", "F F F F U", 3, "binary_compressed");
  put(compressed, static_cast<std::uint32_t>(packed.size()));
  put(compressed, static_cast<std::uint32_t>(raw.size()));
  compressed += packed;

  for (const std::string* bytes : {&ascii, &binary, &compressed}) {
    const PointCloud c = parse_pcd(*bytes, "t.pcd");
    REQUIRE(c.size() == 3);
    REQUIRE(c.has_labels());
    REQUIRE(c.has_intensities());
    for (int i = 0; i < 3; ++i) {
      CHECK(c.points[static_cast<std::size_t>(i)] ==
            Eigen::Vector3f(xyz[i][0], xyz[i][1], xyz[i][2]));
      CHECK(c.labels[static_cast<std::size_t>(i)] == labels[i]);
      CHECK(c.intensities[static_cast<std::size_t>(i)] == intensity[i]);
    }
  }
}

TEST_CASE("PCD: other field types, COUNT > 1 and unknown fields") {
  // x as double, y as int16, z as uint8, a 3-element field skipped, label as float.
  std::string b = header("x y z rgb3 label", "8 2 1 4 4", "F I U F F", 2, "binary", "1 1 1 3 1");
  for (int i = 0; i < 2; ++i) {
    put(b, 0.5 + i);
    put(b, static_cast<std::int16_t>(-3 - i));
    put(b, static_cast<std::uint8_t>(200 + i));
    for (int k = 0; k < 3; ++k) put(b, 9.0f);
    put(b, 20.0f + static_cast<float>(i));
  }
  const PointCloud c = parse_pcd(b, "t.pcd");
  REQUIRE(c.size() == 2);
  CHECK(c.points[1] == Eigen::Vector3f(1.5f, -4.0f, 201.0f));
  CHECK(c.labels[1] == 21u);
  CHECK_FALSE(c.has_intensities());
}

TEST_CASE("PCD binary_compressed written by PCL decodes to PCL's cloud") {
  pcl::PCLPointCloud2 blob;
  const char* names[] = {"x", "y", "z", "label"};
  for (int f = 0; f < 4; ++f) {
    pcl::PCLPointField field;
    field.name = names[f];
    field.offset = static_cast<std::uint32_t>(4 * f);
    field.datatype = f < 3 ? pcl::PCLPointField::FLOAT32 : pcl::PCLPointField::UINT32;
    field.count = 1;
    blob.fields.push_back(field);
  }
  const std::uint32_t n = 5000;
  blob.width = n;
  blob.height = 1;
  blob.point_step = 16;
  blob.row_step = 16 * n;
  blob.data.resize(16 * n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const float v[3] = {0.01f * static_cast<float>(i % 100), 2.0f,
                        -0.5f * static_cast<float>(i / 100)};
    const std::uint32_t label = i % 7;
    std::memcpy(&blob.data[16 * i], v, 12);
    std::memcpy(&blob.data[16 * i + 12], &label, 4);
  }
  test::TempDir dir;
  REQUIRE(pcl::PCDWriter().writeBinaryCompressed(dir.file("c.pcd"), blob) == 0);
  const std::string bytes = read_file(dir.file("c.pcd"));
  REQUIRE(bytes.find("DATA binary_compressed") != std::string::npos);
  const PointCloud c = parse_pcd(bytes, "c.pcd");
  REQUIRE(c.size() == n);
  for (std::uint32_t i = 0; i < n; i += 373) {
    CHECK(c.points[i] == Eigen::Vector3f(0.01f * static_cast<float>(i % 100), 2.0f,
                                         -0.5f * static_cast<float>(i / 100)));
    CHECK(c.labels[i] == i % 7);
  }
}

TEST_CASE("PCD and PLY written by save_cloud read back in PCL as written") {
  PointCloud cloud;
  for (int i = 0; i < 300; ++i) {
    cloud.points.emplace_back(0.25f * static_cast<float>(i), -3.0f + 0.001f * static_cast<float>(i),
                              12.0f);
    cloud.intensities.push_back(0.5f * static_cast<float>(i % 9));
    cloud.labels.push_back(static_cast<std::uint32_t>(i % 40) + 70000u);
  }
  test::TempDir dir;
  for (const char* name : {"c.pcd", "c.ply"}) {
    INFO(name);
    const std::string path = dir.file(name);
    save_cloud(cloud, path);
    pcl::PointCloud<pcl::PointXYZI> xyzi;
    pcl::PointCloud<pcl::PointXYZL> xyzl;
    if (std::string(name) == "c.pcd") {
      REQUIRE(pcl::io::loadPCDFile(path, xyzi) == 0);
      REQUIRE(pcl::io::loadPCDFile(path, xyzl) == 0);
    } else {
      REQUIRE(pcl::io::loadPLYFile(path, xyzi) == 0);
      REQUIRE(pcl::io::loadPLYFile(path, xyzl) == 0);
    }
    REQUIRE(xyzi.size() == cloud.size());
    REQUIRE(xyzl.size() == cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      CHECK(xyzi[i].getVector3fMap() == cloud.points[i]);
      CHECK(xyzi[i].intensity == cloud.intensities[i]);
      CHECK(xyzl[i].label == cloud.labels[i]);
    }
    // And the project's reader gives the cloud back.
    const LoadedCloud back = load_cloud(path);
    REQUIRE(back.cloud.size() == cloud.size());
    CHECK(back.cloud.labels == cloud.labels);
    CHECK(back.cloud.intensities == cloud.intensities);
  }
  // Without intensities or labels: x y z only.
  PointCloud bare;
  bare.points = {Eigen::Vector3f(1, 2, 3), Eigen::Vector3f(-4, 5, -6)};
  save_cloud(bare, dir.file("b.pcd"));
  const std::string bytes = read_file(dir.file("b.pcd"));
  CHECK(bytes.find("FIELDS x y z\n") != std::string::npos);
  pcl::PointCloud<pcl::PointXYZ> xyz;
  REQUIRE(pcl::io::loadPCDFile(dir.file("b.pcd"), xyz) == 0);
  REQUIRE(xyz.size() == 2);
  CHECK(xyz[1].getVector3fMap() == bare.points[1]);
}

TEST_CASE("PCD: the real semreg-dev clouds parse with their declared point counts") {
  const std::string path = test::kitti_root() + "/../semreg-dev/03/source.pcd";
  std::ifstream probe(path);
  if (!probe) return;  // shared data not present: nothing to compare against
  const PointCloud c = parse_pcd(read_file(path), path);
  CHECK(c.size() == 22022);
  CHECK(c.has_labels());
}

TEST_CASE("PCD: malformed input is an InputError saying what and where") {
  const auto fails = [](const std::string& bytes, const std::string& what) {
    CHECK_THROWS_WITH(parse_pcd(bytes, "bad.pcd"),
                      Catch::StartsWith("bad.pcd") && Catch::Contains(what));
  };
  fails("", "no DATA line");
  fails("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nPOINTS 1\n", "no DATA line");
  fails(header("x y z", "4 4 -4", "F F F", 1, "binary"), "SIZE -4");
  fails(header("x y z", "1 1 1", "F F F", 1, "binary"), "SIZE 1 with TYPE F");
  fails(header("x y z", "4 4 4", "F F", 1, "binary"), "3 fields but 3 sizes, 2 types");
  fails(header("x y", "4 4", "F F", 1, "ascii") + "1 2\n", "no x, y, z");
  fails(header("x y z", "4 4 4", "F F F", 1000000000, "binary") + std::string(24, '\0'),
        "truncated");
  fails(header("x y z", "4 4 4", "F F F", 2, "ascii") + "1 2 3\n", "has 1 rows");
  fails(header("x y z", "4 4 4", "F F F", 1, "ascii") + "1 2 3\n4 5 6\n", "bad.pcd:12: more rows");
  fails(header("x y z", "4 4 4", "F F F", 1, "ascii") + "1 2\n", "bad.pcd:11: expected 3 values");
  fails(header("x y z label", "4 4 4 4", "F F F U", 1, "ascii") + "1 2 3 -5\n",
        "'-5' is not a valid value for field label");
  fails(header("x y z label", "4 4 4 4", "F F F F", 1, "ascii") + "1 2 3 2.5\n", "label 2.5");
  fails(header("x y z", "4 4 4", "F F F", 1, "binary_compressed") + "\x01", "two 4-byte sizes");
  fails("VERSION 0.7\nBOGUS 1\n", "bad.pcd:2: not a PCD header line");
  fails("POINTS 1\nPOINTS 2\nFIELDS x\nFIELDS y\n", "bad.pcd:4: FIELDS given twice");
  fails("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nPOINTS 2\nDATA ascii\n", "WIDTH x HEIGHT");
  fails("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nPOINTS 18446744073709551616\nDATA ascii\n",
        "bad.pcd:4: POINTS needs one integer");
  std::string bc = header("x y z", "4 4 4", "F F F", 100, "binary_compressed");
  put(bc, std::uint32_t{3});
  put(bc, std::uint32_t{1200});
  bc += std::string("\x00\x01\x02", 3);
  fails(bc, "cannot hold");
  std::string bad_lzf = header("x y z", "4 4 4", "F F F", 1, "binary_compressed");
  put(bad_lzf, std::uint32_t{2});
  put(bad_lzf, std::uint32_t{12});
  bad_lzf += std::string("\x20\x05", 2);
  fails(bad_lzf, "not valid LZF");
}
