// A seeded random "monkey": thousands of mouse, keyboard and window events anywhere in the studio.
// It asserts what must hold after every frame (UiDriver's invariants: no duplicate IDs, no ImGui
// assertion, values in range, a valid configuration when no edit is in progress), and at the end
// that the worker still answers.

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <random>

#include "studio_test_util.hpp"
#include "ui_driver.hpp"

using namespace pagor;
using namespace pagor::test;

namespace {

int monkey_events() {
  const char* env = std::getenv("PAGOR_MONKEY_EVENTS");
  return env ? std::max(100, std::atoi(env)) : 3000;
}

// Changes the working directory for the test's lifetime (typed relative paths land in it).
struct InDirectory {
  explicit InDirectory(const std::string& dir) : old(std::filesystem::current_path()) {
    std::filesystem::current_path(dir);
  }
  ~InDirectory() { std::filesystem::current_path(old); }
  std::filesystem::path old;
};

void run_monkey(UiDriver& d, std::uint32_t seed, int events) {
  std::mt19937 rng(seed);
  const auto uniform = [&](float a, float b) {
    return std::uniform_real_distribution<float>(a, b)(rng);
  };
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  const int key_codes[] = {
      'F',       'R',     'T',        'S',         'H',         'Z',          'Y',
      'A',       'O',     keys::Left, keys::Right, keys::Enter, keys::Escape, keys::Backspace,
      keys::Tab, keys::F1};
  const char32_t text[] = {U'0', U'1', U'5', U'9', U'.',      U'-',      U'+', U'e',
                           U'x', U'a', U'/', U' ', U'\u00e9', U'\u03b5', U'='};
  const std::pair<int, int> sizes[] = {{640, 480},  {800, 600},   {1024, 768}, {320, 240},
                                       {1280, 720}, {2560, 1440}, {1920, 1080}};
  const int start = d.events();
  int n = 0;
  while (d.events() - start < events) {
    ++n;
    d.set_action("monkey step " + std::to_string(n) + " (seed " + std::to_string(seed) + ")");
    const int what = pick(100);
    const ImVec2 p(uniform(0, static_cast<float>(d.width())),
                   uniform(0, static_cast<float>(d.height())));
    if (what < 30) {  // a click somewhere, often on a widget
      if (what < 20 && !d.widgets().empty()) {
        const auto w =
            d.widgets()[static_cast<std::size_t>(pick(static_cast<int>(d.widgets().size())))];
        d.touch(w);
        d.click(ImVec2(uniform(w.min.x, w.max.x), uniform(w.min.y, w.max.y)), pick(5) == 0 ? 1 : 0);
      } else {
        d.click(p, pick(3));
      }
    } else if (what < 45) {  // a drag (sliders, splitters, the camera)
      d.drag(p, ImVec2(p.x + uniform(-300, 300), p.y + uniform(-200, 200)), pick(4) == 0 ? 1 : 0,
             1 + pick(3));
    } else if (what < 55) {
      d.move(p);
      d.wheel(uniform(-3, 3));
      d.frame();
    } else if (what < 75) {  // a key, sometimes with Ctrl or Shift
      d.press_key(key_codes[pick(static_cast<int>(std::size(key_codes)))], pick(4) == 0,
                  pick(8) == 0);
    } else if (what < 90) {  // characters (fields take them; + and - are shortcuts)
      std::u32string s;
      for (int i = 0, k = 1 + pick(6); i < k; ++i)
        s += text[pick(static_cast<int>(std::size(text)))];
      d.chars(s);
      d.frame();
    } else if (what < 92) {  // a window resize
      const auto [w, h] = sizes[pick(static_cast<int>(std::size(sizes)))];
      d.resize(w, h);
      d.frame();
    } else if (what < 94) {  // Ctrl+click: a slider becomes a text field
      d.set_modifiers(true, false);
      d.click(p);
      d.set_modifiers(false, false);
    } else {
      d.move(p);
      d.frame();
    }
    hide_clouds(d.state());  // frames stay cheap (see hide_clouds)
    // Keep big windows rare: at 2560x1440 llvmpipe needs ~10x the time of a small frame.
    if (d.width() > 1300 && pick(4) == 0) {
      d.resize(800, 600);
      d.frame();
    }
  }
  d.set_action("monkey done, waiting for the worker");
  d.settle();
}

}  // namespace

TEST_CASE("monkey: thousands of seeded random events in the synthetic scene") {
  TempDir tmp;
  InDirectory in(tmp.file(""));
  UiDriver d(synthetic_state(tmp), 800, 600);
  d.settle();
  const int events = monkey_events();
  run_monkey(d, 20261122, events);
  CHECK(d.events() >= events);
  // The studio still works: a deliberate change re-runs and is answered.
  d.state().have_data = true;
  d.state().data.kind = PairSource::Kind::synthetic;
  d.state().config = default_config();
  d.studio().submit_data();
  d.settle();
  REQUIRE(d.studio().worker().snapshot());
  CHECK(d.studio().worker().status().error.empty());
  WARN("monkey: " << d.events() << " events, " << d.frame_count() << " frames, "
                  << d.touched().size() << " widgets hit by name, up to " << d.max_widgets()
                  << " widgets in a frame");
}
