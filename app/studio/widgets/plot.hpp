#pragma once
/// \file plot.hpp
/// The studio's plots, drawn with ImGui's draw lists (ImPlot is not packaged in Debian 12):
/// horizontal bar charts over named categories and line charts over a numeric x, each with
/// labelled axes carrying units, ticks at round numbers, and a legend. The same drawing goes to
/// the screen, to a PNG (plot_export.hpp) and, as numbers, to CSV.

#include <imgui.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace pagor::studio {

class PlotCanvas;

enum class PlotKind {
  bars,   ///< one horizontal bar per category and series; values along x
  lines,  ///< y over a numeric x, one polyline with markers per series
  map     ///< points in the plane (x, y in the same unit, equal aspect) over a backdrop
};

enum class PlotMarker { dot, cross };

struct PlotSeries {
  std::string label;          ///< legend entry
  std::vector<double> x;      ///< lines: abscissae (ignored for bars)
  std::vector<double> y;      ///< bars: one value per category; lines: one per x
  bool markers_only = false;  ///< lines: points without the connecting line
  // map only:
  bool line_only = false;               ///< a thin line through the points, no markers
  PlotMarker marker = PlotMarker::dot;  ///< how each point is drawn
  std::optional<ImU32> color{};         ///< a fixed colour instead of the palette's
  std::vector<double> color_values{};   ///< per point: coloured on the colour bar's scale
  std::vector<std::string> tips{};      ///< per point: the hover text
};

/// A circle of a map's backdrop, in data units.
struct PlotCircle {
  double x = 0, y = 0, radius = 0;
};

/// Geometry a map is drawn over (e.g. a floor plan), in data units.
struct PlotBackdrop {
  std::vector<std::vector<std::array<double, 2>>> lines;  ///< polylines
  std::vector<PlotCircle> circles;
  bool empty() const { return lines.empty() && circles.empty(); }
};

/// The scale of a map's `color_values`: viridis from `lo` (dark) to `hi` (yellow).
struct PlotColorBar {
  std::string label, unit;
  double lo = 0, hi = 1;
};

struct Plot {
  std::string title;
  PlotKind kind = PlotKind::bars;
  std::string value_label, value_unit;  ///< the values' axis: x for bars, y for lines
  std::string x_label, x_unit;          ///< lines: the abscissa
  std::vector<std::string> categories;  ///< bars: one per group (top to bottom)
  std::vector<PlotSeries> series;
  std::optional<double> value_min, value_max;  ///< fixed value range (default: from the data)
  bool integer_values = false;                 ///< counts: ticks at whole numbers only
  // map only (x: x_label/x_unit, y: value_label/value_unit):
  PlotBackdrop backdrop;
  std::optional<PlotColorBar> color_bar;
};

/// "success [%]": a label with its unit in brackets (no brackets without a unit).
std::string axis_title(const std::string& label, const std::string& unit);

/// Ticks at round numbers (1, 2 or 5 times a power of ten) covering [lo, hi]; about `count`.
/// With `integer`, the step is at least 1.
std::vector<double> nice_ticks(double lo, double hi, int count = 5, bool integer = false);

/// Draws the plot into `rect` [px] of a draw list; `font_size` is the text height [px]. The
/// background is filled, so the result is a self-contained picture.
void draw_plot(ImDrawList* draw, ImVec2 min, ImVec2 max, const Plot& plot, float font_size);
/// The same on any canvas (plot_canvas.hpp).
void draw_plot(PlotCanvas* canvas, ImVec2 min, ImVec2 max, const Plot& plot, float font_size);

/// The plot as an SVG document of width x height pixels (the same drawing as on screen, text as
/// text). Needs an ImGui frame (its font measures the text).
std::string plot_svg(const Plot& plot, int width, int height, float font_size);

/// The plot as an ImGui item of `size` (width <= 0: the available width); hovering a bar or
/// point shows its category or x, series and value in a tooltip.
void plot_widget(const char* id, const Plot& plot, ImVec2 size);

/// A tick label as drawn: its text and rectangle [px].
struct TickLabel {
  std::string text;
  ImVec2 min, max;
};
/// The tick labels a bar or line plot draws into [min, max] (both axes): as many as have room,
/// so that none overlaps another. Needs an ImGui frame (its font).
std::vector<TickLabel> tick_labels(const Plot& plot, ImVec2 min, ImVec2 max, float font_size);

/// The plot's numbers as CSV: bars `category,<series...>`, lines `x,series,y`, maps
/// `series,x,y,colour value,tip` (header included).
std::string plot_csv(const Plot& plot);

}  // namespace pagor::studio
