#pragma once
/// \file diagnosis_overlay.hpp
/// The 3D view's diagnosis items (ViewState::diagnosis): correspondences filtered by class and
/// by truth and coloured by ground-truth residual, the shown level's graph edges around a hovered
/// correspondence, and the legend of the residual and D-contribution colour scales. The numbers
/// come from the worker's snapshot (Snapshot::diagnosis, contributions); nothing is computed here
/// beyond screen positions.

#include <imgui.h>

#include "scene/scene_overlay.hpp"

namespace pagor::studio {

/// Colour scale from green (0) through yellow (0.5) to red (1); t is clamped to [0, 1].
Rgba diagnosis_colormap(float t);

/// Upper end of the residual colour scale [m]: twice the diagnosis tolerance (yellow = tolerance).
double residual_scale(const Snapshot& s);

/// Whether correspondence i passes the view's class and truth filters (the truth filter needs a
/// diagnosis; without one it keeps everything).
bool diagnosis_keeps(const Snapshot& s, const DiagnosisView& view, std::size_t i);

/// Line colour of correspondence i by its ground-truth residual, or `fallback` when residual
/// colouring is off or there is no diagnosis.
ImU32 diagnosis_line_color(const Snapshot& s, const DiagnosisView& view, std::size_t i,
                           ImU32 fallback, int alpha = 255);

/// The edges of correspondence `index` in level `level`'s graph: each neighbour's line, cyan, and
/// a thin link between the two lines' midpoints. Returns how many edges were drawn, and through
/// `true_neighbours` how many of those neighbours are true (-1 without a diagnosis).
int draw_hover_edges(ImDrawList* dl, const ViewRect& r, const Snapshot& s, const Transform& pose,
                     int level, int index, int& true_neighbours);

/// Legend of the residual colours and of the D contributions (each when shown), at `at`.
void draw_diagnosis_legend(ImDrawList* dl, ImVec2 at, const Snapshot& s, const ViewState& view,
                           int level);

/// Height the diagnosis legend needs [px] (0 when nothing of it is shown).
float diagnosis_legend_height(const Snapshot& s, const ViewState& view);

}  // namespace pagor::studio
