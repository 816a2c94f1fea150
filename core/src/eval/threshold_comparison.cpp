#include "pagor/eval/threshold_comparison.hpp"

#include <algorithm>

#include "pagor/eval/sweep.hpp"

#include <cstdio>

#include "pagor/errors.hpp"
#include "pagor/eval/dataset.hpp"
#include "pagor/pipeline.hpp"

namespace pagor {
namespace {

std::string epsilon_text(double e) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.2f", e);
  return buf;
}

}  // namespace

std::vector<Variant> threshold_variants(const Config& base) {
  std::vector<Variant> out;
  const auto& th = base.graph.thresholds;
  out.push_back({"pyramid (" + std::to_string(th.size()) + " levels)", base});
  for (double e : th) {
    Variant v{"single " + epsilon_text(e), base};
    v.config.graph.thresholds = {e};
    out.push_back(v);
  }
  for (double e : th) {
    Variant v{"max clique " + epsilon_text(e), base};
    v.config.graph.thresholds = {e};
    v.config.clique.solver = CliqueSolver::exact;
    out.push_back(v);
  }
  return out;
}

std::vector<VariantResult> compare_variants(
    const PairSet& set, const std::vector<Variant>& variants, int threads,
    const std::function<void(std::size_t, std::size_t)>& progress) {
  std::vector<VariantResult> out;
  if (variants.empty()) return out;
  std::vector<SweepSetting> settings;
  for (const Variant& v : variants) {
    validate(v.config, v.name);
    settings.push_back({v.name, v.config, {}});
  }
  PairSet positives = set;  // known negatives have no pose to get right
  positives.pairs.erase(std::remove_if(positives.pairs.begin(), positives.pairs.end(),
                                       [](const PairEntry& e) { return e.negative; }),
                        positives.pairs.end());
  SetRunner runner(positives, threads);
  const SweepResult swept =
      run_sweep(runner, settings, [&](int pair, int setting, const PairOutcome&) {
        if (progress && setting + 1 == static_cast<int>(settings.size()))
          progress(static_cast<std::size_t>(pair) + 1, positives.pairs.size());
      });
  // The variants differ from the graph on; stages kept from the previous variant cost nothing.
  const Stage timed[] = {Stage::graph, Stage::clique, Stage::gnc, Stage::verification};
  for (const SweepSettingResult& r : swept.settings) {
    VariantResult v{r.setting.label, r.summary.with_truth, r.summary.successes, 0.0};
    for (const PairOutcome& o : r.outcomes) {
      if (!o.loaded || !o.has_ground_truth) continue;
      for (Stage t : timed)
        if (o.ran[static_cast<std::size_t>(t)])
          v.mean_ms += o.stage_ms[static_cast<std::size_t>(t)];
    }
    if (v.with_truth) v.mean_ms /= v.with_truth;
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace pagor
