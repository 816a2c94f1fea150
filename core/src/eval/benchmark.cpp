#include "pagor/eval/benchmark.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <new>
#include <nlohmann/json.hpp>
#include <sstream>

#include "pagor/errors.hpp"
#include "pagor/io/file_input.hpp"
#include "pagor/io/json_input.hpp"
#include "pagor/report.hpp"
#include "pagor/verify/diagnosis.hpp"

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

PairOutcome run_pair(Pipeline& pipeline, const PairEntry& entry, const std::atomic<bool>* cancel) {
  PairOutcome o;
  o.name = entry.name;
  o.negative = entry.negative;
  LoadedPair pair;
  try {
    pair = load_pair(entry.source, pipeline.config().indoor, pipeline.threads_now());
  } catch (const InputError& e) {
    o.load_error = e.what();
    return o;
  } catch (const std::bad_alloc&) {
    o.load_error = describe(entry.source) + ": out of memory while loading the pair";
    return o;
  }
  o.has_ground_truth = pair.T_target_source_gt.has_value();
  std::vector<std::string> warnings = pair.source.warnings;
  warnings.insert(warnings.end(), pair.target.warnings.begin(), pair.target.warnings.end());
  pipeline.set_input(std::move(pair.source.cloud), std::move(pair.target.cloud),
                     pair_label_scheme(entry.source));
  pipeline.set_ground_truth(pair.T_target_source_gt);
  // The pair's own failures fail the pair, naming its files; a ConfigError (the configuration's,
  // the same for every pair) and Cancelled go to the caller.
  try {
    pipeline.run(ProgressFn{}, cancel);
  } catch (const InputError& e) {
    o.load_error = describe(entry.source) + ": " + e.what();
    return o;
  } catch (const std::bad_alloc&) {
    o.load_error = describe(entry.source) + ": out of memory while running the pair";
    return o;
  }
  o = pair_outcome(pipeline, entry, pair.source_name, pair.target_name);
  o.load_warnings = std::move(warnings);
  return o;
}

PairOutcome pair_outcome(const Pipeline& pipeline, const PairEntry& entry,
                         const std::string& source_name, const std::string& target_name) {
  RegistrationContext context;
  context.source_name = source_name;
  context.target_name = target_name;
  return pair_outcome(make_registration(pipeline, context), entry);
}

PairOutcome pair_outcome(const Registration& r, const PairEntry& entry) {
  PairOutcome o;
  o.name = entry.name;
  o.negative = entry.negative;
  o.loaded = true;
  o.has_ground_truth = r.T_target_source_gt.has_value();
  o.source_name = r.source_name;
  o.target_name = r.target_name;
  o.selected_level = r.selected_level;
  o.error = r.error;
  o.success = r.succeeded();
  o.upper_bound = r.any_level_succeeds;
  o.accepted = r.acceptance.accepted;
  o.margin = r.acceptance.margin;
  o.score = r.acceptance.adopted.applied ? r.acceptance.adopted.score_D
            : o.selected_level >= 0 ? r.levels[static_cast<std::size_t>(o.selected_level)].score_D
                                    : std::numeric_limits<double>::quiet_NaN();
  for (const LevelSummary& l : r.levels) {
    if (o.has_ground_truth) o.level_success.push_back(l.error && l.error->success);
    o.level_epsilons.push_back(l.epsilon);
  }
  o.T_target_source = r.T_target_source;
  o.T_target_source_gt = r.T_target_source_gt;
  o.trim = r.config.graph.trim;
  o.stage_ms = r.stage_ms;
  o.total_ms = r.total_ms;
  if (r.diagnosis) o.diagnosis = verdict_name(r.diagnosis->verdict);
  nlohmann::json j = report_object(r, false);
  j["trim"] = to_string(r.config.graph.trim);  // the unit of the levels' epsilon
  j["pair"] = entry.name;
  if (entry.negative) j["negative"] = true;
  o.report_json = dump_report(j, -1);
  return o;
}

std::string rate_text(std::optional<double> rate) {
  if (!rate) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.1f %%", 100.0 * *rate);
  return buf;
}

namespace {

// The per-level picks of the pairs with ground truth.
void count_levels(const PairOutcome& o, BenchmarkSummary& s) {
  if (s.levels.size() < o.level_success.size()) s.levels.resize(o.level_success.size());
  if (o.selected_level >= 0 && static_cast<std::size_t>(o.selected_level) < s.levels.size()) {
    LevelPicks& l = s.levels[static_cast<std::size_t>(o.selected_level)];
    ++l.selected;
    l.selected_and_succeeded += o.success;
  }
  for (std::size_t l = 0; l < o.level_success.size(); ++l)
    s.levels[l].alone_succeeds += o.level_success[l];
}

}  // namespace

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
      count_levels(o, s);
    }
    if (o.accepted && !o.negative && !o.has_ground_truth) ++s.accepted_unjudged;
    if (o.accepted && (o.negative || o.has_ground_truth)) {  // a verdict that can be judged
      ++s.accepted;
      if (o.accepted_wrong())
        ++s.false_accepts;
      else
        ++s.true_accepts;
    }
    if (!o.diagnosis.empty()) {
      auto it = std::find_if(s.diagnoses.begin(), s.diagnoses.end(),
                             [&](const auto& d) { return d.first == o.diagnosis; });
      if (it == s.diagnoses.end())
        s.diagnoses.push_back({o.diagnosis, 1});
      else
        ++it->second;
    }
    if (!s.trim && o.trim) s.trim = o.trim;
    for (std::size_t l = 0; l < o.level_epsilons.size(); ++l) {
      if (s.levels.size() <= l) s.levels.resize(l + 1);
      if (!s.levels[l].epsilon) s.levels[l].epsilon = o.level_epsilons[l];
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

// Typed members of a results line: a member of another type counts as absent (a line written by
// hand or by another tool must not end the reader).
bool flag(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_boolean() && it->get<bool>();
}
double number(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : 0.0;
}
std::string text(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}
const nlohmann::json* object(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_object() ? &*it : nullptr;
}

PairOutcome outcome_from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object() || text(j, "schema") != "pagor.register/1" || !j.contains("pair"))
    throw InputError(where + ": not a pagor bench result (schema pagor.register/1 with 'pair')");
  PairOutcome o;
  o.loaded = true;
  o.name = j["pair"].is_string() ? j["pair"].get<std::string>() : json_excerpt(j["pair"]);
  o.negative = flag(j, "negative");
  o.source_name = text(j, "source");
  o.target_name = text(j, "target");
  const auto level = j.find("selected_level");
  if (level != j.end() && level->is_number_integer()) o.selected_level = level->get<int>();
  if (const nlohmann::json* gt = object(j, "ground_truth")) {
    o.has_ground_truth = true;
    o.success = flag(*gt, "success");
    o.upper_bound = flag(*gt, "upper_bound");
    if (gt->contains("translation_error_m"))
      o.error = PoseError{number(*gt, "translation_error_m"), number(*gt, "rotation_error_deg"),
                          o.success};
    o.T_target_source_gt = transform_from_json(gt->find("T_target_source"), gt->end());
  }
  if (const nlohmann::json* a = object(j, "acceptance")) {
    o.accepted = flag(*a, "accepted");
    o.margin = number(*a, "margin");
  }
  if (const nlohmann::json* d = object(j, "diagnosis")) o.diagnosis = text(*d, "verdict");
  o.T_target_source = transform_from_json(j.find("T_target_source"), j.end());
  o.trim = enum_from_string<TrimKind>(text(j, "trim"));
  const auto levels = j.find("levels");
  if (levels != j.end() && levels->is_array())
    for (const auto& l : *levels) {
      o.level_success.push_back(l.is_object() && flag(l, "success"));
      o.level_epsilons.push_back(l.is_object() ? number(l, "epsilon") : 0.0);
    }
  const nlohmann::json* t = object(j, "timings_ms");
  o.timed = t && t->contains("total");
  if (o.timed) o.total_ms = number(*t, "total");
  o.report_json = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return o;
}

}  // namespace

std::vector<PairOutcome> read_bench_results(const std::string& path) {
  std::istringstream in(read_file(path, "results file", kMaxResultsFileBytes));
  std::vector<PairOutcome> out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = path + ":" + std::to_string(n);
    out.push_back(outcome_from_json_line(line, where));
  }
  if (out.empty()) throw InputError(path + ": no results in the file");
  return out;
}

PairOutcome outcome_from_json_line(const std::string& line, const std::string& where) {
  nlohmann::json j;
  try {
    j = parse_json_limited(line, where);
  } catch (const Error&) {
    throw InputError(where + ": not JSON");
  }
  return outcome_from_json(j, where);
}

}  // namespace pagor
