// The studio against hostile files and situations (issue 25): results files that are deep, full
// of nulls, endless or blocking, sessions that never end, and a worker that runs out of memory.
// Each ends in a message and a studio that keeps running, never in a signal, an abort or a hang.

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <fstream>

#include "pagor/errors.hpp"
#include "runners/worker.hpp"
#include "studio_test_util.hpp"
#include "ui_driver.hpp"

using namespace pagor;
using namespace pagor::test;

namespace {

// Opens `path` as benchmark results in a running studio; the message it shows.
std::string open_results(UiDriver& d, const std::string& path) {
  d.state().bench.source = studio::BenchSource::results;
  d.state().bench.path = path;
  d.state().message = studio::Message{};
  d.studio().open_benchmark_now();
  d.frames(2);  // still drawing
  return d.state().message.text;
}

}  // namespace

TEST_CASE("hostile results files: a message, and the studio keeps running") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp));
  d.settle();
  // 100 000 levels deep: SIGSEGV in the reader once.
  std::ofstream(tmp.file("deep.jsonl")) << std::string(100000, '[') << std::string(100000, ']');
  CHECK_THAT(open_results(d, tmp.file("deep.jsonl")),
             Catch::Contains("deep.jsonl:1") && Catch::Contains("not JSON"));
  // null wherever a text, a number or an object is expected: read as absent.
  std::ofstream(tmp.file("nulls.jsonl"))
      << R"({"schema": "pagor.register/1", "pair": null, "acceptance": {"accepted": null, )"
      << R"("reason": null}, "ground_truth": null, "levels": [null, {"epsilon": null}], )"
      << R"("diagnosis": {"verdict": null}, "timings_ms": null, "trim": null, "source": null, )"
      << R"("target": null, "T_target_source": null, "selected_level": null})"
      << "\n";
  const std::string loaded = open_results(d, tmp.file("nulls.jsonl"));
  CHECK(d.state().message.level != studio::MessageLevel::error);
  REQUIRE(d.studio().bench().rows().size() == 1);
  CHECK(d.studio().bench().rows()[0].outcome.name == "null");
  CHECK_FALSE(d.studio().bench().rows()[0].outcome.accepted);
  INFO(loaded);
  // Files that never end or block.
  CHECK_THAT(open_results(d, "/dev/zero"),
             Catch::Contains("/dev/zero: results file is a character device"));
  REQUIRE(::mkfifo(tmp.file("pipe.jsonl").c_str(), 0600) == 0);
  CHECK_THAT(open_results(d, tmp.file("pipe.jsonl")),
             Catch::Contains("pipe.jsonl: results file is a FIFO"));
  d.frames(2);
  CHECK(d.studio().worker().snapshot());  // the pair view's result is still there
}

TEST_CASE("a session that never ends or blocks is refused, naming it") {
  TempDir tmp;
  studio::AppState s;
  CHECK_THROWS_WITH(studio::load_session("/dev/zero", s),
                    Catch::Contains("/dev/zero: session file is a character device"));
  REQUIRE(::mkfifo(tmp.file("pipe.json").c_str(), 0600) == 0);
  CHECK_THROWS_WITH(studio::load_session(tmp.file("pipe.json"), s),
                    Catch::Contains("pipe.json: session file is a FIFO"));
}

TEST_CASE("out of memory in the worker: an error in the status, and the next run works") {
  if (kSanitized) {  // AddressSanitizer reserves terabytes of address space: no limit possible
    WARN("not under sanitizers");
    return;
  }
  TempDir tmp;
  // A 64 MB scan (4 M points) to load with 48 MB of address space to spare.
  {
    std::ofstream big(tmp.file("big.bin"), std::ios::binary);
    const std::vector<float> row(4 * 4096, 1.0f);
    for (int i = 0; i < 1024; ++i)
      big.write(reinterpret_cast<const char*>(row.data()),
                static_cast<std::streamsize>(row.size() * sizeof(float)));
  }
  const pid_t pid = ::fork();
  if (pid == 0) {  // a child: the limit and the worker threads stay there
    int code = 0;
    studio::Worker worker;
    PairSource big;
    big.kind = PairSource::Kind::files;
    big.source = big.target = tmp.file("big.bin");
    long pages = 0, page = ::sysconf(_SC_PAGESIZE);
    std::ifstream("/proc/self/statm") >> pages;
    rlimit old{};
    ::getrlimit(RLIMIT_AS, &old);
    const rlimit low{static_cast<rlim_t>(pages * page + (48l << 20)), old.rlim_max};
    ::setrlimit(RLIMIT_AS, &low);
    worker.submit(big, default_config());
    if (!worker.wait_idle(600)) code = 10;
    const std::string error = worker.status().error;
    ::setrlimit(RLIMIT_AS, &old);
    if (error.find("out of memory") == std::string::npos) code = code ? code : 11;
    PairSource small;
    small.kind = PairSource::Kind::synthetic;
    worker.submit(small, default_config());
    if (!worker.wait_idle(600) || !worker.status().error.empty() || !worker.snapshot())
      code = code ? code : 12;
    ::_exit(code);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));       // not killed by an uncaught std::bad_alloc (std::terminate)
  CHECK(WEXITSTATUS(status) == 0);  // 10: hung; 11: no "out of memory"; 12: no recovery
}
