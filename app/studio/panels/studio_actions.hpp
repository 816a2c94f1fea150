#pragma once
/// \file studio_actions.hpp
/// What a panel may ask of the studio beyond editing the state it is given: runs, the parameter
/// history, files, and the one channel for messages to the user. The Studio implements it.

#include <optional>
#include <string>

#include "state/app_state.hpp"
#include "state/message.hpp"

namespace pagor::studio {

struct Plot;

class StudioActions {
 public:
  virtual ~StudioActions() = default;
  /// Opens the state's data with its configuration.
  virtual void submit_data() = 0;
  /// Re-runs with the state's configuration; does nothing while it is invalid (the UI says why).
  virtual void submit_config() = 0;
  /// One step back in the parameter history, and re-runs.
  virtual void undo() = 0;
  /// One step forward in the parameter history, and re-runs.
  virtual void redo() = 0;
  /// Saves the state to its session file; the outcome goes to notify().
  virtual void save_session_now() = 0;
  /// Loads the state's session file; the outcome goes to notify().
  virtual void load_session_now() = 0;
  /// Writes the whole window to the state's screenshot path once this frame is drawn.
  virtual void save_screenshot() = 0;
  /// Writes `plot` as PNG at `path` (rendered at the next frame); the outcome goes to notify().
  virtual void export_plot(const Plot& plot, const std::string& path) = 0;
  /// Tells the user something; the status bar shows it until the next message.
  virtual void notify(Message message) = 0;
  /// Opens a user's file as `purpose` says (state/open_file.hpp), re-runs what it changed and
  /// remembers it among the recent files; the outcome goes to notify().
  virtual void open_file(const std::string& path, FilePurpose purpose) = 0;
  /// Opens the file browser for `purpose`, in the directory of `current` (a path the user wrote).
  virtual void browse(FilePurpose purpose, const std::string& current) = 0;
  /// Shows `entry` in the pair view and runs it; `truth`, when given, is its ground truth (a
  /// results row's, for a pair without a truth file).
  virtual void open_pair(const PairEntry& entry, const std::optional<Transform>& truth) = 0;
  /// Puts `text` on the clipboard; notify() says what (`what`, e.g. "the pose as a 4x4 matrix").
  virtual void copy_text(const std::string& text, const std::string& what) = 0;
};

}  // namespace pagor::studio
