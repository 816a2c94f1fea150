#include "pagor/eval/sweep.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <numeric>
#include <optional>
#include <sstream>

#include "pagor/errors.hpp"
#include "pagor/graph/trim.hpp"

namespace pagor {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", v);
  return buf;
}

// A number as JSON: the shortest text that reads back as the same double.
std::string json_number(double v) {
  return nlohmann::json(v).dump();
}

// The catalog entry of `path` in `config` (null when it names no parameter).
const ConfigField* field_at(const std::vector<ConfigField>& fields, const std::string& path) {
  for (const ConfigField& f : fields)
    if (f.path == path) return &f;
  return nullptr;
}

// A value as a label shows it, with the parameter's unit ("trim": the setting's TRIM unit).
std::string value_text(const ConfigField& f, const std::string& json_text, const Config& config) {
  const nlohmann::json v = nlohmann::json::parse(json_text);
  const std::string unit = f.info.unit;
  const std::string suffix = unit == "trim" ? trim_unit_suffix(config.graph.trim)
                             : unit.empty() ? ""
                                            : " " + unit;
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number()) return number(v.get<double>()) + suffix;
  std::string out;
  if (v.is_array())
    for (const auto& x : v) out += (out.empty() ? "" : "/") + number(x.get<double>());
  return out + suffix;
}

// The dimensions in document order (the order of the catalog), each checked to name a parameter.
std::vector<std::pair<const SweepDimension*, ConfigField>> ordered_dimensions(
    const Config& base, const SweepGrid& grid) {
  const std::vector<ConfigField> fields = config_fields(base);
  std::vector<std::pair<std::size_t, std::pair<const SweepDimension*, ConfigField>>> order;
  for (const SweepDimension& d : grid.dimensions) {
    const ConfigField* f = field_at(fields, d.path);
    if (!f) throw ConfigError("sweep: " + d.path + ": no such parameter");
    if (d.values.empty()) throw ConfigError("sweep: " + d.path + ": no values");
    order.push_back({static_cast<std::size_t>(f - fields.data()), {&d, *f}});
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<const SweepDimension*, ConfigField>> out;
  for (auto& o : order) out.push_back(std::move(o.second));
  return out;
}

}  // namespace

SweepGrid& SweepGrid::add(const std::string& path, const std::vector<double>& values) {
  std::vector<std::string> json;
  for (double v : values) json.push_back(json_number(v));
  return add_json(path, std::move(json));
}

SweepGrid& SweepGrid::add_json(const std::string& path, std::vector<std::string> values) {
  dimensions.push_back({path, std::move(values)});
  return *this;
}

std::string sweep_dimension_name(const std::string& path) {
  static const std::pair<const char*, const char*> kShort[] = {{"graph.thresholds", "eps"},
                                                               {"verification.mu", "mu"},
                                                               {"graph.trim", "trim"},
                                                               {"gnc.model", "model"},
                                                               {"clique.solver", "solver"}};
  for (const auto& [p, name] : kShort)
    if (path == p) return name;
  return path;
}

std::vector<SweepSetting> sweep_settings(const Config& base, const SweepGrid& grid) {
  const auto dims = ordered_dimensions(base, grid);
  std::vector<std::size_t> at(dims.size(), 0);  // an odometer over the dimensions, last fastest
  std::vector<SweepSetting> out;
  for (;;) {
    SweepSetting s;
    for (std::size_t k = 0; k < dims.size(); ++k)
      s.values.push_back({dims[k].first->path, dims[k].first->values[at[k]]});
    s.config = base;
    const std::string where = "sweep setting " + std::to_string(out.size() + 1);
    try {
      set_fields_json(s.config, s.values);
    } catch (const ConfigError& e) {
      std::string values;
      for (const auto& [path, v] : s.values) values += (values.empty() ? "" : " ") + path + "=" + v;
      throw ConfigError(where + " (" + values + "): " + e.what());
    }
    for (std::size_t k = 0; k < dims.size(); ++k)
      if (dims[k].first->values.size() > 1)
        s.label += (s.label.empty() ? "" : " ") + sweep_dimension_name(dims[k].first->path) + "=" +
                   value_text(dims[k].second, s.values[k].second, s.config);
    if (s.label.empty()) s.label = "base";
    out.push_back(std::move(s));
    std::size_t k = dims.size();
    while (k > 0 && ++at[k - 1] == dims[k - 1].first->values.size()) at[--k] = 0;
    if (k == 0) break;
  }
  return out;
}

SweepDimension parse_sweep_dimension(const Config& base, const std::string& path,
                                     const std::string& values, const std::string& what) {
  const std::vector<ConfigField> fields = config_fields(base);
  const ConfigField* f = field_at(fields, path);
  if (!f) throw InputError(what + ": " + path + ": no such parameter (pagor config --describe)");
  SweepDimension d{path, {}};
  switch (f->kind) {
    case FieldKind::number:
    case FieldKind::integer:
    case FieldKind::flag:
      for (double v : parse_number_list(values, what)) d.values.push_back(json_number(v));
      break;
    case FieldKind::choice: {
      std::stringstream in(values);
      std::string item;
      while (std::getline(in, item, ',')) {
        if (std::find(f->choices.begin(), f->choices.end(), item) == f->choices.end()) {
          std::string names;
          for (const auto& c : f->choices) names += (names.empty() ? "\"" : ", \"") + c + "\"";
          throw InputError(what + ": element " + std::to_string(d.values.size() + 1) + " '" + item +
                           "' is not one of " + names);
        }
        d.values.push_back(nlohmann::json(item).dump());
      }
      if (d.values.empty()) throw InputError(what + ": no values in '" + values + "'");
      break;
    }
    case FieldKind::numbers:
      for (const auto& set : parse_threshold_sets(values, what))
        d.values.push_back(nlohmann::json(set).dump());
      break;
    case FieldKind::text:
    case FieldKind::other:
      throw InputError(what + ": " + path + " cannot be swept (not a number, a choice or a list " +
                       "of numbers)");
  }
  return d;
}

SweepDimension parse_sweep_spec(const Config& base, const std::string& spec,
                                const std::string& what) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(what + ": expected PATH=v1,v2,..., got '" + spec + "'");
  return parse_sweep_dimension(base, spec.substr(0, eq), spec.substr(eq + 1), what);
}

SweepResult run_sweep(SetRunner& runner, const std::vector<SweepSetting>& settings,
                      const SweepProgressFn& progress, const std::atomic<bool>* cancel) {
  SweepResult result;
  result.pairs = static_cast<int>(runner.size());
  for (const SweepSetting& s : settings) result.settings.push_back({s, {}, {}, 0.0});
  const std::array<int, kStageCount> runs_before = runner.stage_runs();
  for (std::size_t p = 0; p < runner.size(); ++p) {
    std::optional<PairOutcome> skipped;  // a pair that does not load is skipped in every setting
    for (std::size_t k = 0; k < settings.size(); ++k) {
      if (cancel && cancel->load()) throw Cancelled();
      const auto t0 = std::chrono::steady_clock::now();
      PairOutcome o = skipped ? *skipped : runner.run(p, settings[k].config, cancel);
      if (!o.loaded) skipped = o;
      result.settings[k].wall_ms +=
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      if (progress) progress(static_cast<int>(p), static_cast<int>(k), o);
      result.settings[k].outcomes.push_back(std::move(o));
    }
  }
  for (int i = 0; i < kStageCount; ++i)
    result.stage_runs[static_cast<std::size_t>(i)] =
        runner.stage_runs()[static_cast<std::size_t>(i)] - runs_before[static_cast<std::size_t>(i)];
  for (SweepSettingResult& r : result.settings) r.summary = summarize(r.outcomes);
  return result;
}

SweepResult run_sweep(const PairSet& set, const std::vector<SweepSetting>& settings, int threads,
                      const SweepProgressFn& progress, const std::atomic<bool>* cancel, int jobs) {
  if (jobs <= 1 || set.pairs.size() < 2) {
    SetRunner runner(set, threads);
    return run_sweep(runner, settings, progress, cancel);
  }
  std::vector<std::unique_ptr<SetRunner>> runners = make_runners(set, jobs, threads);
  return run_sweep(runners, settings, progress, cancel);
}

SweepResult run_sweep(std::vector<std::unique_ptr<SetRunner>>& runners,
                      const std::vector<SweepSetting>& settings, const SweepProgressFn& progress,
                      const std::atomic<bool>* cancel) {
  assert(!runners.empty());
  if (runners.size() == 1) return run_sweep(*runners.front(), settings, progress, cancel);
  const std::size_t n = runners.front()->size();
  std::vector<std::array<int, kStageCount>> runs_before;
  for (const auto& runner : runners) runs_before.push_back(runner->stage_runs());
  // by_pair[p][k]: pair p's outcome and time with setting k, each pair filled by one worker
  std::vector<std::vector<PairOutcome>> by_pair(n);
  std::vector<std::vector<double>> ms(n, std::vector<double>(settings.size(), 0.0));
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  run_parallel(
      static_cast<int>(runners.size()), order,
      [&](int w, std::size_t p, const std::atomic<int>* lent, const std::atomic<bool>* stop) {
        SetRunner& runner = *runners[static_cast<std::size_t>(w)];
        std::optional<PairOutcome> skipped;  // a pair that does not load: skipped in every setting
        for (std::size_t k = 0; k < settings.size(); ++k) {
          if (stop->load()) throw Cancelled();
          const auto t0 = std::chrono::steady_clock::now();
          PairOutcome o = skipped ? *skipped : runner.run(p, settings[k].config, stop, lent);
          if (!o.loaded) skipped = o;
          ms[p][k] =
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                  .count();
          by_pair[p].push_back(std::move(o));
        }
      },
      [&](std::size_t p) {
        if (progress)
          for (std::size_t k = 0; k < settings.size(); ++k)
            progress(static_cast<int>(p), static_cast<int>(k), by_pair[p][k]);
      },
      cancel);
  SweepResult result;
  result.pairs = static_cast<int>(n);
  for (std::size_t k = 0; k < settings.size(); ++k) {
    SweepSettingResult r{settings[k], {}, {}, 0.0};
    for (std::size_t p = 0; p < n; ++p) {
      r.outcomes.push_back(std::move(by_pair[p][k]));
      r.wall_ms += ms[p][k];
    }
    r.summary = summarize(r.outcomes);
    result.settings.push_back(std::move(r));
  }
  for (std::size_t w = 0; w < runners.size(); ++w)
    for (std::size_t i = 0; i < static_cast<std::size_t>(kStageCount); ++i)
      result.stage_runs[i] += runners[w]->stage_runs()[i] - runs_before[w][i];
  return result;
}

std::vector<double> parse_number_list(const std::string& text, const std::string& what) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
    const std::string t = b == std::string::npos ? "" : item.substr(b, e - b + 1);
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0' || !std::isfinite(v))
      throw InputError(what + ": element " + std::to_string(out.size() + 1) + " '" + t +
                       "' is not a number");
    out.push_back(v);
  }
  if (out.empty()) throw InputError(what + ": no numbers in '" + text + "'");
  return out;
}

std::vector<std::vector<double>> parse_threshold_sets(const std::string& text,
                                                      const std::string& what) {
  std::vector<std::vector<double>> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ';'))
    out.push_back(parse_number_list(item, what + ", set " + std::to_string(out.size() + 1)));
  if (out.empty()) throw InputError(what + ": no threshold set in '" + text + "'");
  return out;
}

std::string sweep_csv(const SweepResult& result) {
  std::string out =
      "setting,pairs_run,with_truth,successes,success_rate,upper_bound,upper_bound_rate,"
      "accepted,precision,recall,mean_time_ms,wall_ms\n";
  for (const SweepSettingResult& r : result.settings) {
    const BenchmarkSummary& s = r.summary;
    const auto cell = [](std::optional<double> rate) {  // an undefined rate is an empty cell
      char buf[32] = "";
      if (rate) std::snprintf(buf, sizeof(buf), "%.4f", *rate);
      return std::string(buf);
    };
    char times[64];
    std::snprintf(times, sizeof(times), "%.2f,%.2f", s.mean_total_ms, r.wall_ms);
    out += "\"" + r.setting.label + "\"," + std::to_string(s.pairs_run) + "," +
           std::to_string(s.with_truth) + "," + std::to_string(s.successes) + "," +
           cell(s.success_rate()) + "," + std::to_string(s.upper_bound) + "," +
           cell(s.upper_bound_rate()) + "," + std::to_string(s.accepted_total()) + "," +
           cell(s.precision()) + "," + cell(s.recall()) + "," + times + "\n";
  }
  return out;
}

namespace {

// An undefined rate is null.
nlohmann::json json_rate(std::optional<double> rate) {
  return rate ? nlohmann::json(*rate) : nlohmann::json();
}

}  // namespace

std::string sweep_json_lines(const SweepResult& result) {
  std::string out;
  for (const SweepSettingResult& r : result.settings) {
    const BenchmarkSummary& s = r.summary;
    nlohmann::json j = {{"schema", "pagor.sweep/1"},
                        {"setting", r.setting.label},
                        {"thresholds", r.setting.config.graph.thresholds},
                        {"mu", r.setting.config.verification.mu},
                        {"trim", to_string(r.setting.config.graph.trim)},
                        {"model", to_string(r.setting.config.gnc.model)},
                        {"solver", to_string(r.setting.config.clique.solver)},
                        {"pairs_run", s.pairs_run},
                        {"with_truth", s.with_truth},
                        {"successes", s.successes},
                        {"upper_bound", s.upper_bound},
                        {"accepted", s.accepted_total()},
                        {"accepted_unjudged", s.accepted_unjudged},
                        {"precision", json_rate(s.precision())},
                        {"recall", json_rate(s.recall())},
                        {"mean_time_ms", s.mean_total_ms},
                        {"wall_ms", r.wall_ms}};
    nlohmann::json values = nlohmann::json::object();  // every dimension's value, by key path
    for (const auto& [path, v] : r.setting.values) values[path] = nlohmann::json::parse(v);
    j["values"] = std::move(values);
    nlohmann::json pairs = nlohmann::json::array();
    for (const PairOutcome& o : r.outcomes)
      pairs.push_back({{"pair", o.name},
                       {"loaded", o.loaded},
                       {"success", o.success},
                       {"upper_bound", o.upper_bound},
                       {"accepted", o.accepted},
                       {"selected_level", o.selected_level}});
    j["pairs"] = std::move(pairs);
    out += j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";  // names: bytes
  }
  return out;
}

}  // namespace pagor
