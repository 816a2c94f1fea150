// The semreg-dev pairs (real KITTI scans voxelised to 0.3 m, predicted labels in the learning
// map, class-poor) through the default configuration with only the label scheme set, and the
// known negatives of the shipped manifest.

#include <catch2/catch.hpp>

#include "pagor/sets/benchmark.hpp"
#include "pagor/sets/pair_set.hpp"

using namespace pagor;

TEST_CASE("semreg-dev: at least 9 of 10 pairs succeed, every true pair is accepted, no negative") {
  const PairSet set =
      read_pair_manifest(std::string(PAGOR_SOURCE_DIR) + "/bench/manifests/semreg-dev.txt");
  Config config = default_config();
  config.label_scheme = builtin_label_scheme("semantickitti-learning");
  Pipeline pipeline(config);
  std::vector<PairOutcome> outcomes;
  for (const PairEntry& entry : set.pairs) {
    outcomes.push_back(run_pair(pipeline, entry));
    const PairOutcome& o = outcomes.back();
    INFO("pair " << o.name << (o.negative ? " (negative)" : "") << ": "
                 << (o.error ? std::to_string(o.error->translation) + " m, " +
                                   std::to_string(o.error->rotation_deg) + " deg"
                             : std::string("no pose")));
    REQUIRE(o.loaded);
    if (o.negative) CHECK_FALSE(o.accepted);
    if (o.accepted) CHECK(o.success);  // what is trusted is right
    // Refinement brings every true pair close: measured at most 0.30 m and 0.98 deg.
    if (!o.negative && o.error) {
      CHECK(o.error->translation < 0.5);
      CHECK(o.error->rotation_deg < 2.0);
    }
  }
  const BenchmarkSummary s = summarize(outcomes);
  CHECK(s.with_truth == 10);
  CHECK(s.negatives == 5);
  CHECK(s.successes >= 9);
  CHECK(s.upper_bound >= 9);
  CHECK(s.false_accepts == 0);
  // Every true pair is accepted once refined (measured 10 of 10; before refinement 07 was off by
  // 0.9 m and 2.7 deg and aligned only 12 % of its structure).
  CHECK(s.true_accepts == s.with_truth);
}
