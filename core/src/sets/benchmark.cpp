#include "pagor/sets/benchmark.hpp"

#include <algorithm>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "pagor/verify/diagnosis.hpp"
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
  return pair_outcome(pipeline, entry, pair.source_name, pair.target_name);
}

PairOutcome pair_outcome(const Pipeline& pipeline, const PairEntry& entry,
                         const std::string& source_name, const std::string& target_name) {
  PairOutcome o;
  o.name = entry.name;
  o.negative = entry.negative;
  o.loaded = true;
  o.has_ground_truth = pipeline.ground_truth().has_value();
  o.source_name = source_name;
  o.target_name = target_name;
  o.selected_level = pipeline.selected_level();
  o.error = pipeline.selected_error();
  o.success = o.error && o.error->success;
  o.upper_bound = pipeline.upper_bound_success();
  o.accepted = pipeline.acceptance().accepted;
  o.margin = pipeline.acceptance().margin;
  const std::vector<double>& scores = pipeline.verification().scores;
  o.score = o.selected_level >= 0 && static_cast<std::size_t>(o.selected_level) < scores.size()
                ? scores[static_cast<std::size_t>(o.selected_level)]
                : std::numeric_limits<double>::quiet_NaN();
  for (const auto& e : pipeline.level_errors()) o.level_success.push_back(e && e->success);
  o.T_target_source = pipeline.selected_transform();
  o.T_target_source_gt = pipeline.ground_truth();
  o.level_epsilons = pipeline.graph().thresholds;
  o.level_epsilons.resize(pipeline.cliques().size());
  o.trim = pipeline.config().graph.trim;
  for (int i = 0; i < kStageCount; ++i) {
    o.stage_ms[static_cast<std::size_t>(i)] = pipeline.time_ms(static_cast<Stage>(i));
    o.total_ms += o.stage_ms[static_cast<std::size_t>(i)];
  }
  auto j = nlohmann::json::parse(registration_report_json(pipeline, source_name, target_name, -1));
  j.erase("config");
  j["trim"] = to_string(pipeline.config().graph.trim);  // the unit of the levels' epsilon
  const std::optional<Diagnosis> diagnosis = diagnose(pipeline);
  if (diagnosis) o.diagnosis = verdict_name(diagnosis->verdict);
  j["diagnosis"] = diagnosis ? nlohmann::json::parse(diagnosis_json(*diagnosis)) : nlohmann::json();
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

namespace pagor {
namespace {

// A 4x4 matrix written by the report (rows of four numbers); nullopt when absent or malformed.
std::optional<Transform> transform_from_json(nlohmann::json::const_iterator it,
                                             nlohmann::json::const_iterator end) {
  if (it == end || !it->is_array() || it->size() != 4) return std::nullopt;
  Transform T;
  for (int r = 0; r < 4; ++r) {
    const auto& row = (*it)[static_cast<std::size_t>(r)];
    if (!row.is_array() || row.size() != 4) return std::nullopt;
    for (int c = 0; c < 4; ++c) {
      if (!row[static_cast<std::size_t>(c)].is_number()) return std::nullopt;
      T(r, c) = row[static_cast<std::size_t>(c)].get<double>();
    }
  }
  return T;
}

PairOutcome outcome_from_line(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object() || j.value("schema", "") != "pagor.register/1" || !j.contains("pair"))
    throw InputError(where + ": not a pagor bench result (schema pagor.register/1 with 'pair')");
  PairOutcome o;
  o.loaded = true;
  o.name = j["pair"].is_string() ? j["pair"].get<std::string>() : j["pair"].dump();
  o.negative = j.value("negative", false);
  o.source_name = j.value("source", "");
  o.target_name = j.value("target", "");
  const auto level = j.find("selected_level");
  if (level != j.end() && level->is_number_integer()) o.selected_level = level->get<int>();
  const auto gt = j.find("ground_truth");
  if (gt != j.end() && gt->is_object()) {
    o.has_ground_truth = true;
    o.success = gt->value("success", false);
    o.upper_bound = gt->value("upper_bound", false);
    if (gt->contains("translation_error_m"))
      o.error = PoseError{gt->value("translation_error_m", 0.0),
                          gt->value("rotation_error_deg", 0.0), o.success};
  }
  const auto a = j.find("acceptance");
  if (a != j.end() && a->is_object()) {
    o.accepted = a->value("accepted", false);
    o.margin = a->value("margin", 0.0);
  }
  o.T_target_source = transform_from_json(j.find("T_target_source"), j.end());
  if (gt != j.end() && gt->is_object())
    o.T_target_source_gt = transform_from_json(gt->find("T_target_source"), gt->end());
  const std::string trim = j.value("trim", "");
  if (trim == to_string(TrimKind::difference)) o.trim = TrimKind::difference;
  if (trim == to_string(TrimKind::ratio)) o.trim = TrimKind::ratio;
  const auto levels = j.find("levels");
  if (levels != j.end() && levels->is_array())
    for (const auto& l : *levels) {
      o.level_success.push_back(l.is_object() && l.value("success", false));
      o.level_epsilons.push_back(l.is_object() ? l.value("epsilon", 0.0) : 0.0);
    }
  const auto t = j.find("timings_ms");
  o.timed = t != j.end() && t->is_object() && t->contains("total");
  if (o.timed) o.total_ms = t->value("total", 0.0);
  o.report_json = j.dump();
  return o;
}

}  // namespace

std::vector<PairOutcome> read_bench_results(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the results file");
  std::vector<PairOutcome> out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = path + ":" + std::to_string(n);
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(line);
    } catch (const nlohmann::json::exception&) {
      throw InputError(where + ": not JSON");
    }
    out.push_back(outcome_from_line(j, where));
  }
  if (out.empty()) throw InputError(path + ": no results in the file");
  return out;
}

}  // namespace pagor
