#include "bench_plots.hpp"

#include <algorithm>

namespace pagor::studio {
namespace {

double percent(int n, int of) {
  return of ? 100.0 * n / of : 0.0;
}

}  // namespace

Plot sweep_success_plot(const SweepResult& result) {
  Plot p;
  p.title = "Sweep: success per setting";
  p.kind = PlotKind::bars;
  p.value_label = "pairs with ground truth";
  p.value_unit = "%";
  p.value_min = 0.0;
  p.value_max = 100.0;
  p.series = {{"success", {}, {}}, {"upper bound", {}, {}}};
  for (const SweepSettingResult& r : result.settings) {
    p.categories.push_back(r.setting.label);
    p.series[0].y.push_back(percent(r.summary.successes, r.summary.with_truth));
    p.series[1].y.push_back(percent(r.summary.upper_bound, r.summary.with_truth));
  }
  return p;
}

Plot sweep_line_plot(const SweepResult& result) {
  Plot p;
  p.kind = PlotKind::lines;
  p.value_label = "success";
  p.value_unit = "%";
  p.value_min = 0.0;
  p.value_max = 100.0;
  if (result.settings.size() < 2) return p;
  const Config& a = result.settings[0].setting.config;
  const Config& b = result.settings[1].setting.config;
  const bool mu = a.verification.mu != b.verification.mu;
  const bool eps = a.graph.thresholds.size() == 1 && a.graph.thresholds != b.graph.thresholds;
  if (!mu && !eps) return p;
  p.title = mu ? "Success against mu" : "Success against a single epsilon";
  p.x_label = mu ? "mu" : "epsilon";
  p.x_unit = mu ? "m" : (a.graph.trim == TrimKind::ratio ? "ratio" : "m");
  p.series = {{"success", {}, {}}, {"upper bound", {}, {}}};
  for (const SweepSettingResult& r : result.settings) {
    const Config& c = r.setting.config;
    if (c.graph.thresholds.empty()) return Plot{};
    const double x = mu ? c.verification.mu : c.graph.thresholds.front();
    p.series[0].x.push_back(x);
    p.series[1].x.push_back(x);
    p.series[0].y.push_back(percent(r.summary.successes, r.summary.with_truth));
    p.series[1].y.push_back(percent(r.summary.upper_bound, r.summary.with_truth));
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
  Plot p;
  p.title = "Rates";
  p.kind = PlotKind::bars;
  p.value_label = "rate";
  p.value_unit = "%";
  p.value_min = 0.0;
  p.value_max = 100.0;
  p.categories = {"success", "upper bound", "verdict precision", "verdict recall"};
  p.series = {{"this run",
               {},
               {percent(s.successes, s.with_truth), percent(s.upper_bound, s.with_truth),
                100.0 * s.precision(), 100.0 * s.recall()}}};
  return p;
}

}  // namespace pagor::studio
