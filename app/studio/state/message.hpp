#pragma once
/// \file message.hpp
/// A message for the user: what the studio says after an action (a file written, a file it
/// could not read). Everything the user is told goes through one channel, StudioActions::notify
/// (panels/studio_actions.hpp), and the status bar shows the last message.

#include <string>
#include <utility>

namespace pagor::studio {

/// How a message is shown: plain, amber or red.
enum class MessageLevel { info, warning, error };

struct Message {
  MessageLevel level = MessageLevel::info;
  std::string text;    ///< one line for the status bar (empty: nothing to say)
  std::string detail;  ///< more, shown when the line is hovered (may be empty)

  /// Something done ("wrote x.png").
  static Message info(std::string text, std::string detail = {}) {
    return {MessageLevel::info, std::move(text), std::move(detail)};
  }
  /// Something the user should look at, though nothing failed.
  static Message warning(std::string text, std::string detail = {}) {
    return {MessageLevel::warning, std::move(text), std::move(detail)};
  }
  /// Something that failed; the studio keeps running.
  static Message error(std::string text, std::string detail = {}) {
    return {MessageLevel::error, std::move(text), std::move(detail)};
  }
};

}  // namespace pagor::studio
