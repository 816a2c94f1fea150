#include "bench_plots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pagor::studio {
namespace {

double percent(int n, int of) {
  return of ? 100.0 * n / of : 0.0;
}

// A plot whose values are percentages, on an axis from 0 to 100 %.
Plot percent_plot(PlotKind kind, const char* value_label) {
  Plot p;
  p.kind = kind;
  p.value_label = value_label;
  p.value_unit = "%";
  p.value_min = 0.0;
  p.value_max = 100.0;
  return p;
}

}  // namespace

Plot sweep_success_plot(const SweepResult& result) {
  Plot p = percent_plot(PlotKind::bars, "pairs with ground truth");
  p.title = "Sweep: success per setting";
  p.series = {{"success", {}, {}}, {"upper bound", {}, {}}};
  for (const SweepSettingResult& r : result.settings) {
    p.categories.push_back(r.setting.label);
    p.series[0].y.push_back(percent(r.summary.successes, r.summary.with_truth));
    p.series[1].y.push_back(percent(r.summary.upper_bound, r.summary.with_truth));
  }
  return p;
}

namespace {

// What a line plot puts on x: mu, or the single threshold, when the settings differ in that
// alone (and take at least two values).
enum class Axis { none, mu, epsilon };

Axis line_axis(const SweepResult& result) {
  if (result.settings.size() < 2) return Axis::none;
  const auto without = [](Config c, Axis a) {
    if (a == Axis::mu) c.verification.mu = 0;
    if (a == Axis::epsilon) c.graph.thresholds = {1.0};
    return config_to_json(c, -1);
  };
  for (Axis a : {Axis::mu, Axis::epsilon}) {
    const std::string first = without(result.settings[0].setting.config, a);
    bool same = true;
    for (const SweepSettingResult& r : result.settings)
      same = same && without(r.setting.config, a) == first &&
             (a != Axis::epsilon || r.setting.config.graph.thresholds.size() == 1);
    if (same) return a;
  }
  return Axis::none;
}

double axis_value(const Config& c, Axis a) {
  return a == Axis::mu ? c.verification.mu : c.graph.thresholds.front();
}

void set_axis(Plot& p, Axis a, const Config& c) {
  p.x_label = a == Axis::mu ? "mu" : "epsilon";
  p.x_unit = a == Axis::mu ? "m" : (c.graph.trim == TrimKind::ratio ? "ratio" : "m");
}

}  // namespace

Plot sweep_line_plot(const SweepResult& result) {
  Plot p = percent_plot(PlotKind::lines, "success");
  const Axis a = line_axis(result);
  if (a == Axis::none) return p;
  p.title = a == Axis::mu ? "Success against mu" : "Success against a single epsilon";
  set_axis(p, a, result.settings[0].setting.config);
  p.series = {{"success", {}, {}}, {"upper bound", {}, {}}};
  for (const SweepSettingResult& r : result.settings) {
    const double x = axis_value(r.setting.config, a);
    p.series[0].x.push_back(x);
    p.series[1].x.push_back(x);
    p.series[0].y.push_back(percent(r.summary.successes, r.summary.with_truth));
    p.series[1].y.push_back(percent(r.summary.upper_bound, r.summary.with_truth));
  }
  return p;
}

Plot sweep_pair_plot(const SweepResult& result, std::size_t pair) {
  Plot p;
  p.kind = PlotKind::lines;
  p.value_label = "D of the selected pose";
  p.value_unit = "m";
  const Axis a = line_axis(result);
  if (a == Axis::none || result.settings[0].outcomes.size() <= pair) return p;
  p.title = "Pair " + result.settings[0].outcomes[pair].name + ": D and success";
  set_axis(p, a, result.settings[0].setting.config);
  p.series = {{"success", {}, {}, true}, {"failure", {}, {}, true}};
  for (const SweepSettingResult& r : result.settings) {
    const PairOutcome& o = r.outcomes[pair];
    if (!o.loaded || !std::isfinite(o.score)) continue;
    PlotSeries& s = p.series[o.success ? 0 : 1];
    s.x.push_back(axis_value(r.setting.config, a));
    s.y.push_back(o.score);
  }
  return p;
}

Plot picking_plot(const std::vector<PairOutcome>& outcomes) {
  Plot p;
  p.title = "Picking: per pyramid level";
  p.kind = PlotKind::bars;
  p.value_label = "pairs";
  p.value_unit = "count";
  p.value_min = 0.0;
  p.integer_values = true;
  std::size_t levels = 0;
  for (const PairOutcome& o : outcomes) levels = std::max(levels, o.level_success.size());
  p.series = {{"selected", std::vector<double>{}, std::vector<double>(levels, 0.0)},
              {"alone would succeed", std::vector<double>{}, std::vector<double>(levels, 0.0)},
              {"selected and succeeded", std::vector<double>{}, std::vector<double>(levels, 0.0)}};
  for (std::size_t l = 0; l < levels; ++l) p.categories.push_back("level " + std::to_string(l));
  for (const PairOutcome& o : outcomes) {
    if (!o.loaded || o.negative || !o.has_ground_truth) continue;
    if (o.selected_level >= 0 && static_cast<std::size_t>(o.selected_level) < levels) {
      p.series[0].y[static_cast<std::size_t>(o.selected_level)] += 1;
      if (o.success) p.series[2].y[static_cast<std::size_t>(o.selected_level)] += 1;
    }
    for (std::size_t l = 0; l < o.level_success.size(); ++l)
      if (o.level_success[l]) p.series[1].y[l] += 1;
  }
  return p;
}

Plot rates_plot(const BenchmarkSummary& s) {
  Plot p = percent_plot(PlotKind::bars, "rate");
  p.title = "Rates";
  p.categories = {"success", "upper bound", "verdict precision", "verdict recall"};
  // A rate of nothing (no pair with a ground truth, none accepted, none successful) is drawn as
  // n/a rather than as the 0 % or 100 % the summary's conventions would give.
  const double none = std::numeric_limits<double>::quiet_NaN();
  const auto rate = [&](int n, int of) { return of ? percent(n, of) : none; };
  p.series = {{"this run",
               {},
               {rate(s.successes, s.with_truth), rate(s.upper_bound, s.with_truth),
                rate(s.true_accepts, s.accepted), rate(s.true_accepts, s.successes)}}};
  return p;
}

}  // namespace pagor::studio
