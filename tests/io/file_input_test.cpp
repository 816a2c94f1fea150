// Bounded reading of the files users name: regular files only (a FIFO or /dev/zero would block or
// never end), a size limit naming the file, content fingerprints that ignore where a file is.

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "pagor/errors.hpp"
#include "pagor/eval/file_lock.hpp"
#include "pagor/io/atomic_file.hpp"
#include "pagor/io/file_input.hpp"
#include "support/test_util.hpp"

using namespace pagor;

TEST_CASE("a regular file is read whole, within its limit") {
  test::TempDir dir;
  std::ofstream(dir.file("a.txt")) << "hello\nworld\n";
  CHECK(read_file(dir.file("a.txt"), "text file", 64) == "hello\nworld\n");
  CHECK(read_file(dir.file("a.txt"), "text file", 12) == "hello\nworld\n");
  CHECK_THROWS_WITH(read_file(dir.file("a.txt"), "text file", 11),
                    Catch::Contains("a.txt: text file is 12 bytes, more than the 11 bytes"));
  CHECK_THROWS_WITH(read_file(dir.file("none.txt"), "config file", 64),
                    Catch::Contains("none.txt: config file does not exist"));
  CHECK_THROWS_WITH(read_file(dir.file(""), "config file", 64),
                    Catch::Contains("config file is a directory"));
}

TEST_CASE("devices and FIFOs are refused at once, naming the file") {
  // /dev/zero never ends and a FIFO without a writer blocks: both must fail before reading.
  CHECK_THROWS_WITH(read_file("/dev/zero", "point cloud", kMaxCloudFileBytes),
                    Catch::Contains("/dev/zero: point cloud is a character device"));
  CHECK_THROWS_WITH(file_fingerprint("/dev/zero", "scan", kMaxCloudFileBytes),
                    Catch::Contains("/dev/zero: scan is a character device"));
  test::TempDir dir;
  REQUIRE(::mkfifo(dir.file("pipe.pcd").c_str(), 0600) == 0);
  CHECK_THROWS_WITH(read_file(dir.file("pipe.pcd"), "point cloud", kMaxCloudFileBytes),
                    Catch::Contains("pipe.pcd: point cloud is a FIFO"));
  // A symbolic link is followed to what it names.
  std::filesystem::create_symlink("/dev/zero", dir.file("zero.bin"));
  CHECK_THROWS_WITH(read_file(dir.file("zero.bin"), "scan", kMaxCloudFileBytes),
                    Catch::Contains("zero.bin: scan is a character device"));
}

TEST_CASE("a fingerprint depends on the content only") {
  test::TempDir dir;
  std::ofstream(dir.file("a.bin")) << std::string(3000000, 'x') << "tail";
  std::filesystem::create_directories(dir.file("sub"));
  std::filesystem::copy_file(dir.file("a.bin"), dir.file("sub/copy.bin"));
  std::filesystem::create_symlink(dir.file("a.bin"), dir.file("link.bin"));
  const std::string f = file_fingerprint(dir.file("a.bin"), "scan", kMaxCloudFileBytes);
  CHECK(f.rfind("3000004:", 0) == 0);
  CHECK(file_fingerprint(dir.file("sub/copy.bin"), "scan", kMaxCloudFileBytes) == f);
  CHECK(file_fingerprint(dir.file("link.bin"), "scan", kMaxCloudFileBytes) == f);
  std::ofstream(dir.file("b.bin")) << std::string(3000000, 'x') << "tajl";  // one byte differs
  CHECK(file_fingerprint(dir.file("b.bin"), "scan", kMaxCloudFileBytes) != f);
  CHECK_THROWS_WITH(file_fingerprint(dir.file("a.bin"), "scan", 100),
                    Catch::Contains("a.bin: scan is 3000004 bytes, more than the 100 bytes"));
}

TEST_CASE("sibling names stay within 255 bytes, and atomic writes work on such long names") {
  test::TempDir dir;
  const std::string name(250, 'n');  // + ".partial" or a temporary suffix would pass 255
  const std::string path = dir.file(name);
  const std::string partial = sibling_path(path, ".partial");
  CHECK(std::filesystem::path(partial).filename().string().size() <= 255);
  CHECK(partial == sibling_path(path, ".partial"));  // the same every time
  CHECK(partial != sibling_path(dir.file(std::string(249, 'n') + "m"), ".partial"));
  CHECK(partial.rfind(dir.file(std::string(200, 'n')), 0) == 0);
  CHECK(sibling_path(dir.file("short.jsonl"), ".partial") == dir.file("short.jsonl.partial"));
  write_file_atomic(path, "whole\n");
  CHECK(read_file(path, "results file", 64) == "whole\n");
  write_file_atomic(partial, "x");
  CHECK(read_file(partial, "journal", 64) == "x");
}

TEST_CASE("one writer per output: a second process is refused, naming the file and holder") {
  test::TempDir dir;
  const std::string out = dir.file("results.jsonl");
  int ready[2], release[2];
  REQUIRE(::pipe(ready) == 0);
  REQUIRE(::pipe(release) == 0);
  const pid_t pid = ::fork();
  if (pid == 0) {  // the first writer: holds the lock until told to let go
    int code = 0;
    try {
      FileLock lock(out, "pagor bench --out");
      code = ::write(ready[1], "1", 1) == 1 ? 0 : 3;
      char c;
      if (::read(release[0], &c, 1) != 1) code = 4;
    } catch (const InputError&) {
      code = 2;
    }
    ::_exit(code);
  }
  char c = 0;
  REQUIRE(::read(ready[0], &c, 1) == 1);
  CHECK_THROWS_WITH(FileLock(out, "pagor bench --out"),
                    Catch::Contains("results.jsonl: is being written by pid " +
                                    std::to_string(pid) + ": pagor bench --out"));
  REQUIRE(::write(release[1], "1", 1) == 1);
  int status = 0;
  ::waitpid(pid, &status, 0);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK_FALSE(std::filesystem::exists(out + ".lock"));  // released and removed
  {
    FileLock again(out, "pagor bench --out");  // free once the holder is gone
    CHECK(std::filesystem::exists(again.lock_path()));
  }
  CHECK_FALSE(std::filesystem::exists(out + ".lock"));
}
