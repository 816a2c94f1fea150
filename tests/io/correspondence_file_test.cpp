#include <catch2/catch.hpp>
#include <fstream>

#include "pagor/io/correspondence_file.hpp"
#include "pagor/errors.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

// The message of the InputError `text` raises, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_correspondence_file(text, "c.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a correspondences file with comments, blank lines, commas and all columns") {
  const std::string text =
      "# matcher output\n"
      "\n"
      "1 2 3  4 5 6  0.5 1   # first\n"
      "  -1.5,0,2e-1, 7,8,9, 1, 0\r\n"
      "# trailing comment\n";
  const CorrespondenceFile f = parse_correspondence_file(text, "c.txt");
  REQUIRE(f.items.size() == 2);
  CHECK(f.items[0].p == Eigen::Vector3d(1, 2, 3));
  CHECK(f.items[0].q == Eigen::Vector3d(4, 5, 6));
  CHECK(f.items[1].p == Eigen::Vector3d(-1.5, 0, 0.2));
  CHECK(f.items[1].q == Eigen::Vector3d(7, 8, 9));
  CHECK(f.weights == std::vector<double>{0.5, 1.0});
  CHECK(f.items[0].score == 0.5);
  CHECK(f.inlier == std::vector<char>{1, 0});
  CHECK(f.lines == std::vector<int>{3, 4});
  // Every correspondence has its own landmarks, so no pair is excluded for sharing one.
  CHECK(f.items[0].source == 0);
  CHECK(f.items[1].source == 1);
  CHECK(f.items[1].target == 1);
}

TEST_CASE("six columns: no weights, no flags") {
  const CorrespondenceFile f = parse_correspondence_file("0 0 0 1 1 1\n2 2 2 3 3 3\n");
  CHECK(f.items.size() == 2);
  CHECK(f.weights.empty());
  CHECK(f.inlier.empty());
  CHECK(f.items[1].score == 1.0);
}

TEST_CASE("malformed lines are errors naming the file and the line") {
  CHECK(error_of("1 2 3 4 5\n") ==
        "c.txt:1: expected 6 to 8 columns (px py pz qx qy qz [weight "
        "[inlier]]), got 5");
  CHECK(error_of("# c\n1 2 3 4 5 6 1 1\n1 2 3 4 5 6 1\n") ==
        "c.txt:3: 7 columns, but line 2 has 8");
  CHECK(error_of("1 2 3 4 5 x\n") == "c.txt:1: qz 'x' is not a finite number (column 11)");
  CHECK(error_of("1 2 3 4 5 6\n1 2 nan 4 5 6\n") ==
        "c.txt:2: pz 'nan' is not a finite number (column 5)");
  CHECK(error_of("1 2 3 4 5 6 1e999\n") ==
        "c.txt:1: weight '1e999' is not a finite number (column 13)");
  CHECK(error_of("1 2 3 4 5 6 -1\n") == "c.txt:1: weight '-1' is negative");
  CHECK(error_of("1 2 3 4 5 6 1 2\n") == "c.txt:1: inlier flag '2' is not 0 or 1");
  CHECK(error_of("1 2 3 4 5 6 1 yes\n") == "c.txt:1: inlier flag 'yes' is not 0 or 1");
  CHECK(error_of("1 2 3 4 5 6 1 1 9\n") ==
        "c.txt:1: expected 6 to 8 columns (px py pz qx qy qz [weight [inlier]]), got 9");
  CHECK(error_of("# nothing\n\n") == "c.txt: no correspondences");
  CHECK(error_of("") == "c.txt: no correspondences");
}

TEST_CASE("reading a file, and a missing file names its path") {
  test::TempDir dir;
  const std::string path = dir.file("c.txt");
  std::ofstream(path) << "0 0 0 1 1 1 1 1\n0 1 0 1 2 1 1 0\n";
  const CorrespondenceFile f = read_correspondence_file(path);
  CHECK(f.items.size() == 2);
  CHECK(f.inlier == std::vector<char>{1, 0});
  std::ofstream(path) << "0 0 0 1 1 1 1 3\n";
  CHECK_THROWS_WITH(read_correspondence_file(path), path + ":1: inlier flag '3' is not 0 or 1");
  CHECK_THROWS_WITH(read_correspondence_file(dir.file("nope.txt")),
                    dir.file("nope.txt") + ": correspondences file does not exist");
}

TEST_CASE("precision and recall against the flags") {
  const std::vector<char> flags = {1, 1, 0, 1, 0};
  const InlierQuality q = inlier_quality({0, 2, 3}, flags);
  CHECK(q.selected == 3);
  CHECK(q.true_inliers == 2);
  CHECK(q.inliers == 3);
  CHECK(q.precision == Approx(2.0 / 3));
  CHECK(q.recall == Approx(2.0 / 3));
  const InlierQuality none = inlier_quality({}, flags);
  CHECK(none.precision == 0.0);
  CHECK(none.recall == 0.0);
  CHECK(inlier_quality({2}, {0, 0, 0}).recall == 0.0);
  CHECK_THROWS_AS(inlier_quality({7}, flags), std::out_of_range);
}

TEST_CASE("a correspondences file holds at most what the consistency graph takes") {
  // 100 000 lines once made the graph ask for 4.2 GB; the reader stops at the budget, naming the
  // file, the line and the budget.
  std::string text = "# header\n";
  for (std::size_t i = 0; i < kMaxFileCorrespondences; ++i) text += "0 0 0 1 1 1\n";
  CHECK(parse_correspondence_file(text, "c.txt").items.size() == kMaxFileCorrespondences);
  text += "0 0 0 1 1 1\n";
  CHECK_THAT(
      error_of(text),
      Catch::Contains("c.txt:" + std::to_string(kMaxFileCorrespondences + 2) + ": more than " +
                      std::to_string(kMaxFileCorrespondences) + " correspondences") &&
          Catch::Contains("kMaxGraphCorrespondences"));
  test::TempDir dir;
  const std::string path = dir.file("huge.txt");
  std::ofstream(path) << std::string(kMaxCorrespondenceFileBytes + 1, '#');
  CHECK_THROWS_WITH(
      read_correspondence_file(path),
      Catch::Contains("huge.txt: correspondences file is ") && Catch::Contains("more than the"));
  CHECK_THROWS_WITH(read_correspondence_file("/dev/zero"),
                    Catch::Contains("/dev/zero: correspondences file is a character device"));
}

TEST_CASE("hexadecimal is not a coordinate: an error naming the line and the column") {
  // strtod read 0x10 as 16.
  CHECK(error_of("0x10 2 3 4 5 6\n") ==
        "c.txt:1: px '0x10' is not a finite number (column 1; numbers are decimal, hexadecimal "
        "is not read)");
  CHECK(error_of("1 2 3 4 5 6\n1, 2, 3, 4, -0X1p3, 6\n") ==
        "c.txt:2: qy '-0X1p3' is not a finite number (column 13; numbers are decimal, "
        "hexadecimal is not read)");
  CHECK(error_of("1 2 3 4 5 6 0x1\n") ==
        "c.txt:1: weight '0x1' is not a finite number (column 13; numbers are decimal, "
        "hexadecimal is not read)");
  CHECK(error_of("1 2 3 4 5 inf\n") == "c.txt:1: qz 'inf' is not a finite number (column 11)");
  // Decimal forms are all read.
  const CorrespondenceFile f = parse_correspondence_file("+1 .5 -2. 1e3 -3E-1 0\n", "c.txt");
  CHECK(f.items[0].p == Eigen::Vector3d(1, 0.5, -2));
  CHECK(f.items[0].q == Eigen::Vector3d(1000, -0.3, 0));
}

TEST_CASE("a coordinate beyond 1e7 m is corrupt: an error naming the line and the column") {
  CHECK(error_of("1 2 3 4 5 6\n1 2 3 1e30 5 6\n") ==
        "c.txt:2: qx '1e30' lies farther than 1e7 m from the origin, corrupt (column 7)");
  CHECK(error_of("-2e7 2 3 4 5 6\n") ==
        "c.txt:1: px '-2e7' lies farther than 1e7 m from the origin, corrupt (column 1)");
  // A georeferenced frame (a national grid, 300 km and 5,000 km out) is read as it is.
  const CorrespondenceFile f =
      parse_correspondence_file("300000.25 5000000 10 300001.5 5000001 11\n", "c.txt");
  CHECK(f.items[0].p == Eigen::Vector3d(300000.25, 5000000, 10));
  CHECK(f.items[0].q == Eigen::Vector3d(300001.5, 5000001, 11));
  // A weight is not a coordinate: a large one is kept.
  CHECK(parse_correspondence_file("1 2 3 4 5 6 1e30\n").weights == std::vector<double>{1e30});
}
