#pragma once
/// \file plot_export.hpp
/// Plots as pictures: rendered by the studio's own ImGui renderer through the GL table, read back
/// and written as PNG (render/png.hpp). In the studio it uses the window's (or headless)
/// context; `pagor --plot` opens an OSMesa context of its own (so `core/` stays free of GL).

#include <string>

#include "render/gl.hpp"
#include "render/imgui_renderer.hpp"
#include "widgets/plot.hpp"

namespace pagor::studio {

/// Default picture size [px].
constexpr int kPlotPngWidth = 960, kPlotPngHeight = 600;

/// Renders `plot` into the lower-left width x height pixels of the default framebuffer (which
/// must be at least that large; render/png.hpp reads them back). Needs a current GL context and
/// an ImGui frame begun (the font is the frame's).
void render_plot(const Gl& gl, ImGuiRenderer& renderer, const Plot& plot, int width, int height);

/// For the command line: opens an offscreen context and an ImGui context of its own, renders the
/// plot and writes the PNG. Throws pagor::Error (no OSMesa, unwritable file).
void export_plot_png(const Plot& plot, const std::string& path, int width = kPlotPngWidth,
                     int height = kPlotPngHeight);

}  // namespace pagor::studio
