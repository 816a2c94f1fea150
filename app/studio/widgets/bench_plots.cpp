#include "widgets/bench_plots.hpp"

#include "widgets/timings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>

namespace pagor::studio {
namespace {

// A rate in percent; an undefined one (BenchmarkSummary) is NaN, which the plots show as n/a.
double percent(std::optional<double> rate) {
  return rate ? 100.0 * *rate : std::numeric_limits<double>::quiet_NaN();
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
  // success, upper bound: of the pairs with a ground truth; precision: of the accepted pairs;
  // recall: of the right poses (benchmark.hpp defines each rate once)
  Plot p = percent_plot(PlotKind::bars, "rate");
  p.title = "Sweep: success and verdict per setting";
  // Precision beside recall: a setting that buys precision with recall shows it at a glance.
  p.series = {{"success", {}, {}},
              {"upper bound", {}, {}},
              {"verdict precision", {}, {}},
              {"verdict recall", {}, {}}};
  for (const SweepSettingResult& r : result.settings) {
    p.categories.push_back(r.setting.label);
    p.series[0].y.push_back(percent(r.summary.success_rate()));
    p.series[1].y.push_back(percent(r.summary.upper_bound_rate()));
    p.series[2].y.push_back(percent(r.summary.precision()));
    p.series[3].y.push_back(percent(r.summary.recall()));
  }
  return p;
}

namespace {

// What a line plot of a sweep puts on x: the innermost dimension that varies, when its values
// are numbers (or single thresholds), and what tells its series apart: the other varying
// dimension (at most one more).
struct SweepAxes {
  int x = -1;       // index into each setting's values; -1: no line plot
  int series = -1;  // -1: one series
};

std::optional<double> number_of(const std::string& json_text) {
  const auto v = nlohmann::json::parse(json_text, nullptr, false);
  if (v.is_number()) return v.get<double>();
  if (v.is_array() && v.size() == 1 && v[0].is_number()) return v[0].get<double>();
  return std::nullopt;
}

SweepAxes sweep_axes(const SweepResult& result) {
  SweepAxes a;
  if (result.settings.size() < 2) return a;
  const auto& first = result.settings[0].setting.values;
  std::vector<int> varying;
  for (std::size_t k = 0; k < first.size(); ++k)
    for (const SweepSettingResult& r : result.settings)
      if (r.setting.values.size() == first.size() && r.setting.values[k] != first[k]) {
        varying.push_back(static_cast<int>(k));
        break;
      }
  if (varying.empty() || varying.size() > 2) return a;
  const int x = varying.back();
  for (const SweepSettingResult& r : result.settings)
    if (!number_of(r.setting.values[static_cast<std::size_t>(x)].second)) return a;
  a.x = x;
  if (varying.size() == 2) a.series = varying.front();
  return a;
}

void set_axis(Plot& p, const SweepResult& result, int x) {
  const Config& c = result.settings[0].setting.config;
  const std::string path = result.settings[0].setting.values[static_cast<std::size_t>(x)].first;
  const std::string name = sweep_dimension_name(path);
  p.x_label = name == "eps" ? "epsilon" : name;
  for (const ConfigField& f : config_fields(c))
    if (f.path == path)
      p.x_unit = std::string(f.info.unit) == "trim"
                     ? (c.graph.trim == TrimKind::ratio ? "ratio" : "m")
                     : f.info.unit;
  p.title = name == "mu"    ? "Success against mu"
            : name == "eps" ? "Success against a single epsilon"
                            : "Success against " + name;
}

double x_of(const SweepSettingResult& r, int x) {
  return *number_of(r.setting.values[static_cast<std::size_t>(x)].second);
}

}  // namespace

Plot sweep_line_plot(const SweepResult& result) {
  Plot p = percent_plot(PlotKind::lines, "success");
  const SweepAxes a = sweep_axes(result);
  if (a.x < 0) return p;
  set_axis(p, result, a.x);
  if (a.series < 0)
    p.series = {{"success", {}, {}},
                {"upper bound", {}, {}},
                {"verdict precision", {}, {}},
                {"verdict recall", {}, {}}};
  for (const SweepSettingResult& r : result.settings) {
    const double x = x_of(r, a.x);
    if (a.series < 0) {
      const BenchmarkSummary& s = r.summary;
      const double y[] = {percent(s.success_rate()), percent(s.upper_bound_rate()),
                          percent(s.precision()), percent(s.recall())};
      for (std::size_t i = 0; i < p.series.size(); ++i) {
        p.series[i].x.push_back(x);
        p.series[i].y.push_back(y[i]);
      }
      continue;
    }
    // Two dimensions: a success series per value of the outer one.
    const auto& [path, value] = r.setting.values[static_cast<std::size_t>(a.series)];
    const std::string label = sweep_dimension_name(path) + "=" + value;
    auto it = std::find_if(p.series.begin(), p.series.end(),
                           [&](const PlotSeries& s) { return s.label == label; });
    if (it == p.series.end()) it = p.series.insert(p.series.end(), PlotSeries{label, {}, {}});
    it->x.push_back(x);
    it->y.push_back(percent(r.summary.success_rate()));
  }
  return p;
}

Plot sweep_pair_plot(const SweepResult& result, std::size_t pair) {
  Plot p;
  p.kind = PlotKind::lines;
  p.value_label = "D of the selected pose";
  p.value_unit = "m";
  const SweepAxes a = sweep_axes(result);
  if (a.x < 0 || a.series >= 0 || result.settings[0].outcomes.size() <= pair) return p;
  set_axis(p, result, a.x);
  p.title = "Pair " + result.settings[0].outcomes[pair].name + ": D and success";
  p.series = {{"success", {}, {}, true}, {"failure", {}, {}, true}};
  for (const SweepSettingResult& r : result.settings) {
    const PairOutcome& o = r.outcomes[pair];
    if (!o.loaded || !std::isfinite(o.score)) continue;
    PlotSeries& s = p.series[o.success ? 0 : 1];
    s.x.push_back(x_of(r, a.x));
    s.y.push_back(o.score);
  }
  return p;
}

Plot picking_plot(const BenchmarkSummary& s) {
  Plot p;
  p.title = "Picking: per pyramid level";
  p.kind = PlotKind::bars;
  p.value_label = "pairs";
  p.value_unit = "count";
  p.value_min = 0.0;
  p.integer_values = true;
  p.series = {
      {"selected", {}, {}}, {"alone would succeed", {}, {}}, {"selected and succeeded", {}, {}}};
  for (std::size_t l = 0; l < s.levels.size(); ++l) {
    const LevelPicks& picks = s.levels[l];
    p.categories.push_back(level_label(static_cast<int>(l), picks.epsilon, s.trim));
    p.series[0].y.push_back(picks.selected);
    p.series[1].y.push_back(picks.alone_succeeds);
    p.series[2].y.push_back(picks.selected_and_succeeded);
  }
  return p;
}

Plot rates_plot(const BenchmarkSummary& s) {
  Plot p = percent_plot(PlotKind::bars, "rate");
  p.title = "Rates";
  p.categories = {"success", "upper bound", "verdict precision", "verdict recall"};
  p.series = {{"this run",
               {},
               {percent(s.success_rate()), percent(s.upper_bound_rate()), percent(s.precision()),
                percent(s.recall())}}};
  return p;
}

}  // namespace pagor::studio

namespace pagor::studio {

std::string level_label(int level, std::optional<double> epsilon, std::optional<TrimKind> trim) {
  std::string s = "level " + std::to_string(level);
  if (!epsilon) return s;
  char buf[48];
  std::snprintf(buf, sizeof(buf), ": \xCE\xB5 = %.3g%s", *epsilon,
                trim ? trim_unit_suffix(*trim) : "");
  return s + buf;
}

namespace {

constexpr ImU32 kTruthColor = IM_COL32(200, 200, 210, 255);
constexpr ImU32 kFailureColor = IM_COL32(240, 60, 50, 255);
constexpr ImU32 kRejectedColor = IM_COL32(125, 125, 130, 255);

void add_plan(Plot& p, const FloorPlan& plan) {
  for (const PlanWall& w : plan.walls) {
    std::vector<std::array<double, 2>> line;
    for (const Eigen::Vector2d& v : w.points) line.push_back({v.x(), v.y()});
    if (w.closed && w.points.size() > 2) line.push_back(line.front());
    p.backdrop.lines.push_back(std::move(line));
  }
  for (const PlanColumn& c : plan.columns)
    p.backdrop.circles.push_back({c.center.x(), c.center.y(), c.radius});
}

std::string pair_tip(const PairOutcome& o, std::size_t index, const Eigen::Vector3d& t) {
  char buf[160];
  std::snprintf(buf, sizeof(buf), " (scan index %zu)\nposition (%.2f, %.2f) m", index, t.x(),
                t.y());
  std::string tip = "pair " + o.name + buf;
  if (o.error) {
    std::snprintf(buf, sizeof(buf), "\nerror %.2f m, %.2f\xC2\xB0 (%s)", o.error->translation,
                  o.error->rotation_deg, o.success ? "success" : "failure");
    tip += buf;
  }
  const auto l = static_cast<std::size_t>(o.selected_level);
  const std::optional<double> eps =
      l < o.level_epsilons.size() ? std::optional<double>(o.level_epsilons[l]) : std::nullopt;
  return tip + "\n" + level_label(o.selected_level, eps, o.trim) +
         " picked\nverdict: " + (o.accepted ? "accepted" : "rejected");
}

}  // namespace

Plot trajectory_plot(const std::vector<PairOutcome>& outcomes, const FloorPlan* plan) {
  Plot p;
  p.title = "Trajectory: re-localized positions over the plan";
  p.kind = PlotKind::map;
  p.x_label = "x";
  p.x_unit = "m";
  p.value_label = "y";
  p.value_unit = "m";
  if (plan) add_plan(p, *plan);
  p.series = {{"ground truth", {}, {}},
              {"re-localized", {}, {}},
              {"failure", {}, {}},
              {"rejected", {}, {}}};
  p.series[0].line_only = true;
  p.series[0].color = kTruthColor;
  p.series[2].marker = PlotMarker::cross;
  p.series[2].color = kFailureColor;
  p.series[3].color = kRejectedColor;
  p.color_bar = PlotColorBar{"time", "scan index", 0.0, std::max(1.0, outcomes.size() - 1.0)};
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const PairOutcome& o = outcomes[i];
    if (o.T_target_source_gt) {
      p.series[0].x.push_back((*o.T_target_source_gt)(0, 3));
      p.series[0].y.push_back((*o.T_target_source_gt)(1, 3));
    }
    if (!o.T_target_source) continue;
    const Eigen::Vector3d t = o.T_target_source->topRightCorner<3, 1>();
    PlotSeries& s = p.series[o.error && !o.success ? 2 : !o.accepted ? 3 : 1];
    s.x.push_back(t.x());
    s.y.push_back(t.y());
    s.tips.push_back(pair_tip(o, i, t));
    if (&s == &p.series[1]) s.color_values.push_back(static_cast<double>(i));
  }
  return p;
}

std::string summary_text(const BenchmarkSummary& s) {
  char line[320];
  std::snprintf(line, sizeof(line),
                "success %d/%d (%s), upper bound %d/%d (%s); verdict: %d accepted (%d without "
                "truth), precision %s, recall %s; mean time %s per pair",
                s.successes, s.with_truth, rate_text(s.success_rate()).c_str(), s.upper_bound,
                s.with_truth, rate_text(s.upper_bound_rate()).c_str(), s.accepted_total(),
                s.accepted_unjudged, rate_text(s.precision()).c_str(),
                rate_text(s.recall()).c_str(), ui::timing("%.0f ms", s.mean_total_ms).c_str());
  // Pairs that failed (unreadable files, data the stages refused) are in no rate: say how many,
  // so that "0/0 (n/a)" over a set of failed pairs cannot read as a set without truth.
  if (s.skipped > 0)
    return std::to_string(s.skipped) + (s.skipped == 1 ? " pair" : " pairs") +
           " failed (in no rate: see their rows); " + line;
  return line;
}

}  // namespace pagor::studio
