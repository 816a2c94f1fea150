#pragma once
/// \file widget_record.hpp
/// Inside the widgets: records the item ImGui just drew in the registry (widgets.hpp).

#include <imgui.h>

#include "widgets/widgets.hpp"

namespace pagor::studio::ui {

/// Records the last item as a widget of `kind` with its label and ID; `frame_w` is its frame's
/// width without the label [px] (-1: the item's width).
WidgetRecord& record_last(WidgetKind kind, const char* label, ImGuiID id, float frame_w = -1);

}  // namespace pagor::studio::ui
