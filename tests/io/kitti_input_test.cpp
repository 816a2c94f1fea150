// KITTI metadata and pairs files from users: all-zero or non-rigid transforms and numbers that
// are not frame numbers end in an error naming the file and line. Runs on generated files.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "pagor/errors.hpp"
#include "pagor/io/kitti.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

const char* kIdentity = "1 0 0 0 0 1 0 0 0 0 1 0";

std::string make_sequence(const test::TempDir& dir, const std::string& poses,
                          const std::string& tr) {
  const std::filesystem::path seq = std::filesystem::path(dir.file("sequences")) / "00";
  std::filesystem::create_directories(seq);
  std::ofstream(seq / "poses.txt") << poses;
  std::ofstream(seq / "calib.txt") << "P0: 1 2 3\nTr: " << tr << "\n";
  return dir.file("");
}

void write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

}  // namespace

TEST_CASE("KITTI poses and Tr must be rigid transforms") {
  test::TempDir dir;
  const std::string good = std::string(kIdentity) + "\n" + "0 -1 0 5 1 0 0 2 0 0 1 1\n";
  CHECK(KittiSequence(make_sequence(dir, good, kIdentity), "00").pose_count() == 2);

  const std::string zeros = "0 0 0 0 0 0 0 0 0 0 0 0";
  CHECK_THROWS_WITH(KittiSequence(make_sequence(dir, good + zeros + "\n", kIdentity), "00"),
                    Catch::Contains("poses.txt:3: the pose is not a rigid transform"));
  CHECK_THROWS_WITH(KittiSequence(make_sequence(dir, good, zeros), "00"),
                    Catch::Contains("calib.txt:2: Tr is not a rigid transform"));
  CHECK_THROWS_WITH(KittiSequence(make_sequence(dir, good, "2 0 0 0 0 1 0 0 0 0 1 0"), "00"),
                    Catch::Contains("calib.txt:2: Tr is not a rigid transform"));
  CHECK_THROWS_WITH(
      KittiSequence(make_sequence(dir, "1 0 0 0 0 1 0 0 0 0 -1 0\n", kIdentity), "00"),
      Catch::Contains("poses.txt:1: the pose is not a rigid transform"));
  CHECK_THROWS_WITH(
      KittiSequence(make_sequence(dir, "1 0 0 nan 0 1 0 0 0 0 1 0\n", kIdentity), "00"),
      Catch::Contains("poses.txt:1: the pose: value 4 is not a finite number"));
  CHECK_THROWS_WITH(
      KittiSequence(make_sequence(dir, std::string(kIdentity) + " 7\n", kIdentity), "00"),
      Catch::Contains("poses.txt:1: the pose needs 12 numbers"));
}

TEST_CASE("pairs files: only two whole frame numbers per line, comments anywhere") {
  test::TempDir dir;
  write(dir.file("ok.txt"), "# comment\n0 20\n\n  5\t30  \r\n7 9  # the loop at the bridge\n");
  const auto pairs = read_pairs_file(dir.file("ok.txt"));
  REQUIRE(pairs.size() == 3);
  CHECK(pairs[1] == std::make_pair(5, 30));
  CHECK(pairs[2] == std::make_pair(7, 9));
  const auto fails = [&](const std::string& text, const std::string& what) {
    write(dir.file("bad.txt"), text);
    CHECK_THROWS_WITH(read_pairs_file(dir.file("bad.txt")),
                      Catch::Contains("bad.txt:") && Catch::Contains(what));
  };
  fails("0 20.5\n", "bad.txt:1: expected two frame numbers 'source target', but '20.5' is not");
  fails("0 20\n0 1e3\n", "bad.txt:2: expected two frame numbers 'source target', but '1e3'");
  fails("-1 3\n", "'-1' is not a frame number");
  fails("0 4294967316\n", "'4294967316' is not a frame number");
  fails("0 1 2\n", "expected two frame numbers");
}
