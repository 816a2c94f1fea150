#include "widgets/plot_map.hpp"

#include <vector>

namespace pagor::studio::plot_detail {
namespace {

constexpr float kPickPx = 8.0f;     // hover radius [px]
constexpr float kDotPx = 3.5f;      // marker radius [px]
constexpr float kCrossPx = 4.5f;    // half a cross [px]
constexpr int kColorBarSteps = 48;  // gradient slices
constexpr ImU32 kBackdrop = IM_COL32(150, 150, 162, 255);

// Where everything of a map goes, shared by drawing and hovering.
struct MapGeometry {
  ImVec2 area_min, area_max;  // the data area [px]
  double x_lo = 0, y_lo = 0;  // data at the area's lower-left corner
  double scale = 1;           // [px per data unit], the same on both axes
  float legend_y = 0, bar_x = 0;
  std::vector<double> x_ticks, y_ticks;
  ImVec2 px(double x, double y) const {
    return ImVec2(area_min.x + static_cast<float>((x - x_lo) * scale),
                  area_max.y - static_cast<float>((y - y_lo) * scale));
  }
};

struct Bounds {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
};

Bounds data_bounds(const Plot& plot) {
  Bounds b;
  for (const PlotSeries& s : plot.series)
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) b.add(s.x[i], s.y[i]);
  for (const auto& line : plot.backdrop.lines)
    for (const auto& p : line) b.add(p[0], p[1]);
  for (const PlotCircle& c : plot.backdrop.circles) {
    b.add(c.x - c.radius, c.y - c.radius);
    b.add(c.x + c.radius, c.y + c.radius);
  }
  if (b.x0 > b.x1) b = Bounds{0, 0, 1, 1};
  const double pad = 0.03 * std::max({b.x1 - b.x0, b.y1 - b.y0, 1e-6});
  return Bounds{b.x0 - pad, b.y0 - pad, b.x1 + pad, b.y1 + pad};
}

float legend_entry_w(const PlotSeries& s, ImFont* font, float fs) {
  return fs * 1.5f + text_w(font, fs, s.label) + fs * 1.2f;
}

int legend_rows(const Plot& plot, float x0, float x1, ImFont* font, float fs) {
  int row = 0;
  float x = x0;
  for (const PlotSeries& s : plot.series) {
    const float w = legend_entry_w(s, font, fs);
    if (x > x0 && x + w > x1) ++row, x = x0;
    x += w;
  }
  return row + 1;
}

MapGeometry map_layout(const Plot& plot, ImVec2 min, ImVec2 max, ImFont* font, float fs) {
  MapGeometry g;
  const Bounds b = data_bounds(plot);
  g.y_ticks = nice_ticks(b.y0, b.y1);
  float top = min.y + kPad + (plot.title.empty() ? 0 : fs * 1.3f);
  g.legend_y = top;
  top += fs * 1.4f * static_cast<float>(legend_rows(plot, min.x + kPad, max.x - kPad, font, fs));
  top += fs * 1.3f;  // the y axis title above the axis
  float label_w = 0;
  const double ystep = g.y_ticks.size() > 1 ? g.y_ticks[1] - g.y_ticks[0] : 1.0;
  for (double t : g.y_ticks) label_w = std::max(label_w, text_w(font, fs, tick_text(t, ystep)));
  const float left = min.x + kPad + label_w + kPad;
  const float right = max.x - kPad - (plot.color_bar ? fs * 5.0f : fs);
  const float bottom = max.y - kPad - fs * 2.6f;
  const float w = std::max(10.0f, right - left), h = std::max(10.0f, bottom - top);
  g.scale = std::min(w / (b.x1 - b.x0), h / (b.y1 - b.y0));
  // Equal aspect: the data centred in the area, the spare room on one axis.
  g.x_lo = 0.5 * (b.x0 + b.x1) - 0.5 * w / g.scale;
  g.y_lo = 0.5 * (b.y0 + b.y1) - 0.5 * h / g.scale;
  g.area_min = ImVec2(left, top);
  g.area_max = ImVec2(left + w, top + h);
  // About one tick per five text heights across, per three up.
  g.x_ticks = nice_ticks(g.x_lo, g.x_lo + w / g.scale, std::max(2, static_cast<int>(w / (fs * 5))));
  g.y_ticks = nice_ticks(g.y_lo, g.y_lo + h / g.scale, std::max(2, static_cast<int>(h / (fs * 3))));
  g.bar_x = g.area_max.x + kPad * 1.5f;
  return g;
}

ImU32 point_color(const Plot& plot, const PlotSeries& s, std::size_t k, std::size_t i) {
  if (i < s.color_values.size() && plot.color_bar) {
    const PlotColorBar& c = *plot.color_bar;
    return viridis(c.hi > c.lo ? (s.color_values[i] - c.lo) / (c.hi - c.lo) : 0.5);
  }
  return s.color ? *s.color : series_color(k);
}

void marker(PlotCanvas* d, ImVec2 p, PlotMarker m, ImU32 c) {
  if (m == PlotMarker::cross) {
    d->AddLine(ImVec2(p.x - kCrossPx, p.y - kCrossPx), ImVec2(p.x + kCrossPx, p.y + kCrossPx), c,
               2.0f);
    d->AddLine(ImVec2(p.x - kCrossPx, p.y + kCrossPx), ImVec2(p.x + kCrossPx, p.y - kCrossPx), c,
               2.0f);
  } else {
    d->AddCircleFilled(p, kDotPx, c);
  }
}

void draw_map_legend(PlotCanvas* d, const Plot& plot, const MapGeometry& g, ImVec2 min, ImVec2 max,
                     ImFont* font, float fs) {
  float x = min.x + kPad, y = g.legend_y + fs * 0.2f;
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& s = plot.series[k];
    const float w = legend_entry_w(s, font, fs);
    if (x > min.x + kPad && x + w > max.x - kPad) x = min.x + kPad, y += fs * 1.4f;
    const ImVec2 c(x + fs * 0.6f, y + fs * 0.5f);
    if (s.line_only) {
      d->AddLine(ImVec2(x, c.y), ImVec2(x + fs * 1.2f, c.y), point_color(plot, s, k, 0), 1.5f);
    } else if (plot.color_bar && !s.color) {  // coloured on the scale: its ends side by side
      marker(d, ImVec2(c.x - fs * 0.3f, c.y), s.marker, viridis(0.0));
      marker(d, ImVec2(c.x + fs * 0.3f, c.y), s.marker, viridis(1.0));
    } else {
      marker(d, c, s.marker, point_color(plot, s, k, 0));
    }
    d->AddText(font, fs, ImVec2(x + fs * 1.5f, y), kText, s.label.c_str());
    x += w;
  }
}

void draw_axes(PlotCanvas* d, const Plot& plot, const MapGeometry& g, ImFont* font, float fs) {
  const double xs = g.x_ticks.size() > 1 ? g.x_ticks[1] - g.x_ticks[0] : 1.0;
  const double ys = g.y_ticks.size() > 1 ? g.y_ticks[1] - g.y_ticks[0] : 1.0;
  for (double t : g.x_ticks) {
    const float x = g.px(t, 0).x;
    if (x < g.area_min.x - 0.5f || x > g.area_max.x + 0.5f) continue;
    d->AddLine(ImVec2(x, g.area_min.y), ImVec2(x, g.area_max.y), kGrid);
    const std::string s = tick_text(t, xs);
    d->AddText(font, fs, ImVec2(x - text_w(font, fs, s) * 0.5f, g.area_max.y + 3), kText,
               s.c_str());
  }
  for (double t : g.y_ticks) {
    const float y = g.px(0, t).y;
    if (y < g.area_min.y - 0.5f || y > g.area_max.y + 0.5f) continue;
    d->AddLine(ImVec2(g.area_min.x, y), ImVec2(g.area_max.x, y), kGrid);
    const std::string s = tick_text(t, ys);
    d->AddText(font, fs, ImVec2(g.area_min.x - kPad - text_w(font, fs, s), y - fs * 0.5f), kText,
               s.c_str());
  }
  d->AddRect(g.area_min, g.area_max, kAxis);
  const std::string yt = axis_title(plot.value_label, plot.value_unit);
  d->AddText(font, fs, ImVec2(g.area_min.x - kPad, g.area_min.y - fs * 1.35f), kText, yt.c_str());
  const std::string xt = axis_title(plot.x_label, plot.x_unit);
  d->AddText(font, fs,
             ImVec2(0.5f * (g.area_min.x + g.area_max.x) - text_w(font, fs, xt) * 0.5f,
                    g.area_max.y + fs * 1.35f),
             kText, xt.c_str());
}

void draw_color_bar(PlotCanvas* d, const PlotColorBar& c, const MapGeometry& g, ImVec2 max,
                    ImFont* font, float fs) {
  const float x0 = g.bar_x, x1 = x0 + fs * 0.8f, top = g.area_min.y, bottom = g.area_max.y;
  const float step = (bottom - top) / kColorBarSteps;
  for (int i = 0; i < kColorBarSteps; ++i)  // top: the high end
    d->AddRectFilled(ImVec2(x0, top + step * i), ImVec2(x1, top + step * (i + 1) + 0.5f),
                     viridis(1.0 - (i + 0.5) / kColorBarSteps));
  d->AddRect(ImVec2(x0, top), ImVec2(x1, bottom), kAxis);
  const std::vector<double> ticks = nice_ticks(c.lo, c.hi, 4, true);
  const double ts = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
  for (double t : ticks) {
    if (t < c.lo - 1e-9 || t > c.hi + 1e-9) continue;
    const double f = c.hi > c.lo ? (t - c.lo) / (c.hi - c.lo) : 0.5;
    const float y = bottom - static_cast<float>(f) * (bottom - top);
    d->AddLine(ImVec2(x1, y), ImVec2(x1 + 3, y), kAxis);
    d->AddText(font, fs, ImVec2(x1 + 5, y - fs * 0.5f), kText, tick_text(t, ts).c_str());
  }
  const std::string title = axis_title(c.label, c.unit);
  d->AddText(font, fs, ImVec2(max.x - kPad - text_w(font, fs, title), top - fs * 1.35f), kText,
             title.c_str());
}

}  // namespace

ImU32 viridis(double t) {
  static const float stops[][3] = {
      {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(t));
  const float f = static_cast<float>(t - i);
  const auto mix = [&](int c) {
    return static_cast<int>(stops[i][c] + f * (stops[i + 1][c] - stops[i][c]) + 0.5f);
  };
  return IM_COL32(mix(0), mix(1), mix(2), 255);
}

void draw_map(PlotCanvas* d, ImVec2 min, ImVec2 max, const Plot& plot, ImFont* font, float fs) {
  const MapGeometry g = map_layout(plot, min, max, font, fs);
  draw_map_legend(d, plot, g, min, max, font, fs);
  draw_axes(d, plot, g, font, fs);
  d->PushClipRect(g.area_min, g.area_max, true);
  for (const auto& line : plot.backdrop.lines) {
    std::vector<ImVec2> pts;
    for (const auto& p : line) pts.push_back(g.px(p[0], p[1]));
    if (pts.size() > 1)
      d->AddPolyline(pts.data(), static_cast<int>(pts.size()), kBackdrop, 0, 1.5f);
  }
  for (const PlotCircle& c : plot.backdrop.circles)
    d->AddCircle(g.px(c.x, c.y), std::max(2.0f, static_cast<float>(c.radius * g.scale)), kBackdrop,
                 0, 1.5f);
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& s = plot.series[k];
    const std::size_t n = std::min(s.x.size(), s.y.size());
    if (s.line_only) {
      std::vector<ImVec2> pts;
      for (std::size_t i = 0; i < n; ++i) pts.push_back(g.px(s.x[i], s.y[i]));
      if (pts.size() > 1)
        d->AddPolyline(pts.data(), static_cast<int>(pts.size()), point_color(plot, s, k, 0), 0,
                       1.5f);
      continue;
    }
    for (std::size_t i = 0; i < n; ++i)
      marker(d, g.px(s.x[i], s.y[i]), s.marker, point_color(plot, s, k, i));
  }
  d->PopClipRect();
  if (plot.color_bar) draw_color_bar(d, *plot.color_bar, g, max, font, fs);
}

std::optional<std::string> map_hover(const Plot& plot, ImVec2 min, ImVec2 max, ImFont* font,
                                     float fs, ImVec2 mouse) {
  const MapGeometry g = map_layout(plot, min, max, font, fs);
  float best = kPickPx;
  std::optional<std::string> tip;
  for (const PlotSeries& s : plot.series) {
    if (s.line_only) continue;
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      const ImVec2 p = g.px(s.x[i], s.y[i]);
      const float dist = std::hypot(p.x - mouse.x, p.y - mouse.y);
      if (dist >= best) continue;
      best = dist;
      tip = i < s.tips.size() ? s.tips[i]
                              : s.label + ": (" + value_text(s.x[i]) + ", " + value_text(s.y[i]) +
                                    ") " + plot.x_unit;
    }
  }
  return tip;
}

std::string map_csv(const Plot& plot) {
  const auto quoted = [](const std::string& s) {
    std::string q = "\"";
    for (char c : s)
      q += c == '"' ? std::string("\"\"") : c == '\n' ? std::string("; ") : std::string(1, c);
    return q + "\"";
  };
  const std::string bar =
      plot.color_bar ? axis_title(plot.color_bar->label, plot.color_bar->unit) : "colour value";
  std::string out = "\"series\"," + quoted(axis_title(plot.x_label, plot.x_unit)) + "," +
                    quoted(axis_title(plot.value_label, plot.value_unit)) + "," + quoted(bar) +
                    ",\"tip\"\n";
  for (const PlotSeries& s : plot.series)
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      out += quoted(s.label) + "," + value_text(s.x[i], 10) + "," + value_text(s.y[i], 10) + "," +
             (i < s.color_values.size() ? value_text(s.color_values[i], 10) : std::string()) + "," +
             (i < s.tips.size() ? quoted(s.tips[i]) : std::string()) + "\n";
  return out;
}

}  // namespace pagor::studio::plot_detail
