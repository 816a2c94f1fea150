#include "widgets/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "widgets/plot_map.hpp"

namespace pagor::studio {
namespace {

using namespace plot_detail;

// `s` shortened with "..." to fit `width` [px].
std::string fit(ImFont* font, float size, std::string s, float width) {
  if (text_w(font, size, s) <= width) return s;
  while (s.size() > 1 && text_w(font, size, s + "...") > width) s.pop_back();
  return s + "...";
}

// Round ticks inside [lo, hi] whose labels fit `span` pixels along the axis (horizontal: side by
// side with a gap; vertical: a line each with a gap): at most 5, fewer when they would overlap.
std::vector<double> fitted_ticks(double lo, double hi, bool integer, float span, bool horizontal,
                                 ImFont* font, float fs) {
  std::vector<double> best;
  for (int count = 5; count >= 1; --count) {
    std::vector<double> ticks;
    for (double t : nice_ticks(lo, hi, count, integer))
      if (t >= lo - 1e-9 * (hi - lo) && t <= hi + 1e-9 * (hi - lo)) ticks.push_back(t);
    if (ticks.empty()) continue;
    const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : hi - lo;
    float need = 0;
    for (double t : ticks)
      need = std::max(need, horizontal ? text_w(font, fs, tick_text(t, step)) : fs);
    best = ticks;
    const float pitch = ticks.size() > 1 ? span / static_cast<float>((hi - lo) / step) : span;
    if (need + fs * 0.8f <= pitch || ticks.size() <= 2) return ticks;
  }
  return best;
}

// Where everything goes, shared by drawing and hovering.
struct Geometry {
  ImVec2 area_min, area_max;  // the data area [px]
  double lo = 0, hi = 1;      // value range
  double x_lo = 0, x_hi = 1;  // lines: abscissa range
  std::vector<double> ticks, x_ticks;
  float legend_y = 0, label_w = 0;
  std::vector<int> legend_rows{0};  // row of each legend entry (one entry at least)
};

float legend_entry_w(const PlotSeries& s, ImFont* font, float fs) {
  return fs * 1.1f + text_w(font, fs, s.label) + fs * 1.2f;
}

// The legend row of each series when the entries flow left to right within [x0, x1].
std::vector<int> legend_rows(const Plot& plot, float x0, float x1, ImFont* font, float fs) {
  std::vector<int> rows;
  float x = x0;
  int row = 0;
  for (const PlotSeries& s : plot.series) {
    const float w = legend_entry_w(s, font, fs);
    if (x > x0 && x + w > x1) ++row, x = x0;
    rows.push_back(row);
    x += w;
  }
  if (rows.empty()) rows.push_back(0);
  return rows;
}

void value_range(const Plot& plot, double& lo, double& hi, std::vector<double>& ticks) {
  lo = plot.kind == PlotKind::bars ? 0.0 : 1e300;
  hi = plot.kind == PlotKind::bars ? 0.0 : -1e300;
  for (const PlotSeries& s : plot.series)
    for (double v : s.y)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (lo > hi) lo = 0, hi = 1;
  if (plot.value_min) lo = *plot.value_min;
  if (plot.value_max) hi = *plot.value_max;
  if (hi - lo < 1e-12) hi = lo + 1;
  ticks = nice_ticks(lo, hi, 5, plot.integer_values);
  if (!plot.value_min) lo = std::min(lo, ticks.front());
  if (!plot.value_max) hi = std::max(hi, ticks.back());
}

Geometry layout(const Plot& plot, ImVec2 min, ImVec2 max, ImFont* font, float fs) {
  Geometry g;
  value_range(plot, g.lo, g.hi, g.ticks);
  if (plot.kind == PlotKind::lines) {
    g.x_lo = 1e300, g.x_hi = -1e300;
    for (const PlotSeries& s : plot.series)
      for (double x : s.x) g.x_lo = std::min(g.x_lo, x), g.x_hi = std::max(g.x_hi, x);
    if (g.x_lo > g.x_hi) g.x_lo = 0, g.x_hi = 1;
    if (g.x_hi - g.x_lo < 1e-12) g.x_lo -= 0.5, g.x_hi += 0.5;
    g.x_ticks = nice_ticks(g.x_lo, g.x_hi);
  }
  float top = min.y + kPad + (plot.title.empty() ? 0 : fs * 1.3f);
  g.legend_y = top;
  g.legend_rows = legend_rows(plot, min.x + kPad, max.x - kPad, font, fs);
  top += fs * 1.4f * static_cast<float>(std::max(1, g.legend_rows.back() + 1));
  if (plot.kind == PlotKind::lines) top += fs * 1.3f;  // the value axis title above the axis
  float left = min.x + kPad;
  if (plot.kind == PlotKind::bars) {
    for (const std::string& c : plot.categories)
      g.label_w = std::max(g.label_w, text_w(font, fs, c));
    g.label_w = std::min(g.label_w, 0.4f * (max.x - min.x));
  } else {
    for (double t : g.ticks)
      g.label_w = std::max(g.label_w, text_w(font, fs, tick_text(t, g.ticks[1] - g.ticks[0])));
  }
  left += g.label_w + kPad;
  const float bottom = max.y - kPad - fs * 2.6f;  // tick labels and the axis title
  g.area_min = ImVec2(left, top);
  const float right = plot.kind == PlotKind::bars ? fs * 2.4f : fs;  // bars: their values
  g.area_max = ImVec2(std::max(left + 10, max.x - kPad - right), std::max(top + 10, bottom));
  // As many ticks as their labels have room for (a small plot gets fewer, never overlapping).
  const float width = g.area_max.x - g.area_min.x, height = g.area_max.y - g.area_min.y;
  if (plot.kind == PlotKind::bars)
    g.ticks = fitted_ticks(g.lo, g.hi, plot.integer_values, width, true, font, fs);
  else {
    g.ticks = fitted_ticks(g.lo, g.hi, plot.integer_values, height, false, font, fs);
    g.x_ticks = fitted_ticks(g.x_lo, g.x_hi, false, width, true, font, fs);
  }
  return g;
}

float value_to_px(const Geometry& g, double v, bool horizontal) {
  const double t = (v - g.lo) / (g.hi - g.lo);
  return horizontal ? g.area_min.x + static_cast<float>(t) * (g.area_max.x - g.area_min.x)
                    : g.area_max.y - static_cast<float>(t) * (g.area_max.y - g.area_min.y);
}

float x_to_px(const Geometry& g, double x) {
  return g.area_min.x +
         static_cast<float>((x - g.x_lo) / (g.x_hi - g.x_lo)) * (g.area_max.x - g.area_min.x);
}

// Bar k of category c: its rectangle [px].
void bar_rect(const Plot& plot, const Geometry& g, std::size_t c, std::size_t k, double v,
              ImVec2& a, ImVec2& b) {
  const float slot =
      (g.area_max.y - g.area_min.y) / std::max<std::size_t>(1, plot.categories.size());
  const float bar = slot * 0.8f / std::max<std::size_t>(1, plot.series.size());
  const float y = g.area_min.y + slot * c + slot * 0.1f + bar * k;
  const float x0 = value_to_px(g, std::max(g.lo, 0.0), true), x1 = value_to_px(g, v, true);
  a = ImVec2(std::min(x0, x1), y);
  b = ImVec2(std::max(x0, x1), y + bar * 0.92f);
}

void draw_legend(PlotCanvas* d, const Plot& plot, const Geometry& g, ImVec2 min, ImFont* font,
                 float fs) {
  float x = min.x + kPad;
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    if (k > 0 && g.legend_rows[k] != g.legend_rows[k - 1]) x = min.x + kPad;
    const float y = g.legend_y + fs * 0.2f + fs * 1.4f * static_cast<float>(g.legend_rows[k]);
    d->AddRectFilled(ImVec2(x, y + fs * 0.15f), ImVec2(x + fs * 0.8f, y + fs * 0.85f),
                     series_color(k));
    x += fs * 1.1f;
    d->AddText(font, fs, ImVec2(x, y), kText, plot.series[k].label.c_str());
    x += text_w(font, fs, plot.series[k].label) + fs * 1.2f;
  }
}

// Every tick label of the plot with where it goes: the value axis (x for bars, y for lines) and,
// for lines, the x axis; what draw_bars and draw_lines write, and what a test checks.
std::vector<TickLabel> labels_of(const Plot& plot, const Geometry& g, ImFont* font, float fs) {
  std::vector<TickLabel> out;
  const auto add = [&](const std::string& text, ImVec2 at) {
    out.push_back({text, at, ImVec2(at.x + text_w(font, fs, text), at.y + fs)});
  };
  const double step = g.ticks.size() > 1 ? g.ticks[1] - g.ticks[0] : 1.0;
  for (double t : g.ticks) {
    const std::string s = tick_text(t, step);
    if (plot.kind == PlotKind::bars) {
      const float x = value_to_px(g, t, true);
      add(s, ImVec2(x - text_w(font, fs, s) * 0.5f, g.area_max.y + 3));
    } else if (t >= g.lo - 1e-9 && t <= g.hi + 1e-9) {
      const float y = value_to_px(g, t, false);
      add(s, ImVec2(g.area_min.x - kPad - text_w(font, fs, s), y - fs * 0.5f));
    }
  }
  if (plot.kind != PlotKind::lines) return out;
  const double xstep = g.x_ticks.size() > 1 ? g.x_ticks[1] - g.x_ticks[0] : 1.0;
  for (double t : g.x_ticks) {
    if (t < g.x_lo - 1e-9 || t > g.x_hi + 1e-9) continue;
    const std::string s = tick_text(t, xstep);
    add(s, ImVec2(x_to_px(g, t) - text_w(font, fs, s) * 0.5f, g.area_max.y + 3));
  }
  return out;
}

void draw_tick_labels(PlotCanvas* d, const Plot& plot, const Geometry& g, ImFont* font, float fs) {
  for (const TickLabel& l : labels_of(plot, g, font, fs))
    d->AddText(font, fs, l.min, kText, l.text.c_str());
}

void draw_bars(PlotCanvas* d, const Plot& plot, const Geometry& g, ImFont* font, float fs) {
  for (double t : g.ticks) {
    const float x = value_to_px(g, t, true);
    d->AddLine(ImVec2(x, g.area_min.y), ImVec2(x, g.area_max.y), kGrid);
  }
  draw_tick_labels(d, plot, g, font, fs);
  const float slot =
      (g.area_max.y - g.area_min.y) / std::max<std::size_t>(1, plot.categories.size());
  for (std::size_t c = 0; c < plot.categories.size(); ++c) {
    const std::string label = fit(font, fs, plot.categories[c], g.label_w);
    const float y = g.area_min.y + slot * (c + 0.5f) - fs * 0.5f;
    d->AddText(font, fs, ImVec2(g.area_min.x - kPad - text_w(font, fs, label), y), kText,
               label.c_str());
    for (std::size_t k = 0; k < plot.series.size(); ++k) {
      if (c >= plot.series[k].y.size()) continue;
      if (!std::isfinite(plot.series[k].y[c])) {  // undefined (e.g. a rate of nothing): say so
        d->AddText(font, fs * 0.85f, ImVec2(g.area_min.x + 3, y), kText, "n/a");
        continue;
      }
      ImVec2 a, b;
      bar_rect(plot, g, c, k, plot.series[k].y[c], a, b);
      d->AddRectFilled(a, b, series_color(k));
      const std::string v = value_text(plot.series[k].y[c]);
      if (b.y - a.y >= fs * 0.8f)
        d->AddText(font, fs * 0.85f, ImVec2(b.x + 3, 0.5f * (a.y + b.y) - fs * 0.42f), kText,
                   v.c_str());
    }
  }
  d->AddLine(ImVec2(g.area_min.x, g.area_min.y), ImVec2(g.area_min.x, g.area_max.y), kAxis);
  d->AddLine(ImVec2(g.area_min.x, g.area_max.y), g.area_max, kAxis);
  const std::string title = axis_title(plot.value_label, plot.value_unit);
  d->AddText(font, fs,
             ImVec2(0.5f * (g.area_min.x + g.area_max.x) - text_w(font, fs, title) * 0.5f,
                    g.area_max.y + fs * 1.35f),
             kText, title.c_str());
}

void draw_lines(PlotCanvas* d, const Plot& plot, const Geometry& g, ImFont* font, float fs) {
  for (double t : g.ticks) {
    if (t < g.lo - 1e-9 || t > g.hi + 1e-9) continue;
    const float y = value_to_px(g, t, false);
    d->AddLine(ImVec2(g.area_min.x, y), ImVec2(g.area_max.x, y), kGrid);
  }
  for (double t : g.x_ticks) {
    if (t < g.x_lo - 1e-9 || t > g.x_hi + 1e-9) continue;
    const float x = x_to_px(g, t);
    d->AddLine(ImVec2(x, g.area_min.y), ImVec2(x, g.area_max.y), kGrid);
  }
  draw_tick_labels(d, plot, g, font, fs);
  d->PushClipRect(ImVec2(g.area_min.x - 5, g.area_min.y - 5),
                  ImVec2(g.area_max.x + 5, g.area_max.y + 5), true);
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& s = plot.series[k];
    std::vector<ImVec2> pts;
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      if (std::isfinite(s.y[i]))
        pts.emplace_back(x_to_px(g, s.x[i]), value_to_px(g, s.y[i], false));
    if (pts.size() > 1)
      d->AddPolyline(pts.data(), static_cast<int>(pts.size()), series_color(k), 0, 2.0f);
    for (const ImVec2& p : pts) d->AddCircleFilled(p, 3.5f, series_color(k));
  }
  d->PopClipRect();
  d->AddLine(ImVec2(g.area_min.x, g.area_min.y), ImVec2(g.area_min.x, g.area_max.y), kAxis);
  d->AddLine(ImVec2(g.area_min.x, g.area_max.y), g.area_max, kAxis);
  const std::string yt = axis_title(plot.value_label, plot.value_unit);
  d->AddText(font, fs, ImVec2(g.area_min.x - g.label_w - kPad, g.area_min.y - fs * 1.35f), kText,
             yt.c_str());
  const std::string xt = axis_title(plot.x_label, plot.x_unit);
  d->AddText(font, fs,
             ImVec2(0.5f * (g.area_min.x + g.area_max.x) - text_w(font, fs, xt) * 0.5f,
                    g.area_max.y + fs * 1.35f),
             kText, xt.c_str());
}

}  // namespace

std::string axis_title(const std::string& label, const std::string& unit) {
  return unit.empty() ? label : label + " [" + unit + "]";
}

std::vector<double> nice_ticks(double lo, double hi, int count, bool integer) {
  if (!(hi > lo)) hi = lo + 1;
  const double raw = (hi - lo) / std::max(1, count);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / p;
  double step = (f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 5.0 ? 5.0 : 10.0) * p;
  if (integer) step = std::max(step, 1.0);
  std::vector<double> ticks;
  for (double t = std::floor(lo / step + 1e-9) * step; t <= hi + step * (1 - 1e-9); t += step) {
    ticks.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
    if (t >= hi - step * 1e-9) break;
  }
  if (ticks.size() < 2) ticks.push_back(ticks.back() + step);
  return ticks;
}

void draw_plot(ImDrawList* list, ImVec2 min, ImVec2 max, const Plot& plot, float fs) {
  DrawListCanvas canvas(list);
  draw_plot(&canvas, min, max, plot, fs);
}

void draw_plot(PlotCanvas* d, ImVec2 min, ImVec2 max, const Plot& plot, float fs) {
  ImFont* font = ImGui::GetFont();
  d->PushClipRect(min, max, true);
  d->AddRectFilled(min, max, kBackground);
  if (!plot.title.empty())
    d->AddText(font, fs * 1.1f, ImVec2(min.x + kPad, min.y + kPad * 0.5f), kText,
               plot.title.c_str());
  if (plot.kind == PlotKind::map) {
    draw_map(d, min, max, plot, font, fs);
    d->PopClipRect();
    return;
  }
  const Geometry g = layout(plot, min, max, font, fs);
  draw_legend(d, plot, g, min, font, fs);
  if (plot.kind == PlotKind::bars)
    draw_bars(d, plot, g, font, fs);
  else
    draw_lines(d, plot, g, font, fs);
  d->PopClipRect();
}

void plot_widget(const char* id, const Plot& plot, ImVec2 size) {
  if (size.x <= 0) size.x = ImGui::GetContentRegionAvail().x;
  ImGui::PushID(id);
  const ImVec2 min = ImGui::GetCursorScreenPos(), max(min.x + size.x, min.y + size.y);
  const float fs = ImGui::GetFontSize();
  draw_plot(ImGui::GetWindowDrawList(), min, max, plot, fs);
  ImGui::Dummy(size);
  if (ImGui::IsItemHovered() && plot.kind == PlotKind::map) {
    if (const auto tip = map_hover(plot, min, max, ImGui::GetFont(), fs, ImGui::GetIO().MousePos))
      ImGui::SetTooltip("%s", tip->c_str());
  } else if (ImGui::IsItemHovered()) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const Geometry g = layout(plot, min, max, ImGui::GetFont(), fs);
    const std::string unit = plot.value_unit.empty() ? "" : " " + plot.value_unit;
    for (std::size_t k = 0; k < plot.series.size(); ++k) {
      const PlotSeries& s = plot.series[k];
      for (std::size_t i = 0; i < s.y.size(); ++i) {
        bool hit = false;
        std::string where;
        if (plot.kind == PlotKind::bars && i < plot.categories.size()) {
          ImVec2 a, b;
          bar_rect(plot, g, i, k, s.y[i], a, b);
          hit = m.y >= a.y && m.y <= b.y && m.x >= g.area_min.x && m.x <= std::max(b.x, a.x + 6);
          where = plot.categories[i];
        } else if (plot.kind == PlotKind::lines && i < s.x.size()) {
          const float dx = m.x - x_to_px(g, s.x[i]), dy = m.y - value_to_px(g, s.y[i], false);
          hit = dx * dx + dy * dy < 64;
          where = axis_title(plot.x_label, "") + " " + value_text(s.x[i]) +
                  (plot.x_unit.empty() ? "" : " " + plot.x_unit);
        }
        if (hit)
          ImGui::SetTooltip("%s\n%s: %s%s", where.c_str(), s.label.c_str(),
                            value_text(s.y[i]).c_str(), unit.c_str());
      }
    }
  }
  ImGui::PopID();
}

std::vector<TickLabel> tick_labels(const Plot& plot, ImVec2 min, ImVec2 max, float fs) {
  if (plot.kind == PlotKind::map) return {};
  ImFont* font = ImGui::GetFont();
  return labels_of(plot, layout(plot, min, max, font, fs), font, fs);
}

std::string plot_csv(const Plot& plot) {
  const auto quoted = [](const std::string& s) {
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  if (plot.kind == PlotKind::map) return map_csv(plot);
  std::string out;
  if (plot.kind == PlotKind::bars) {
    out = quoted("category");
    for (const PlotSeries& s : plot.series)
      out += "," + quoted(axis_title(s.label, plot.value_unit));
    out += "\n";
    for (std::size_t c = 0; c < plot.categories.size(); ++c) {
      out += quoted(plot.categories[c]);
      for (const PlotSeries& s : plot.series)
        out += "," +
               (c < s.y.size() && std::isfinite(s.y[c]) ? value_text(s.y[c], 10) : std::string());
      out += "\n";
    }
    return out;
  }
  out = quoted(axis_title(plot.x_label, plot.x_unit)) + ",\"series\"," +
        quoted(axis_title(plot.value_label, plot.value_unit)) + "\n";
  for (const PlotSeries& s : plot.series)
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      out += value_text(s.x[i], 10) + "," + quoted(s.label) + "," + value_text(s.y[i], 10) + "\n";
  return out;
}

}  // namespace pagor::studio
