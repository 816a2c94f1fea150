// The keyboard at slow frame rates (the window's GLFW callbacks queue every key and character;
// each frame feeds ImGui one logical event), path fields that show what they hold, and a studio
// that asks for frames only while something is to be drawn.

#include <catch2/catch.hpp>
#include <string>

#include "state/input_queue.hpp"
#include "studio_test_util.hpp"
#include "ui_driver.hpp"

using namespace pagor;
using namespace pagor::test;

namespace {

// A long path: longer than the Data panel's field, so that it is shown shortened.
const std::string kLongPath =
    "/nowhere/first-directory/second-directory/third-directory/fourth/scan_000020.pcd";

// Clicks into the source field near its middle (the caret lands mid-path, as a user's click
// does) and returns its ID.
ImGuiID focus_source_field(UiDriver& d) {
  const auto* field = d.find("source cloud", "Pagor Studio");
  REQUIRE(field);
  const ImGuiID id = field->id;
  REQUIRE(d.reveal(id));
  const auto* w = d.find_id(id);
  d.click(ImVec2(w->min.x + w->frame_w * 0.5f, (w->min.y + w->max.y) * 0.5f));
  return id;
}

}  // namespace

TEST_CASE("InputQueue: one logical key event a frame, chords whole, typing after the key") {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  studio::InputQueue q;
  // Ctrl+A, Home, Shift+End, "ab": all between two frames.
  q.key(keys::LeftCtrl, true);
  q.key('A', true);
  q.key('A', false);
  q.key(keys::LeftCtrl, false);
  q.key(keys::Home, true);
  q.key(keys::Home, false);
  q.key(keys::LeftShift, true);
  q.key(keys::End, true);
  q.key(keys::End, false);
  q.key(keys::LeftShift, false);
  q.key('A', true);
  q.character('a');
  q.key('A', false);
  q.key('B', true);
  q.character('b');
  q.key('B', false);
  // Frame 1: the chord Ctrl+A.
  q.feed(io);
  CHECK(io.KeyCtrl);
  CHECK(io.KeysDown[int{'A'}]);
  REQUIRE(q.presses().size() == 1);
  CHECK((q.presses()[0].key == 'A' && q.presses()[0].ctrl));
  // Frame 2: A and Ctrl released, Home pressed without Ctrl.
  q.feed(io);
  CHECK_FALSE(io.KeyCtrl);
  CHECK_FALSE(io.KeysDown[int{'A'}]);
  CHECK(io.KeysDown[keys::Home]);
  // Frame 3: Home released, Shift+End.
  q.feed(io);
  CHECK_FALSE(io.KeysDown[keys::Home]);
  CHECK(io.KeyShift);
  CHECK(io.KeysDown[keys::End]);
  CHECK(io.InputQueueCharacters.Size == 0);
  // Frame 4: End and Shift released, then the typing, both characters in this one frame.
  q.feed(io);
  CHECK_FALSE(io.KeyShift);
  CHECK_FALSE(io.KeysDown[keys::End]);
  REQUIRE(io.InputQueueCharacters.Size == 2);
  CHECK(io.InputQueueCharacters[0] == 'a');
  CHECK(io.InputQueueCharacters[1] == 'b');
  CHECK(q.presses().size() == 2);  // A and B, for the shortcuts
  CHECK_FALSE(q.pending());
  ImGui::DestroyContext();
}

TEST_CASE("keys typed faster than a frame edit the right place in a path field") {
  TempDir tmp;
  UiDriver d(files_state(tmp));
  d.settle();
  focus_source_field(d);
  SECTION("Ctrl+A, Home, Shift+End, typing, Enter: the typed path replaces the old one") {
    d.queue_key(keys::LeftCtrl, true);
    d.queue_tap('A');
    d.queue_key(keys::LeftCtrl, false);
    d.queue_tap(keys::Home);
    d.queue_key(keys::LeftShift, true);
    d.queue_tap(keys::End);
    d.queue_key(keys::LeftShift, false);
    d.queue_chars(U"/tmp/new.pcd");
    d.queue_tap(keys::Enter);
    CHECK(d.drain() >= 5);  // one logical event a frame
    CHECK(d.state().data.source == "/tmp/new.pcd");
  }
  SECTION("Home then typing inserts at the start, End then typing appends") {
    const std::string old = d.state().data.source;
    d.queue_tap(keys::Home);
    d.queue_chars(U"A");
    d.queue_tap(keys::End);
    d.queue_chars(U"Z");
    d.queue_tap(keys::Enter);
    d.drain();
    CHECK(d.state().data.source == "A" + old + "Z");
  }
  d.frames(2);
  CHECK_FALSE(ImGui::GetIO().WantTextInput);  // Enter left the field
}

TEST_CASE("a shortcut key in the queue acts once, and not while a field is edited") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp));
  d.settle();
  REQUIRE_FALSE(d.state().show_help);
  d.queue_tap('H');
  d.queue_chars(U"h");
  d.drain();
  d.frame();
  CHECK(d.state().show_help);
  d.queue_tap('H');
  d.queue_chars(U"h");
  d.drain();
  d.frame();
  CHECK_FALSE(d.state().show_help);
}

TEST_CASE("a long path field shows its start and its end, and a path naming nothing is marked") {
  TempDir tmp;
  studio::AppState s = files_state(tmp);
  const std::string real = s.data.source;
  s.data.source = kLongPath;
  UiDriver d(std::move(s));
  d.settle();
  const auto* field = d.find("source cloud", "Pagor Studio");
  REQUIRE(field);
  const std::string shown = field->text;
  CHECK(shown.size() < kLongPath.size());
  CHECK(shown.find("...") != std::string::npos);
  CHECK(kLongPath.rfind(shown.substr(0, shown.find("...")), 0) == 0);  // the start
  CHECK(shown.substr(shown.find("...") + 3) ==
        kLongPath.substr(kLongPath.size() - (shown.size() - shown.find("...") - 3)));
  INFO("shown: " << shown);
  CHECK(shown.find("scan_000020.pcd") != std::string::npos);
  CHECK(field->warned);  // /nowhere/... names no file
  d.state().data.source = real;
  d.frames(2);
  INFO("path: " << d.state().data.source << " shown "
                << d.find("source cloud", "Pagor Studio")->text);
  CHECK_FALSE(d.find("source cloud", "Pagor Studio")->warned);
}

TEST_CASE("the studio asks for frames only while something is to be drawn") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp));
  d.settle();
  d.frames(4);  // a new result is drawn over a few frames (ImGui fits its tables)
  CHECK_FALSE(d.studio().wants_frame());  // idle: the window waits for events
  d.queue_tap(keys::F1);
  CHECK(d.studio().wants_frame());  // queued input
  d.drain();
  d.frame();
  CHECK_FALSE(d.studio().wants_frame());
  d.studio().save_screenshot();
  CHECK(d.studio().wants_frame());  // a screenshot to write
  d.frame();
  CHECK_FALSE(d.studio().wants_frame());
  d.state().config.verification.mu *= 2;
  d.studio().submit_config();
  CHECK(d.studio().wants_frame());  // a run pending, then its result to show
  d.settle();
  d.frames(4);
  CHECK_FALSE(d.studio().wants_frame());
}
