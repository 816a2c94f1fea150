#include "pagor/benchmark.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "pagor/errors.hpp"
#include "pagor/report.hpp"

namespace pagor {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

}  // namespace

PairOutcome run_pair(Pipeline& pipeline, const PairEntry& entry) {
  PairOutcome o;
  o.name = entry.name;
  o.negative = entry.negative;
  LoadedPair pair;
  try {
    pair = load_pair(entry.source, pipeline.config().indoor);
  } catch (const InputError& e) {
    o.load_error = e.what();
    return o;
  }
  o.loaded = true;
  o.has_ground_truth = pair.T_target_source_gt.has_value();
  pipeline.set_input(std::move(pair.source.cloud), std::move(pair.target.cloud));
  pipeline.set_ground_truth(pair.T_target_source_gt);
  pipeline.run();
  o.selected_level = pipeline.selected_level();
  o.error = pipeline.selected_error();
  o.success = o.error && o.error->success;
  o.upper_bound = pipeline.upper_bound_success();
  o.accepted = pipeline.acceptance().accepted;
  for (int i = 0; i < kStageCount; ++i) {
    o.stage_ms[static_cast<std::size_t>(i)] = pipeline.time_ms(static_cast<Stage>(i));
    o.total_ms += o.stage_ms[static_cast<std::size_t>(i)];
  }
  auto j = nlohmann::json::parse(
      registration_report_json(pipeline, pair.source_name, pair.target_name, -1));
  j.erase("config");
  j["pair"] = entry.name;
  if (entry.negative) j["negative"] = true;
  o.report_json = j.dump();
  return o;
}

BenchmarkSummary summarize(const std::vector<PairOutcome>& outcomes) {
  BenchmarkSummary s;
  std::array<std::vector<double>, kStageCount> times;
  std::vector<double> totals;
  for (const PairOutcome& o : outcomes) {
    if (!o.loaded) {
      ++s.skipped;
      continue;
    }
    ++s.pairs_run;
    if (o.negative) ++s.negatives;
    if (!o.negative && o.has_ground_truth) {
      ++s.with_truth;
      s.successes += o.success;
      s.upper_bound += o.upper_bound;
    }
    if (o.accepted && (o.negative || o.has_ground_truth)) {  // a verdict that can be judged
      ++s.accepted;
      if (!o.negative && o.success)
        ++s.true_accepts;
      else if (o.negative || o.has_ground_truth)
        ++s.false_accepts;
    }
    if (!o.timed) continue;
    for (int i = 0; i < kStageCount; ++i)
      times[static_cast<std::size_t>(i)].push_back(o.stage_ms[static_cast<std::size_t>(i)]);
    totals.push_back(o.total_ms);
  }
  for (int i = 0; i < kStageCount; ++i) {
    s.mean_ms[static_cast<std::size_t>(i)] = mean(times[static_cast<std::size_t>(i)]);
    s.median_ms[static_cast<std::size_t>(i)] = median(times[static_cast<std::size_t>(i)]);
  }
  s.mean_total_ms = mean(totals);
  s.median_total_ms = median(totals);
  return s;
}

}  // namespace pagor
