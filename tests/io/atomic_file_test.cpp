// Nothing lost: a write cut short by a file-size limit leaves the previous file intact, and an
// append adds a whole line or nothing. The limit is set in a forked child (setrlimit
// RLIMIT_FSIZE), which reports back through its exit code.

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "pagor/io/atomic_file.hpp"
#include "pagor/errors.hpp"
#include "support/test_util.hpp"

using namespace pagor;

namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Runs `body` in a child limited to `limit` bytes per file; the child's exit code: 0 when `body`
// threw InputError whose message contains `expected`, 1 when it threw another message, 2 when it
// did not throw.
int in_limited_child(rlim_t limit, const std::string& expected, const std::function<void()>& body) {
  const pid_t pid = fork();
  if (pid == 0) {
    signal(SIGXFSZ, SIG_IGN);
    const rlimit rl{limit, limit};
    setrlimit(RLIMIT_FSIZE, &rl);
    int code = 2;
    try {
      body();
    } catch (const InputError& e) {
      code = std::string(e.what()).find(expected) != std::string::npos ? 0 : 1;
    }
    _exit(code);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 100 + WTERMSIG(status);
}

std::size_t files_in(const std::string& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST_CASE("an atomic write replaces the file, with its permissions") {
  test::TempDir dir;
  const std::string path = dir.file("out.json");
  write_file_atomic(path, "first\n");
  CHECK(read_file(path) == "first\n");
  std::filesystem::permissions(path, std::filesystem::perms::owner_read |
                                         std::filesystem::perms::owner_write |
                                         std::filesystem::perms::group_read);
  write_file_atomic(path, "second\n");
  CHECK(read_file(path) == "second\n");
  CHECK((std::filesystem::status(path).permissions() & std::filesystem::perms::others_read) ==
        std::filesystem::perms::none);
  CHECK(files_in(dir.file("")) == 1);
}

TEST_CASE("a write cut short by a size limit leaves the old file and no temporary behind") {
  test::TempDir dir;
  const std::string path = dir.file("result.json");
  write_file_atomic(path, "{\"good\": true}\n");
  const std::string big(100000, 'x');
  CHECK(in_limited_child(8192, "the previous file, if any, is unchanged",
                         [&] { write_file_atomic(path, big); }) == 0);
  CHECK(read_file(path) == "{\"good\": true}\n");
  CHECK(files_in(dir.file("")) == 1);
}

TEST_CASE("a write into a missing directory names the file") {
  test::TempDir dir;
  CHECK_THROWS_WITH(write_file_atomic(dir.file("no/such/out.json"), "x"),
                    Catch::Contains("out.json") && Catch::Contains("nothing was written"));
}

TEST_CASE("appended lines are whole: a line that does not fit is taken back") {
  test::TempDir dir;
  const std::string path = dir.file("results.jsonl");
  {
    LineAppender out(path);
    out.append("{\"pair\": [0, 20]}");
    out.append("{\"pair\": [0, 30]}");
  }
  const std::string before = read_file(path);
  CHECK(before == "{\"pair\": [0, 20]}\n{\"pair\": [0, 30]}\n");
  CHECK(in_limited_child(before.size() + 100, "the lines written before are intact", [&] {
          LineAppender out(path);
          out.append(std::string(5000, 'y'));
        }) == 0);
  CHECK(read_file(path) == before);
}

TEST_CASE("an incomplete last line left by a killed writer is cut off on reopening") {
  test::TempDir dir;
  const std::string path = dir.file("results.jsonl");
  std::ofstream(path) << "{\"a\": 1}\n{\"b\": 2}\n{\"c\": ";
  LineAppender out(path);
  out.append("{\"c\": 3}");
  CHECK(read_file(path) == "{\"a\": 1}\n{\"b\": 2}\n{\"c\": 3}\n");
  std::ofstream(dir.file("partial.jsonl")) << "no newline at all";
  LineAppender(dir.file("partial.jsonl")).append("x");
  CHECK(read_file(dir.file("partial.jsonl")) == "x\n");
}

TEST_CASE("fingerprints are stable") {
  CHECK(fingerprint("") == "cbf29ce484222325");
  CHECK(fingerprint("a") == "af63dc4c8601ec8c");
  CHECK(fingerprint("config 1") != fingerprint("config 2"));
}
