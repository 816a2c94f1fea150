// The widget walk of the driven-UI tests: acts on every widget the studio shows.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>

#include "ui_driver.hpp"

namespace pagor::test {
namespace {

using studio::ui::WidgetKind;
using studio::ui::WidgetRecord;

struct Saved {
  PairSource data;
  std::string pairs_file, session_path, screenshot_path, export_path;
  studio::BenchViewState bench;
  studio::SearchState search;
};
Saved save(const studio::AppState& s) {
  return {s.data, s.pairs_file, s.session_path, s.screenshot_path, s.export_path, s.bench,
          s.search};
}
void restore(UiDriver& d, const Saved& v, bool resubmit) {
  studio::AppState& s = d.state();
  const bool data_changed = s.data.source_frame != v.data.source_frame ||
                            s.data.target_frame != v.data.target_frame ||
                            s.data.synthetic_seed != v.data.synthetic_seed;
  s.data = v.data;
  s.pairs_file = v.pairs_file;
  s.session_path = v.session_path;
  s.screenshot_path = v.screenshot_path;
  s.export_path = v.export_path;
  s.search = v.search;
  s.bench.path = v.bench.path;
  s.bench.kitti_root = v.bench.kitti_root;
  s.bench.sequence = v.bench.sequence;
  s.bench.config_path = v.bench.config_path;
  s.bench.filter = v.bench.filter;
  s.bench.plot_path = v.bench.plot_path;
  s.bench.sweep_values = v.bench.sweep_values;
  s.bench.sweep_values2 = v.bench.sweep_values2;
  if (resubmit && data_changed) d.studio().submit_data();
}

void act_on_text(UiDriver& d, const WidgetRecord& w) {
  // A result arriving between locating the field and the click can move the panel under the
  // pointer (seen under ASan, where runs are slow): type into a settled layout.
  d.settle();
  const Saved before = save(d.state());
  d.state().message = {};
  const std::u32string text = U"nicht/da \u00fc\u00e9 \u03b5.pcd";
  d.type_into(w.id, text);
  const studio::AppState& s = d.state();
  const std::string expected = "nicht/da \xc3\xbc\xc3\xa9 \xce\xb5.pcd";
  const bool landed =
      s.data.kitti_root == expected || s.data.sequence == expected || s.data.source == expected ||
      s.data.source_labels == expected || s.data.target == expected ||
      s.data.target_labels == expected || s.data.ground_truth == expected ||
      s.data.correspondences == expected ||
      s.pairs_file == expected || s.session_path == expected || s.screenshot_path == expected ||
      s.export_path == expected ||
      s.bench.path == expected || s.bench.kitti_root == expected || s.bench.sequence == expected ||
      s.bench.config_path == expected || s.bench.filter == expected ||
      s.bench.plot_path == expected || s.bench.sweep_values == expected ||
      s.bench.sweep_values2 == expected || s.dialog.directory == expected ||
      s.dialog.filter == expected || s.dialog.name == expected ||
      s.search.parameters == expected || s.search.sweep == expected;
  // A parameter's text (a class name, a list as JSON) lands in the configuration, or is refused
  // with a message saying why.
  const bool parameter = config_to_json(s.config, -1).find(expected) != std::string::npos;
  const bool refused = s.message.level == studio::MessageLevel::error && !s.message.text.empty();
  if (!landed && !parameter && !refused)
    FAIL("typed text did not reach the state, nor was it refused: field '" << w.label << "'");
  restore(d, before, false);
  d.frame();
}

void act_on_int(UiDriver& d, const WidgetRecord& w) {
  const Saved before = save(d.state());
  if (w.label.find("###") != std::string::npos) {  // a typed parameter: below and far above
    for (const std::u32string& t : {std::u32string(U"-7"), std::u32string(U"99999999999")})
      d.type_into(w.id, t);
    restore(d, before, true);
    d.frame();
    return;
  }
  for (const std::u32string& t : {std::u32string(U"-7"), std::u32string(U"99999999999"),
                                  std::u32string(U"x1"), std::u32string(U"3")})
    d.type_into(w.id, t);
  // The +/- buttons at the right end of the field.
  if (d.reveal(w.id)) {
    const WidgetRecord now = *d.find_id(w.id);
    const float h = now.max.y - now.min.y, cy = (now.min.y + now.max.y) * 0.5f;
    d.set_action("click + and - of '" + now.label + "'");
    d.click(ImVec2(now.min.x + now.frame_w - h * 0.5f, cy));
    d.click(ImVec2(now.min.x + now.frame_w - h * 1.6f, cy));
  }
  restore(d, before, true);
  d.frame();
}

void act_on_slider(UiDriver& d, const WidgetRecord& w) {
  if (!d.reveal(w.id)) return;
  WidgetRecord now = *d.find_id(w.id);
  d.set_action("drag slider '" + now.label + "' across its range");
  d.touch(now);
  d.drag(frame_point(now, 0.0f), frame_point(now, 1.0f));
  static int turn = 0;
  if (now.label.find("###") != std::string::npos) {
    // A parameter of the generated editor (a hundred of them, alike): one drag, one typed value
    // out of range, alternating low and high.
    d.type_into_slider(w.id, (turn++ % 2) ? U"-1" : U"1e12");
    return;
  }
  if (!d.reveal(w.id)) return;
  now = *d.find_id(w.id);
  d.drag(frame_point(now, 1.0f), frame_point(now, 0.35f));
  // Out of range both ways, not a number, zero: two per slider, alternating, so that every
  // slider gets one value below and one above (or unparseable) and the walk stays short.
  const std::u32string low = (turn % 2) ? U"0" : U"-1", high = (turn % 2) ? U"abc" : U"1e9";
  ++turn;
  d.type_into_slider(w.id, low);
  d.type_into_slider(w.id, high);
}

void act_on_combo(UiDriver& d, const WidgetRecord& w) {
  for (int option = 0; option < 16; ++option) {
    if (!d.click_id(w.id)) return;
    std::vector<ImGuiID> options;
    for (const WidgetRecord& o : d.widgets())
      if (o.window.rfind("##Combo", 0) == 0 && o.kind == WidgetKind::selectable)
        options.push_back(o.id);
    if (option >= static_cast<int>(options.size())) {
      d.press_key(keys::Escape);
      return;
    }
    if (!d.click_id(options[static_cast<std::size_t>(option)])) d.press_key(keys::Escape);
  }
}

void act_on_splitter(UiDriver& d, const WidgetRecord& w) {
  const ImVec2 c = centre(w);
  const bool vertical = w.max.y - w.min.y > w.max.x - w.min.x;
  const ImVec2 off = vertical ? ImVec2(60, 0) : ImVec2(0, 40);
  d.set_action("drag splitter '" + w.label + "'");
  d.touch(w);
  d.drag(c, ImVec2(c.x + off.x, c.y + off.y));
  if (const WidgetRecord* now = d.find_id(w.id)) {
    const ImVec2 c2 = centre(*now);
    d.drag(c2, ImVec2(c2.x - off.x, c2.y - off.y));
  }
}

}  // namespace

bool skip_parameter_sections(const WidgetRecord& w) {
  return w.kind == WidgetKind::tree_node && w.label == "##section";
}

int exercise_every_widget(UiDriver& d, const std::function<void()>& keep, int max_actions,
                          const std::string& window,
                          const std::function<bool(const WidgetRecord&)>& skip) {
  std::set<ImGuiID> done;
  int actions = 0;
  while (actions < max_actions) {
    const WidgetRecord* next = nullptr;
    for (const WidgetRecord& w : d.widgets()) {
      if (done.count(w.id) || !w.enabled || w.kind == WidgetKind::text) continue;
      if (skip && skip(w)) continue;
      if (w.window.rfind("##Combo", 0) == 0 || w.window.rfind("##Tooltip", 0) == 0) continue;
      if (w.window.rfind(window, 0) != 0) continue;
      next = &w;
      break;
    }
    if (!next) break;
    const WidgetRecord w = *next;
    if (std::getenv("PAGOR_UI_TRACE"))
      std::fprintf(stderr, "act %d: %s '%s' in '%s' (%zu widgets)\n", actions, to_string(w.kind),
                   w.label.c_str(), w.window.c_str(), d.widgets().size());
    done.insert(w.id);
    ++actions;
    const std::string config_before = config_to_json(d.state().config, -1);
    const std::size_t undo_before = d.studio().param_history().undo_steps();
    switch (w.kind) {
      case WidgetKind::slider:
        act_on_slider(d, w);
        break;
      case WidgetKind::input_text:
        act_on_text(d, w);
        break;
      case WidgetKind::input_int:
        act_on_int(d, w);
        break;
      case WidgetKind::combo:
        act_on_combo(d, w);
        break;
      case WidgetKind::splitter:
        act_on_splitter(d, w);
        break;
      case WidgetKind::header:
      case WidgetKind::tree_node:  // closed and opened again, so that what it holds is walked too
        // Both transitions, ending open: fewer widgets after a click means it closed.
        for (int i = 0; i < 3; ++i) {
          const std::size_t before = d.widgets().size();
          if (!d.click_id(w.id)) break;
          d.idle();  // the next click is not a double click
          if (i >= 1 && d.widgets().size() > before) break;
        }
        break;
      default:
        d.click_id(w.id);
        break;
    }
    // Parameter changes are undone with Ctrl+Z, which must give back exactly the configuration
    // before the action (and keeps the walk from piling up slow settings). A field still being
    // edited would take the keys: leave it first.
    d.frames(1);
    if (ImGui::GetIO().WantTextInput) d.press_key(keys::Escape);
    const std::size_t undo_after = d.studio().param_history().undo_steps();
    if (undo_after > undo_before && undo_after < studio::ParamHistory::kMaxSteps) {
      d.set_action("Ctrl+Z after '" + w.label + "'");
      for (std::size_t i = undo_before; i < undo_after; ++i) d.press_key('Z', true);
      const std::string config_after = config_to_json(d.state().config, -1);
      if (config_after != config_before)
        FAIL("undo after '" << w.label << "' did not restore the configuration");
    }
    if (keep) keep();
  }
  return actions;
}

}  // namespace pagor::test
