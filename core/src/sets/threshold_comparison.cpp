#include "pagor/sets/threshold_comparison.hpp"

#include <cstdio>

#include "pagor/errors.hpp"
#include "pagor/pipeline.hpp"
#include "pagor/sets/dataset.hpp"

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
  for (const Variant& v : variants) {
    validate(v.config, v.name);
    out.push_back({v.name});
  }
  Pipeline pipeline(variants.front().config, threads);
  const Stage timed[] = {Stage::graph, Stage::clique, Stage::gnc, Stage::verification};
  for (std::size_t k = 0; k < set.pairs.size(); ++k) {
    const PairEntry& entry = set.pairs[k];
    LoadedPair pair;
    bool usable = !entry.negative;
    if (usable) {
      try {
        pair = load_pair(entry.source, variants.front().config.indoor);
      } catch (const InputError&) {
        usable = false;  // a pair that does not load counts for no variant
      }
    }
    if (usable && pair.T_target_source_gt) {
      pipeline.set_input(std::move(pair.source.cloud), std::move(pair.target.cloud));
      pipeline.set_ground_truth(pair.T_target_source_gt);
      for (std::size_t i = 0; i < variants.size(); ++i) {
        pipeline.set_config(variants[i].config);  // landmarks and correspondences stay cached
        int before[4];
        for (int t = 0; t < 4; ++t) before[t] = pipeline.runs(timed[t]);
        pipeline.run();
        const auto err = pipeline.selected_error();
        VariantResult& r = out[i];
        ++r.with_truth;
        r.successes += err && err->success;
        double ms = 0;
        for (int t = 0; t < 4; ++t)  // stages cached from the previous variant cost nothing
          if (pipeline.runs(timed[t]) > before[t]) ms += pipeline.time_ms(timed[t]);
        r.mean_ms += ms;
      }
    }
    if (progress) progress(k + 1, set.pairs.size());
  }
  for (VariantResult& r : out)
    if (r.with_truth) r.mean_ms /= r.with_truth;
  return out;
}

}  // namespace pagor
