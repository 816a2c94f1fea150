#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "pagor/errors.hpp"
#include "pagor/eval/pair_set.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

void write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

const char* kRigid =
    "0.998488299 -0.053735237 -0.011558872 -20.821863941\n"
    "0.053709623 0.998553457 -0.002513002 -0.767760066\n"
    "0.011677190 0.001888380 0.999929970 -0.392830636\n"
    "0 0 0 1\n";

}  // namespace

TEST_CASE("a 4x4 ground-truth file is read and checked to be rigid") {
  test::TempDir dir;
  write(dir.file("gt.txt"), kRigid);
  const Transform T = read_transform_file(dir.file("gt.txt"));
  CHECK(T(0, 3) == Approx(-20.821863941));
  CHECK(T(2, 2) == Approx(0.999929970));

  write(dir.file("gt34.txt"), "# 3x4 is enough\n1 0 0 1\n0 1 0 2\n0 0 1 3\n");
  CHECK(read_transform_file(dir.file("gt34.txt"))(1, 3) == 2.0);

  write(dir.file("scaled.txt"), "2 0 0 0\n0 2 0 0\n0 0 2 0\n0 0 0 1\n");
  CHECK_THROWS_WITH(read_transform_file(dir.file("scaled.txt")),
                    Catch::Contains("scaled.txt:4") && Catch::Contains("not orthonormal"));
  write(dir.file("mirror.txt"), "-1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  CHECK_THROWS_WITH(read_transform_file(dir.file("mirror.txt")), Catch::Contains("determinant"));
  write(dir.file("row.txt"), "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 1 1\n");
  CHECK_THROWS_WITH(read_transform_file(dir.file("row.txt")), Catch::Contains("last row"));
  write(dir.file("short.txt"), "1 0 0\n0 1 0\n");
  CHECK_THROWS_WITH(read_transform_file(dir.file("short.txt")),
                    Catch::Contains("short.txt: 6 numbers"));
  write(dir.file("word.txt"), "1 0 0 0\n0 one 0 0\n");
  CHECK_THROWS_WITH(read_transform_file(dir.file("word.txt")),
                    Catch::Contains("word.txt:2") && Catch::Contains("'one'"));
  write(dir.file("nan.txt"), "1 0 0 nan\n0 1 0 0\n0 0 1 0\n");
  CHECK_THROWS_WITH(read_transform_file(dir.file("nan.txt")), Catch::Contains("nan.txt:1"));
  CHECK_THROWS_WITH(read_transform_file(dir.file("none.txt")),
                    Catch::Contains("none.txt: transform file does not exist"));
}

TEST_CASE("a pairs manifest resolves paths against its directory and reads every key") {
  test::TempDir dir;
  write(dir.file("a.pcd"), "x");
  write(dir.file("b.pcd"), "x");
  write(dir.file("a.label"), "x");
  write(dir.file("gt.txt"), kRigid);
  write(dir.file("m.txt"),
        "# comment\n\n"
        "a.pcd b.pcd gt=gt.txt name=first source_labels=a.label\n"
        "a.pcd b.pcd overlap=no   # trailing comment\n"
        "a.pcd b.pcd scheme=semantickitti\n"
        "a.pcd b.pcd scheme=none\n");
  const PairSet set = read_pair_manifest(dir.file("m.txt"));
  REQUIRE(set.pairs.size() == 4);
  CHECK(set.pairs[0].source.label_scheme.empty());  // the configuration's
  CHECK_FALSE(pair_label_scheme(set.pairs[0].source));
  CHECK(pair_label_scheme(set.pairs[2].source)->ids_of("car") == std::vector<std::uint32_t>{10});
  CHECK(pair_label_scheme(set.pairs[3].source)->ignores_labels());
  CHECK(set.pairs[0].name == "first");
  CHECK(set.pairs[0].source.kind == PairSource::Kind::files);
  CHECK(set.pairs[0].source.source == dir.file("a.pcd"));
  CHECK(set.pairs[0].source.source_labels == dir.file("a.label"));
  CHECK(set.pairs[0].source.ground_truth == dir.file("gt.txt"));
  CHECK_FALSE(set.pairs[0].negative);
  CHECK(set.pairs[1].name == "4");  // the line number
  CHECK(set.pairs[1].negative);
  CHECK(set.pairs[1].source.ground_truth.empty());
}

TEST_CASE("manifest errors name the manifest and the line") {
  test::TempDir dir;
  write(dir.file("a.pcd"), "x");
  const auto fails_with = [&](const std::string& text, const std::string& what) {
    write(dir.file("m.txt"), text);
    CHECK_THROWS_WITH(read_pair_manifest(dir.file("m.txt")), Catch::Contains(what));
  };
  fails_with("a.pcd\n", "m.txt:1: expected 'SOURCE TARGET");
  fails_with("\na.pcd missing.pcd\n", "m.txt:2: " + dir.file("missing.pcd") + " does not exist");
  fails_with("a.pcd a.pcd colour=red\n", "m.txt:1: unknown key 'colour'");
  fails_with("a.pcd a.pcd gt\n", "'gt' is not a key=value option");
  fails_with("a.pcd a.pcd scheme=nuscenes\n",
             "m.txt:1: scheme: unknown label scheme 'nuscenes' (built-in: auto, none,");
  fails_with("a.pcd a.pcd overlap=maybe\n", "overlap must be 'yes' or 'no'");
  fails_with("a.pcd a.pcd overlap=no gt=a.pcd\n", "cannot have a ground truth");
  fails_with("# nothing\n", "m.txt: no pairs");
}

TEST_CASE("the shipped semreg-dev manifest names every pair and its negatives") {
  const std::string manifest = std::string(PAGOR_SOURCE_DIR) + "/bench/manifests/semreg-dev.txt";
  if (!std::ifstream(std::string(PAGOR_SEMREG_DIR) + "/03/source.pcd")) {
    WARN("no semreg-dev data beside the repository; the manifest is not checked");
    return;
  }
  const PairSet set = read_pair_manifest(manifest);
  int positives = 0, negatives = 0;
  for (const auto& p : set.pairs) {
    positives += !p.negative && !p.source.ground_truth.empty();
    negatives += p.negative;
  }
  CHECK(positives == 10);
  CHECK(negatives == 5);
}

TEST_CASE("manifest paths with blanks are quoted") {
  test::TempDir dir;
  std::filesystem::create_directories(dir.file("my scans"));
  write(dir.file("my scans/a b.pcd"), "x");
  write(dir.file("b.pcd"), "x");
  write(dir.file("gt \"1\".txt"), kRigid);
  write(dir.file("m.txt"),
        "\"my scans/a b.pcd\" b.pcd gt=\"gt \\\"1\\\".txt\" name=\"pair one\"\n");
  const PairSet set = read_pair_manifest(dir.file("m.txt"));
  REQUIRE(set.pairs.size() == 1);
  CHECK(set.pairs[0].source.source == dir.file("my scans/a b.pcd"));
  CHECK(set.pairs[0].source.ground_truth == dir.file("gt \"1\".txt"));
  CHECK(set.pairs[0].name == "pair one");
  write(dir.file("m.txt"), "\"my scans/a b.pcd b.pcd\n");
  CHECK_THROWS_WITH(read_pair_manifest(dir.file("m.txt")),
                    Catch::Contains("m.txt:1: a quoted path is not closed"));
  write(dir.file("m.txt"), "my scans/a b.pcd b.pcd\n");  // unquoted: three words
  CHECK_THROWS_WITH(read_pair_manifest(dir.file("m.txt")),
                    Catch::Contains("m.txt:1: 'b.pcd' is not a key=value option"));
}

TEST_CASE("every pair of a manifest has its own name and its own files") {
  test::TempDir dir;
  for (const char* f : {"a.pcd", "b.pcd", "c.pcd"}) write(dir.file(f), "x");
  std::filesystem::create_symlink(dir.file("a.pcd"), dir.file("link.pcd"));
  const auto fails_with = [&](const std::string& text, const std::string& what) {
    write(dir.file("m.txt"), text);
    CHECK_THROWS_WITH(read_pair_manifest(dir.file("m.txt")), Catch::Contains(what));
  };
  // Two pairs sharing a name: the second once got the first's result line.
  fails_with("a.pcd b.pcd name=x\nc.pcd b.pcd name=x\n",
             "m.txt:2: the name 'x' is already used by line 1");
  fails_with("a.pcd b.pcd name=2\nc.pcd b.pcd\n", "m.txt:2: the name '2' is already used");
  // The same files spelled another way are the same pair.
  fails_with("a.pcd b.pcd\n./a.pcd b.pcd\n", "m.txt:2: the same pair as line 1");
  fails_with("a.pcd b.pcd\nlink.pcd ./b.pcd\n", "m.txt:2: the same pair as line 1");
  write(dir.file("m.txt"), "a.pcd b.pcd\na.pcd c.pcd\nc.pcd b.pcd\n");
  CHECK(read_pair_manifest(dir.file("m.txt")).pairs.size() == 3);
}

TEST_CASE("a pair's fingerprint follows its files' content, not their names") {
  test::TempDir dir;
  write(dir.file("a.pcd"), "source bytes");
  write(dir.file("b.pcd"), "target bytes");
  std::filesystem::create_directories(dir.file("copy"));
  std::filesystem::copy_file(dir.file("a.pcd"), dir.file("copy/a.pcd"));
  PairEntry e;
  e.name = "03";
  e.source.kind = PairSource::Kind::files;
  e.source.source = dir.file("a.pcd");
  e.source.target = dir.file("b.pcd");
  const std::string f = pair_fingerprint(e);
  PairEntry moved = e;
  moved.source.source = dir.file("copy/./a.pcd");
  CHECK(pair_fingerprint(moved) == f);
  PairEntry renamed = e;
  renamed.name = "04";
  CHECK(pair_fingerprint(renamed) != f);
  PairEntry negative = e;
  negative.negative = true;
  CHECK(pair_fingerprint(negative) != f);
  write(dir.file("copy/a.pcd"), "other bytes!");
  CHECK(pair_fingerprint(moved) != f);
  PairEntry missing = e;
  missing.source.target = dir.file("none.pcd");
  CHECK_THROWS_WITH(pair_fingerprint(missing), Catch::Contains("none.pcd"));
}
