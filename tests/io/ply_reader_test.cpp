// The project's PLY reader against known answers: ascii, binary little and big endian, elements
// before and after the vertices, list properties, and malformed files.

#include <catch2/catch.hpp>
#include <cstring>
#include <string>

#include "pagor/errors.hpp"
#include "io/ply_reader.hpp"

using namespace pagor;

namespace {

template <class T>
void put(std::string& s, T v, bool big) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  for (std::size_t i = 0; i < sizeof(T); ++i) s += b[big ? sizeof(T) - 1 - i : i];
}

const char* kHeaderTail =
    "element vertex 2\n"
    "property float x\nproperty float y\nproperty double z\n"
    "property list uchar int extra\n"
    "property uint label\nproperty float intensity\n"
    "element face 1\nproperty list uchar int vertex_indices\n"
    "end_header\n";

std::string binary_file(bool big) {
  std::string s = std::string("ply\nformat ") +
                  (big ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\ncomment made by a test\nobj_info nothing\n"
                  "element camera 1\nproperty list ushort uchar name\nproperty short k\n" +
                  kHeaderTail;
  put<std::uint16_t>(s, 3, big);  // camera: a list of 3 uchars and a short
  s += "abc";
  put<std::int16_t>(s, -7, big);
  for (int i = 0; i < 2; ++i) {
    put<float>(s, 1.0f + static_cast<float>(i), big);
    put<float>(s, -2.0f, big);
    put<double>(s, 0.125 * i, big);
    put<std::uint8_t>(s, 2, big);
    put<std::int32_t>(s, 5, big);
    put<std::int32_t>(s, 6, big);
    put<std::uint32_t>(s, 40u + static_cast<std::uint32_t>(i), big);
    put<float>(s, 0.5f, big);
  }
  put<std::uint8_t>(s, 3, big);  // face
  for (int k = 0; k < 3; ++k) put<std::int32_t>(s, k, big);
  return s;
}

void check_known(const PointCloud& c) {
  REQUIRE(c.size() == 2);
  REQUIRE(c.has_labels());
  REQUIRE(c.has_intensities());
  CHECK(c.points[0] == Eigen::Vector3f(1.0f, -2.0f, 0.0f));
  CHECK(c.points[1] == Eigen::Vector3f(2.0f, -2.0f, 0.125f));
  CHECK(c.labels[1] == 41u);
  CHECK(c.intensities[0] == 0.5f);
}

}  // namespace

TEST_CASE("PLY binary little and big endian, with lists and other elements") {
  check_known(parse_ply(binary_file(false), "le.ply"));
  check_known(parse_ply(binary_file(true), "be.ply"));
}

TEST_CASE("PLY ascii") {
  const std::string s = std::string("ply\r\nformat ascii 1.0\r\n") +
                        "element camera 1\nproperty list uchar uchar name\n" + kHeaderTail +
                        "2 7 8\n"
                        "1 -2 0 2 5 6 40 0.5\n\n"
                        "2 -2 0.125 0 41 0.5\n"
                        "3 0 1 2\n";
  check_known(parse_ply(s, "a.ply"));
}

TEST_CASE("PLY: malformed input is an InputError saying what and where") {
  const auto fails = [](const std::string& bytes, const std::string& what) {
    CHECK_THROWS_WITH(parse_ply(bytes, "bad.ply"),
                      Catch::StartsWith("bad.ply") && Catch::Contains(what));
  };
  const std::string head = "ply\nformat binary_little_endian 1.0\n";
  fails("", "not a PLY file");
  fails("ply\n obj_info end_headerelement vertex", "no end_header");
  fails(head + "element vertmx -5\nelement vertex 0\nend_header\n", "bad.ply:3: expected 'element");
  fails("ply\nend_header\n", "no format line");
  fails(head + "property float x\nend_header\n", "bad.ply:3: property before any element");
  fails(head + "element vertex 1\nproperty half x\nend_header\n", "bad.ply:4: expected 'property");
  fails(head + "element vertex 1\nproperty float x\nproperty float y\nend_header\n", "no x, y, z");
  fails(head + "element face 1\nproperty float a\nend_header\n", "no 'vertex' element");
  const std::string xyz =
      "element vertex 1000000000\nproperty float x\nproperty float y\nproperty float z\n";
  fails(head + xyz + "end_header\n" + std::string(24, '\0'), "more than the 24 bytes");
  fails(head + "element face 1000000000000\nproperty float a\n" + xyz + "end_header\n",
        "element 'face': 1000000000000 records");
  fails(head + "element face 2\nproperty list uint int a\n" + xyz + "end_header\n" +
            std::string("\xff\xff\xff\x0f", 4),
        "list 'a'");
  fails(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar label\nend_header\n1 2 3 300\n",
      "bad.ply:9: element 'vertex' record 0: '300' is not a valid value for property 'label'");
  fails(
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n1 2 3\n",
      "declares 2 records, more than the 6 bytes");
  fails(
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n1 2 3\n\n\n\n\n\n\n\n",
      "bad.ply: element 'vertex' record 1: the file ends");
  fails(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n1 2 3 4\n",
      "1 values more than its properties");
}
