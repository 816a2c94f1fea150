#include "state/input_queue.hpp"

#include <algorithm>
#include <vector>

namespace pagor::studio {
namespace {

// GLFW's key codes of the modifiers (left, right).
constexpr int kShift[2] = {340, 344}, kCtrl[2] = {341, 345}, kAlt[2] = {342, 346},
              kSuper[2] = {343, 347};

bool down(const ImGuiIO& io, const int (&codes)[2]) {
  return io.KeysDown[codes[0]] || io.KeysDown[codes[1]];
}

bool in_range(unsigned int code) {
  return code < static_cast<unsigned int>(IM_ARRAYSIZE(ImGuiIO::KeysDown));
}

// A key that types a character (GLFW's printable keys and the keypad's), pressed without Ctrl,
// Alt or Super: its character event is what a field reads, so its press and release need no
// frame of their own.
bool types(const ImGuiIO& io, unsigned int code) {
  const bool printable = (code >= 32 && code <= 96) || code == 161 || code == 162 ||
                         (code >= 320 && code <= 334) || code == 336;
  return printable && !down(io, kCtrl) && !down(io, kAlt) && !down(io, kSuper);
}

}  // namespace

bool is_modifier_key(int code) {
  return code >= kShift[0] && code <= kSuper[1];
}

void InputQueue::key(int code, bool is_down) {
  if (code < 0 || !in_range(static_cast<unsigned int>(code))) return;
  events_.push_back(
      {is_down ? Event::Kind::press : Event::Kind::release, static_cast<unsigned int>(code)});
}

void InputQueue::character(unsigned int codepoint) {
  if (codepoint != 0) events_.push_back({Event::Kind::character, codepoint});
}

// Whether event `e` still belongs to this frame, given what the frame has taken so far.
bool InputQueue::fits(const Event& e, const ImGuiIO& io, const Frame& f) const {
  const int code = static_cast<int>(e.code);
  switch (e.kind) {
    case Event::Kind::character:
      return !f.key_pressed;  // typed after a key press: after it has been seen
    case Event::Kind::press:
      // One key press a frame, after the characters typed before it; a typing key rides along
      // with the characters; a modifier pressed after a key belongs to the next chord.
      if (f.key_pressed) return false;
      return types(io, e.code) || is_modifier_key(code) || !f.typed;
    case Event::Kind::release:
      // A key is held for the frame of its press; a chord's modifier stays down for the frame
      // of its key.
      if (std::find(f.held.begin(), f.held.end(), e.code) != f.held.end()) return false;
      return !(is_modifier_key(code) && (f.key_pressed || f.typed));
  }
  return false;
}

void InputQueue::feed(ImGuiIO& io) {
  presses_.clear();
  if (events_.empty()) return;
  Frame f;
  while (!events_.empty() && fits(events_.front(), io, f)) {
    const Event e = events_.front();
    events_.pop_front();
    if (e.kind == Event::Kind::character) {
      io.AddInputCharacter(e.code);
      f.typed = true;
      continue;
    }
    const int code = static_cast<int>(e.code);
    if (e.kind == Event::Kind::release) {
      io.KeysDown[e.code] = false;
      continue;
    }
    const bool typing = types(io, e.code);
    io.KeysDown[e.code] = true;
    if (is_modifier_key(code)) {
      f.held.push_back(e.code);
    } else {
      presses_.push_back({code, down(io, kCtrl), down(io, kShift)});
      if (!typing) f.held.push_back(e.code);
      f.key_pressed = f.key_pressed || !typing;
      f.typed = f.typed || typing;
    }
  }
  io.KeyCtrl = down(io, kCtrl);
  io.KeyShift = down(io, kShift);
  io.KeyAlt = down(io, kAlt);
  io.KeySuper = down(io, kSuper);
}

}  // namespace pagor::studio
