#pragma once
/// \file input_queue.hpp
/// Keyboard events as the platform reported them, fed to ImGui one logical event a frame.
///
/// ImGui 1.86 reads the keyboard as key states once a frame (io.KeysDown, io.KeyCtrl, ...), and
/// an InputText handles the frame's typed characters before its key presses. When a frame takes
/// longer than a keystroke (60-190 ms in software GL), a key pressed and released between two
/// frames would be missed, a chord's modifier released with it (Ctrl+A read as A), and a Home
/// followed by typing would type first and move after. The queue keeps every event and lets a
/// frame see at most one key press (held down for that frame, with the modifiers held at its
/// press) or one run of characters (with the presses of the keys that type them), in the order
/// they came.

#include <imgui.h>

#include <cstddef>
#include <deque>
#include <vector>

namespace pagor::studio {

class InputQueue {
 public:
  /// A key pressed (`down`) or released, by GLFW key code; repeats are not queued (ImGui repeats
  /// a held key itself).
  void key(int code, bool down);
  /// A typed character (Unicode code point).
  void character(unsigned int codepoint);

  /// Applies the next logical step to `io`: modifier changes, then one key press or a run of
  /// characters; a release waits for the frame after its press. Touches nothing when the queue
  /// is empty (a driver may set the key states itself).
  void feed(ImGuiIO& io);
  /// A key (not a modifier) the last feed pressed, with the modifiers then held.
  struct Press {
    int key;
    bool ctrl, shift;
  };
  /// The key presses of the last feed, in order: the studio's shortcuts read them.
  const std::vector<Press>& presses() const { return presses_; }
  /// Events not yet fed.
  bool pending() const { return !events_.empty(); }
  std::size_t size() const { return events_.size(); }

 private:
  struct Event {
    enum class Kind { press, release, character } kind;
    unsigned int code;
  };
  struct Frame {  // what the frame being fed has taken
    bool key_pressed = false, typed = false;
    std::vector<unsigned int> held;  // keys it pressed that it must show down
  };
  bool fits(const Event& e, const ImGuiIO& io, const Frame& f) const;

  std::deque<Event> events_;
  std::vector<Press> presses_;
};

/// Ctrl, Shift, Alt or Super (left or right), by GLFW key code.
bool is_modifier_key(int code);

}  // namespace pagor::studio
