#pragma once
/// \file plot_map.hpp
/// Inside the plot widget (plot.hpp): its shared style (palette, padding, tick labels) and the
/// `map` kind — points in the plane at equal aspect over a backdrop, with a colour bar.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "widgets/plot.hpp"
#include "widgets/plot_canvas.hpp"

namespace pagor::studio::plot_detail {

constexpr float kPad = 8.0f;  ///< [px]
// Distinguishable under the common colour-vision deficiencies (Okabe-Ito).
inline constexpr ImU32 kSeriesColors[] = {IM_COL32(86, 180, 233, 255), IM_COL32(230, 159, 0, 255),
                                          IM_COL32(0, 158, 115, 255),  IM_COL32(204, 121, 167, 255),
                                          IM_COL32(240, 228, 66, 255), IM_COL32(213, 94, 0, 255)};
constexpr ImU32 kBackground = IM_COL32(24, 24, 28, 255), kGrid = IM_COL32(70, 70, 78, 255),
                kAxis = IM_COL32(170, 170, 180, 255), kText = IM_COL32(225, 225, 230, 255);

inline ImU32 series_color(std::size_t i) {
  return kSeriesColors[i % std::size(kSeriesColors)];
}

/// A tick's label with as many decimals as the step needs.
inline std::string tick_text(double v, double step) {
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

inline std::string value_text(double v, int digits = 3) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
  return buf;
}

inline float text_w(ImFont* font, float size, const std::string& s) {
  return font->CalcTextSizeA(size, 1e9f, 0.0f, s.c_str()).x;
}

/// Viridis at t in [0, 1] (clamped).
ImU32 viridis(double t);

/// Draws a map plot below its title (legend, backdrop, points, axes, colour bar) in [min, max].
void draw_map(PlotCanvas* d, ImVec2 min, ImVec2 max, const Plot& plot, ImFont* font, float fs);

/// The tip of the map point nearest `mouse` within a few pixels (nullopt: none).
std::optional<std::string> map_hover(const Plot& plot, ImVec2 min, ImVec2 max, ImFont* font,
                                     float fs, ImVec2 mouse);

/// The map's points as CSV: `series,x,y,colour value,tip`.
std::string map_csv(const Plot& plot);

}  // namespace pagor::studio::plot_detail
