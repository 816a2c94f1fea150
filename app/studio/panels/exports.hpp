#pragma once
/// \file exports.hpp
/// What the user takes out of the studio: the selected pose as a 4x4 matrix or JSON on the
/// clipboard, the result in the CLI's schema (pagor.register/1), tables as CSV; files go to
/// `<base>-<name>` (the export path of the Session panel).

#include <string>

#include "panels/studio_actions.hpp"
#include "runners/worker.hpp"

namespace pagor::studio {

/// Where exports go: `<base>-<name>`, and who tells the user.
struct Exports {
  const std::string& base;  ///< the export path (state.bench.plot_path)
  StudioActions& actions;   ///< renders PNGs, copies, says where files went
};

/// Writes `text` to `<base>-<name>` (atomically; made absolute) and says where.
void write_export(const Exports& to, const std::string& name, const std::string& text);

/// A transform as four lines of four numbers (row-major), each exact to the double.
std::string pose_matrix_text(const Transform& T);
/// {"T_target_source": [[...] x4], "level": L, "refined": bool} as JSON.
std::string pose_json(const Transform& T, int level, bool refined);
/// One line per level: epsilon, vertices, edges, clique size, D, errors and success (empty
/// without ground truth), translation and yaw; a header line first.
std::string levels_csv(const Snapshot& s);
/// One line per level of the diagnosis: true vertices, consistent, clique (true), precision and
/// recall (empty when undefined), errors, D, GNC inliers (true).
std::string diagnosis_csv(const Diagnosis& d);

/// Buttons: copy the selected pose (4x4, JSON), copy the result JSON, write the result JSON and
/// the levels table (CSV).
void result_exports(const Snapshot& s, const Exports& to);

}  // namespace pagor::studio
