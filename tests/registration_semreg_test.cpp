// The semreg-dev pairs (real KITTI scans voxelised to 0.3 m, predicted labels in the learning
// map, class-poor) through the default configuration, with no configuration at all (the label
// scheme detected per cloud) and in variants derived here: labels rewritten as raw SemanticKITTI
// ids with instance bits, one pair in another numbering than the rest, and labels dropped. The
// known negatives of the shipped manifest are in every run.

#include <catch2/catch.hpp>
#include <functional>

#include "pagor/eval/benchmark.hpp"
#include "pagor/eval/pair_set.hpp"
#include "support/label_variants.hpp"

using namespace pagor;

namespace {

PairSet semreg_dev() {
  return read_pair_manifest(std::string(PAGOR_SOURCE_DIR) + "/bench/manifests/semreg-dev.txt");
}

// Which cloud of a pair a variant is asked for.
enum class Side { source, target };

// Every pair of the set, its clouds passed through `variant(pair index, side, cloud)` after loading
// (as run_pair does otherwise). Checks on each pair what holds for any trusted verdict: a negative
// is rejected, and what is accepted is right.
std::vector<PairOutcome> run_variant(
    const PairSet& set, const Config& config,
    const std::function<PointCloud(std::size_t, Side, PointCloud)>& variant) {
  Pipeline pipeline(config);
  std::vector<PairOutcome> outcomes;
  for (std::size_t i = 0; i < set.pairs.size(); ++i) {
    const PairEntry& entry = set.pairs[i];
    LoadedPair pair = load_pair(entry.source);
    PointCloud source = variant(i, Side::source, std::move(pair.source.cloud));
    PointCloud target = variant(i, Side::target, std::move(pair.target.cloud));
    pipeline.set_input(std::move(source), std::move(target));
    pipeline.set_ground_truth(pair.T_target_source_gt);
    pipeline.run();
    outcomes.push_back(pair_outcome(pipeline, entry, pair.source_name, pair.target_name));
    const PairOutcome& o = outcomes.back();
    INFO("pair " << o.name << (o.negative ? " (negative)" : "") << ": "
                 << (o.error ? std::to_string(o.error->translation) + " m, " +
                                   std::to_string(o.error->rotation_deg) + " deg"
                             : std::string("no pose")));
    if (o.negative) CHECK_FALSE(o.accepted);
    if (o.accepted) CHECK(o.success);  // what is trusted is right
  }
  return outcomes;
}

// The ten pairs and, besides the manifest's five negatives, every source against every target
// five or more pairs later (~100-200 m away, nothing shared): 15 negatives.
PairSet with_all_negatives(PairSet set) {
  std::vector<PairEntry> positives;
  for (const PairEntry& e : set.pairs)
    if (!e.negative) positives.push_back(e);
  set.pairs = positives;
  for (std::size_t i = 0; i < positives.size(); ++i)
    for (std::size_t j = i + 5; j < positives.size(); ++j) {
      PairEntry n;
      n.name = positives[i].name + "-vs-" + positives[j].name;
      n.negative = true;
      n.source.kind = PairSource::Kind::files;
      n.source.source = positives[i].source.source;
      n.source.target = positives[j].source.target;
      set.pairs.push_back(n);
    }
  return set;
}

PointCloud as_is(std::size_t, Side, PointCloud c) {
  return c;
}

}  // namespace

TEST_CASE("semreg-dev with no configuration: every pair succeeds and is accepted, no negative") {
  const PairSet set = semreg_dev();
  Pipeline pipeline(default_config());  // label scheme auto: detected per cloud
  std::vector<PairOutcome> outcomes;
  for (const PairEntry& entry : set.pairs) {
    outcomes.push_back(run_pair(pipeline, entry));
    const PairOutcome& o = outcomes.back();
    INFO("pair " << o.name);
    REQUIRE(o.loaded);
    CHECK(pipeline.source_landmarks().labels.scheme.name == "semantickitti-learning");
    CHECK(pipeline.target_landmarks().labels.scheme.name == "semantickitti-learning");
    if (o.negative) CHECK_FALSE(o.accepted);
    if (o.accepted) CHECK(o.success);
    // Refinement brings every true pair close: measured at most 0.30 m and 0.98 deg.
    if (!o.negative && o.error) {
      CHECK(o.error->translation < 0.5);
      CHECK(o.error->rotation_deg < 2.0);
    }
  }
  const BenchmarkSummary s = summarize(outcomes);
  CHECK(s.with_truth == 10);
  CHECK(s.negatives == 5);
  CHECK(s.successes == 10);
  CHECK(s.false_accepts == 0);
  CHECK(s.true_accepts == s.with_truth);
}

TEST_CASE("semreg-dev with the scheme set by hand gives what auto gives") {
  const PairSet set = semreg_dev();
  Config learning = default_config();
  learning.label_scheme = builtin_label_scheme("semantickitti-learning");
  const auto by_hand = run_variant(set, learning, as_is);
  const auto detected = run_variant(set, default_config(), as_is);
  for (std::size_t i = 0; i < set.pairs.size(); ++i) {
    INFO("pair " << set.pairs[i].name);
    CHECK(by_hand[i].success == detected[i].success);
    CHECK(by_hand[i].accepted == detected[i].accepted);
    CHECK(by_hand[i].selected_level == detected[i].selected_level);
  }
}

TEST_CASE("semreg-dev in raw SemanticKITTI ids, and with one pair in another numbering") {
  const PairSet set = semreg_dev();
  const BenchmarkSummary raw =
      summarize(run_variant(set, default_config(), [](std::size_t, Side, PointCloud c) {
        return test::learning_to_raw(std::move(c));
      }));
  CHECK(raw.successes == 10);
  CHECK(raw.true_accepts == 10);
  CHECK(raw.false_accepts == 0);
  // Pair 05 (index 2) in the training numbering, the rest in the learning map; and pair 06's
  // source alone in raw ids: each cloud is read in its own numbering.
  const BenchmarkSummary mixed =
      summarize(run_variant(set, default_config(), [](std::size_t i, Side side, PointCloud c) {
        if (i == 2) return test::learning_to_train(std::move(c));
        if (i == 3 && side == Side::source) return test::learning_to_raw(std::move(c));
        return c;
      }));
  CHECK(mixed.successes == 10);
  CHECK(mixed.true_accepts == 10);
  CHECK(mixed.false_accepts == 0);
}

TEST_CASE("a label scheme set by hand that does not fit is the diagnosis, naming the numbering") {
  const PairSet set = semreg_dev();
  Config raw = default_config();
  raw.label_scheme = builtin_label_scheme("semantickitti");
  Pipeline pipeline(raw);
  int named = 0;
  for (const PairEntry& entry : set.pairs) {
    if (entry.negative) continue;
    const PairOutcome o = run_pair(pipeline, entry);
    INFO("pair " << o.name << ": " << o.diagnosis);
    CHECK(pipeline.source_landmarks().labels.mismatch != "");
    // A pose the fallback found by luck is a success; every failure names the labels.
    CHECK((o.success || o.diagnosis == "label-scheme"));
    if (o.diagnosis == "label-scheme") {
      ++named;
      CHECK_THAT(o.report_json, Catch::Contains("\"labels_look_like\":\"semantickitti-learning\""));
    }
  }
  CHECK(named > 0);
}

TEST_CASE("semreg-dev without labels: 9 of 10, nothing wrong accepted, 15 negatives rejected") {
  const PairSet set = with_all_negatives(semreg_dev());
  const std::vector<PairOutcome> outcomes = run_variant(
      set, default_config(),
      [](std::size_t, Side, PointCloud c) { return test::without_labels(std::move(c)); });
  const BenchmarkSummary s = summarize(outcomes);
  CHECK(s.with_truth == 10);
  CHECK(s.negatives == 15);
  // Measured 9 of 10 (08 fails: its source has 5.7k points), all nine accepted. Before this round
  // 3 of 10.
  CHECK(s.successes >= 9);
  CHECK(s.true_accepts >= 9);
  CHECK(s.false_accepts == 0);
  // `label_scheme: none` reads labelled clouds the same way.
  Config none = default_config();
  none.label_scheme = builtin_label_scheme("none");
  Pipeline pipeline(none);
  const PairOutcome o = run_pair(pipeline, set.pairs[0]);
  CHECK(o.success == outcomes[0].success);
  CHECK(o.T_target_source->isApprox(*outcomes[0].T_target_source));
}
