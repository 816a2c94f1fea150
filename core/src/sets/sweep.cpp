#include "pagor/sets/sweep.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
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

std::string thresholds_text(const std::vector<double>& t) {
  std::string s;
  for (std::size_t i = 0; i < t.size(); ++i) s += (i ? "/" : "") + number(t[i]);
  return s;
}

// The values of one dimension: the grid's, or the base's alone.
template <class T>
std::vector<T> values_or(const std::vector<T>& grid, const T& base) {
  return grid.empty() ? std::vector<T>{base} : grid;
}

}  // namespace

std::vector<SweepSetting> sweep_settings(const Config& base, const SweepGrid& grid) {
  std::vector<SweepSetting> out;
  // Outer to inner: the dimensions whose change invalidates most come first, so consecutive
  // settings (mu innermost) share the most cached stages.
  for (TrimKind trim : values_or(grid.trims, base.graph.trim))
    for (const auto& eps : values_or(grid.threshold_sets, base.graph.thresholds))
      for (CliqueSolver solver : values_or(grid.solvers, base.clique.solver))
        for (PoseModel model : values_or(grid.models, base.gnc.model))
          for (double mu : values_or(grid.mus, base.verification.mu)) {
            SweepSetting s;
            s.config = base;
            s.config.graph.trim = trim;
            s.config.graph.thresholds = eps;
            s.config.clique.solver = solver;
            s.config.gnc.model = model;
            s.config.verification.mu = mu;
            const auto add = [&s](const std::string& part) {
              s.label += (s.label.empty() ? "" : " ") + part;
            };
            if (grid.trims.size() > 1) add(std::string("trim=") + to_string(trim));
            // Units as everywhere: difference TRIM thresholds and mu in metres.
            if (grid.threshold_sets.size() > 1)
              add("eps=" + thresholds_text(eps) + trim_unit_suffix(trim));
            if (grid.solvers.size() > 1) add(std::string("solver=") + to_string(solver));
            if (grid.models.size() > 1) add(std::string("model=") + to_string(model));
            if (grid.mus.size() > 1) add("mu=" + number(mu) + " m");
            if (s.label.empty()) s.label = "base";
            validate(s.config,
                     "sweep setting " + std::to_string(out.size() + 1) + " (" + s.label + ")");
            out.push_back(std::move(s));
          }
  return out;
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
                      const SweepProgressFn& progress, const std::atomic<bool>* cancel) {
  SetRunner runner(set, threads);
  return run_sweep(runner, settings, progress, cancel);
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
