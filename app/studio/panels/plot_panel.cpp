#include "panels/plot_panel.hpp"

#include <cstdio>
#include <filesystem>

#include "pagor/errors.hpp"
#include "pagor/eval/sweep.hpp"
#include "pagor/io/atomic_file.hpp"
#include "widgets/bench_plots.hpp"
#include "widgets/plot_export.hpp"
#include "widgets/widgets.hpp"

namespace pagor::studio {

void plot_with_exports(const Exports& to, const char* id, const Plot& plot, float width,
                       float height) {
  ImGui::BeginGroup();
  ImGui::PushID(id);
  plot_widget(id, plot, ImVec2(width, height));
  // Absolute, so that the message after an export says where the file went (made on a click,
  // not every frame).
  const auto base = [&] { return absolute_path(to.base + "-" + id); };
  if (ui::small_button("PNG", "write the plot as PNG (path below the plots)"))
    to.actions.export_plot(plot, base() + ".png");
  ImGui::SameLine();
  if (ui::small_button("SVG", "write the plot as SVG (the same drawing, text as text)"))
    write_export(to, std::string(id) + ".svg",
                 plot_svg(plot, kPlotPngWidth, kPlotPngHeight, ImGui::GetFontSize()));
  ImGui::SameLine();
  if (ui::small_button("CSV", "write the plotted numbers as CSV")) {
    const std::string path = base() + ".csv";
    try {
      write_file_atomic(path, plot_csv(plot));
      to.actions.notify(Message::info("wrote " + path));
    } catch (const Error& e) {
      to.actions.notify(Message::error(e.what()));
    }
  }
  ImGui::PopID();
  ImGui::EndGroup();
}

}  // namespace pagor::studio
