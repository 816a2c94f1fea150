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
  const std::string& base;  ///< the export path (the pair view's, or the benchmark view's)
  StudioActions& actions;   ///< renders PNGs, copies, says where files went
};

/// Writes `text` to `<base>-<name>` (atomically; made absolute) and says where.
void write_export(const Exports& to, const std::string& name, const std::string& text);

/// A transform as four lines of four numbers (row-major), each exact to the double.
std::string pose_matrix_text(const Transform& T);
/// {"T_target_source": [[...] x4], "level": L, "refined": bool} as JSON, with "adopted_from" when
/// `adopted` names the verdict's alternative the pose is (acceptance.adopted) instead of L's.
std::string pose_json(const Transform& T, int level, bool refined, const std::string& adopted = "");
/// One line per level: epsilon, vertices, edges, clique size, D, errors and success (empty
/// without ground truth), translation and yaw; a header line first.
std::string levels_csv(const Snapshot& s);
/// One line per level of the diagnosis: true vertices, consistent, clique (true), precision and
/// recall (empty when undefined), errors, D, GNC inliers (true).
std::string diagnosis_csv(const Diagnosis& d);

/// An export button of a run's result: disabled, with a tooltip saying why, while the result is
/// stale (`stale_reason` not empty: a pair or parameter change whose run has not finished), so
/// that nothing exports an earlier pair's pose or an earlier run's figures as current. True when
/// clicked.
bool result_button(const char* label, const char* tip, const std::string& stale_reason);

/// Buttons: copy the selected pose (4x4, JSON), copy the result JSON, write the result JSON and
/// the levels table (CSV); each disabled while the result is stale.
void result_exports(const Snapshot& s, const std::string& stale_reason, const Exports& to);

}  // namespace pagor::studio
