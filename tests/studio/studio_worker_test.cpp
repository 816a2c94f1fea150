// The studio's worker thread: requests replace each other while a run is in progress, readers on
// the UI thread see whole snapshots only, and the last request is the one answered. Built also
// with ThreadSanitizer (PAGOR_SANITIZE_THREAD, see the README), where it checks the locking.

#include <catch2/catch.hpp>

#include "pagor/config.hpp"
#include "runners/worker.hpp"

using namespace pagor;
using studio::Worker;

namespace {

constexpr double kTimeout = 600.0;  // [s]: generous for sanitizer builds; a hang fails the test

PairSource synthetic(std::uint64_t seed) {
  PairSource d;
  d.kind = PairSource::Kind::synthetic;
  d.synthetic_seed = seed;
  return d;
}

// Two cloud files as a pair.
PairSource files(const std::string& source, const std::string& target) {
  PairSource d;
  d.kind = PairSource::Kind::files;
  d.source = source;
  d.target = target;
  return d;
}

}  // namespace

TEST_CASE("requests submitted during a run: the last one is answered, readers see whole results") {
  Worker worker;
  Config config = default_config();
  std::uint64_t last = worker.submit(synthetic(7), config);
  // Change mu and a threshold while the worker runs, reading its state the way the UI does.
  int seen = 0;
  for (int i = 1; i <= 12; ++i) {
    config.verification.mu = 0.5 + 0.1 * i;
    config.graph.thresholds[0] = 0.01 + 0.001 * i;
    last = worker.submit(std::nullopt, config);
    const studio::WorkerStatus status = worker.status();
    CHECK(status.submitted == last);
    CHECK(status.finished <= status.submitted);
    if (const auto snap = worker.snapshot()) {
      ++seen;
      CHECK(snap->levels.size() == snap->config.graph.thresholds.size());
      CHECK(snap->request <= last);
    }
  }
  REQUIRE(worker.wait_idle(kTimeout));
  const auto snap = worker.snapshot();
  REQUIRE(snap);
  CHECK(snap->request == last);
  CHECK(section_json(snap->config, "verification") == section_json(config, "verification"));
  CHECK(section_json(snap->config, "graph") == section_json(config, "graph"));
  CHECK(snap->selected >= 0);
  CHECK(snap->selected_error);
  CHECK(worker.status().error.empty());
  INFO("snapshots seen while submitting: " << seen);
}

TEST_CASE("an invalid configuration is reported and the last good result kept") {
  Worker worker;
  Config config = default_config();
  worker.submit(synthetic(7), config);
  REQUIRE(worker.wait_idle(kTimeout));
  const auto good = worker.snapshot();
  REQUIRE(good);
  config.verification.mu = -1.0;
  worker.submit(std::nullopt, config);
  REQUIRE(worker.wait_idle(kTimeout));
  CHECK_THAT(worker.status().error, Catch::Contains("verification.mu"));
  CHECK(worker.snapshot() == good);
}

#ifdef PAGOR_HAVE_KITTI
TEST_CASE("an unlabelled pair runs on class-agnostic landmarks instead of being refused") {
  Worker worker;
  const std::string scans = std::string(PAGOR_KITTI_DIR) + "/sequences/00/velodyne/";
  const PairSource d = files(scans + "000020.bin", scans + "000030.bin");
  worker.submit(d, default_config());
  REQUIRE(worker.wait_idle(kTimeout));
  CHECK(worker.status().error.empty());
  const auto snap = worker.snapshot();
  REQUIRE(snap);
  REQUIRE_FALSE(snap->source_landmarks.classes.empty());
  CHECK(snap->source_landmarks.classes.back().name == "structure");
  CHECK(snap->selected >= 0);
}
#endif

#if defined(PAGOR_GEDI_DIR) && defined(PAGOR_HAVE_SEMREG_DATA)
TEST_CASE("a matcher's correspondences replace the landmark ones, or join them when fused") {
  Worker worker;
  const std::string pair = std::string(PAGOR_SEMREG_DIR) + "/08/";
  PairSource d = files(pair + "source.pcd", pair + "target.pcd");
  d.ground_truth = pair + "T_target_source.txt";
  d.correspondences = std::string(PAGOR_GEDI_DIR) + "/08.txt";
  Config config = default_config();
  worker.submit(d, config);
  REQUIRE(worker.wait_idle(kTimeout));
  REQUIRE(worker.status().error.empty());
  auto snap = worker.snapshot();
  REQUIRE(snap);
  const OriginCounts alone = count_by_origin(snap->correspondences);
  CHECK(alone.landmark == 0);
  CHECK(alone.matcher == 730);

  config.correspondences.fuse_matches = true;
  worker.submit(std::nullopt, config);
  REQUIRE(worker.wait_idle(kTimeout));
  REQUIRE(worker.status().error.empty());
  snap = worker.snapshot();
  REQUIRE(snap);
  const OriginCounts fused = count_by_origin(snap->correspondences);
  CHECK(fused.landmark > 0);
  CHECK(fused.matcher == 730);
  REQUIRE(snap->selected >= 0);
  const OriginCounts clique = count_by_origin(
      snap->correspondences, snap->levels[static_cast<std::size_t>(snap->selected)].clique);
  CHECK(clique.landmark > 0);
  CHECK(clique.matcher > 0);
  REQUIRE(snap->selected_error);
  CHECK(snap->selected_error->success);
}
#endif
