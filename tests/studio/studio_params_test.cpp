// Tuning in the studio: every parameter of the catalog in the generated editor (its range, scale,
// mark and reset), landmark classes added and removed, and sweeps over any one or two parameters
// with the flip view between two settings.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>

#include "panels/param_editor.hpp"
#include "runners/bench_worker.hpp"
#include "studio_test_util.hpp"
#include "ui_driver.hpp"

using namespace pagor;
using namespace pagor::test;
using studio::ui::WidgetKind;

namespace {

bool marked(const studio::ui::WidgetRecord& w) {
  return w.label.rfind("* ", 0) == 0;
}

// The editor's verification.mu slider, once the studio has settled with every node open.
const studio::ui::WidgetRecord& mu_slider(UiDriver& d) {
  d.settle();
  d.open_all_nodes();
  const auto* mu = d.find_param("verification.mu");
  REQUIRE(mu);
  return *mu;
}

}  // namespace

TEST_CASE("every number of the catalog gets a widget over its own range and scale") {
  for (const ConfigField& f : config_fields(default_config())) {
    if (f.kind != FieldKind::number && f.kind != FieldKind::integer) continue;
    INFO(f.path);
    const studio::NumberWidget w = studio::number_widget(f);
    // Inside the range, open ends excluded; a log scale starts above zero.
    CHECK(f.info.range.contains(w.lo));
    CHECK(f.info.range.contains(w.hi));
    CHECK(w.lo < w.hi);
    CHECK((w.kind == studio::NumberWidget::log_slider) == f.info.log_scale);
    if (w.kind == studio::NumberWidget::log_slider) CHECK(w.lo > 0);
    // The preset's value is reachable.
    const double v = *field_number(default_config(), f.path);
    if (std::isnan(f.info.off) || v != f.info.off) CHECK((v >= w.lo && v <= w.hi));
  }
  // Units: a length in metres, a TRIM threshold by the TRIM kind.
  for (const ConfigField& f : config_fields(default_config())) {
    if (f.path == "verification.mu") CHECK(studio::field_label(f, TrimKind::ratio) == "mu [m]");
    if (f.path == "graph.thresholds") {
      CHECK(studio::field_label(f, TrimKind::difference) == "thresholds [m]");
      CHECK(studio::field_label(f, TrimKind::ratio) == "thresholds");
    }
    if (f.path == "verification.voxel_size")
      CHECK(studio::field_tooltip(f, TrimKind::ratio).find("or 0 (off)") != std::string::npos);
  }
}

TEST_CASE("a parameter edited in the editor is marked, reset to the preset, and undone") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 900, 1000);
  const auto* mu = &mu_slider(d);
  CHECK_FALSE(marked(*mu));
  CHECK(mu->has_tooltip);
  CHECK(mu->lo == Approx(0.0).margin(1e-3));  // (0, 1000] on a log scale
  CHECK(mu->hi == Approx(1000.0));
  const ImGuiID id = mu->id;
  REQUIRE(d.type_into_slider(id, U"2.5"));
  d.frames(2);
  CHECK(d.state().config.verification.mu == 2.5);
  const auto* now = d.find_id(id);
  REQUIRE(now);
  CHECK(marked(*now));
  // Its reset button (the small button after it) brings the preset's value back.
  ImGuiID reset = 0;
  for (const auto& w : d.widgets())
    if (w.kind == WidgetKind::button && w.enabled && w.label == "\xe2\x86\xba" &&
        std::abs(w.min.y - now->min.y) < 6)
      reset = w.id;
  REQUIRE(reset);
  REQUIRE(d.click_id(reset));
  CHECK(d.state().config.verification.mu == default_config().verification.mu);
  // Ctrl+Z goes back through the edit.
  d.press_key('Z', true);
  CHECK(d.state().config.verification.mu == 2.5);
  d.press_key('Z', true);
  CHECK(d.state().config.verification.mu == default_config().verification.mu);
  // A value a cross-field rule refuses is said and not kept.
  const auto* fr = d.find_param("landmarks.classes[4].feature_radius");
  REQUIRE(fr);                                   // building: FPFH
  REQUIRE(d.type_into_slider(fr->id, U"0.01"));  // below its normal radius
  d.frames(2);
  CHECK(d.state().config.landmarks.classes[4].feature_radius ==
        default_config().landmarks.classes[4].feature_radius);
  CHECK(d.state().message.level == studio::MessageLevel::error);
  CHECK(d.state().message.text.find("feature_radius") != std::string::npos);
}

TEST_CASE("landmark classes: removed, added from the label scheme, the configuration valid") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 900, 1000);
  d.settle();
  d.open_all_nodes();
  auto& classes = d.state().config.landmarks.classes;
  const std::size_t n = classes.size();
  REQUIRE(classes[3].name == "traffic-sign");
  // The remove button on the fourth class's line.
  std::vector<ImGuiID> removes;
  for (const auto& w : d.widgets())
    if (w.label == "remove") removes.push_back(w.id);
  REQUIRE(removes.size() == n);
  REQUIRE(d.click_id(removes[3]));
  REQUIRE(classes.size() == n - 1);
  CHECK(std::none_of(classes.begin(), classes.end(),
                     [](const ClassParams& c) { return c.name == "traffic-sign"; }));
  d.frames(2);
  // Added back from the scheme's classes: with the preset's parameters for that class.
  REQUIRE(d.click_widget("add class"));
  d.frames(1);
  REQUIRE(d.click_widget("traffic-sign"));
  REQUIRE(classes.size() == n);
  CHECK(classes.back().name == "traffic-sign");
  CHECK(config_to_json(d.state().config).find("traffic-sign") != std::string::npos);
  validate(d.state().config);
  d.settle();
  CHECK(d.studio().worker().status().error.empty());
}

TEST_CASE("a search narrows the parameter editor and the sweep's parameter list") {
  TempDir tmp;
  studio::AppState s = synthetic_state(tmp);
  s.bench.path = PAGOR_SOURCE_DIR "/tests/studio/bench_pairs.txt";
  UiDriver d(s, 1400, 1100);
  d.settle();
  d.open_all_nodes("Pagor Studio");
  const auto params_shown = [&] {
    int n = 0;
    for (const auto& w : d.widgets()) n += w.label.find("###") != std::string::npos;
    return n;
  };
  const int all = params_shown();
  REQUIRE(all > 60);
  const auto* find = d.find("find##parameters", "Pagor Studio");
  REQUIRE(find);
  // Every word, in key or description, case-insensitive: "Noise bound" finds gnc.noise_bound.
  REQUIRE(d.type_into(find->id, U"Noise BOUND"));
  d.frames(2);
  CHECK(d.state().search.parameters == "Noise BOUND");
  CHECK(d.find_param("gnc.noise_bound"));
  CHECK_FALSE(d.find_param("verification.mu"));
  const int narrowed = params_shown();
  CHECK(narrowed >= 1);
  CHECK(narrowed < 10);
  CHECK_FALSE(d.texts("parameters match", "Pagor Studio").empty());
  // A field found is edited as in its section; the list names it by its whole key path.
  const auto* nb = d.find_param("gnc.noise_bound");
  REQUIRE(nb);
  CHECK(nb->label.rfind("gnc.noise_bound", 0) == 0);
  REQUIRE(d.type_into_slider(nb->id, U"0.75"));
  d.frames(2);
  CHECK(d.state().config.gnc.noise_bound == Approx(0.75));
  // A class's field, found among the classes by its key.
  REQUIRE(d.type_into(d.find("find##parameters", "Pagor Studio")->id, U"classes[0] voxel"));
  d.frames(2);
  const auto* cv = d.find_param("landmarks.classes[0].voxel_size");
  REQUIRE(cv);
  CHECK(cv->label.rfind("landmarks.classes[0].voxel_size", 0) == 0);
  // Nothing matches: said so; cleared: every section again.
  REQUIRE(d.type_into(d.find("find##parameters", "Pagor Studio")->id, U"no such words"));
  d.frames(2);
  CHECK(params_shown() == 0);
  CHECK_FALSE(d.texts("0 of", "Pagor Studio").empty());
  // (Typing replaces the selection; a blank search is no search.)
  REQUIRE(d.type_into(d.find("find##parameters", "Pagor Studio")->id, U" "));
  d.frames(2);
  d.open_all_nodes("Pagor Studio");
  CHECK(params_shown() == all);

  // The sweep's parameter list.
  d.open_and_run_bench();
  d.settle_bench();
  const auto* sweep_find = d.find("find##sweep", "Benchmark");
  REQUIRE(sweep_find);
  REQUIRE(d.type_into(sweep_find->id, U"Voxel"));
  REQUIRE(d.click_widget("parameter", "Benchmark"));
  d.frames(2);
  // Listed: exactly the sweepable parameters whose key or description says "voxel".
  std::set<std::string> expected, listed;
  for (const ConfigField& f : config_fields(d.state().config)) {
    std::string text = f.path + " " + f.info.doc;
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const bool sweepable = f.kind == FieldKind::number || f.kind == FieldKind::integer ||
                           f.kind == FieldKind::flag || f.kind == FieldKind::choice ||
                           f.kind == FieldKind::numbers;
    if (sweepable && text.find("voxel") != std::string::npos) expected.insert(f.path);
  }
  for (const auto& w : d.widgets())
    if (w.kind == studio::ui::WidgetKind::selectable && w.label.find('.') != std::string::npos &&
        w.label.find(' ') == std::string::npos)
      listed.insert(w.label);
  CHECK(expected.count("verification.voxel_size"));
  CHECK(listed == expected);
}

TEST_CASE("a 2-D sweep over any parameters from the UI, and the flip view opens a pair with B") {
  TempDir tmp;
  studio::AppState s = synthetic_state(tmp);
  s.config = load_config(PAGOR_SOURCE_DIR "/bench/manifests/semreg-dev.json");
  s.bench.path = PAGOR_SOURCE_DIR "/tests/studio/bench_pairs.txt";
  s.bench.sweep_path = "gnc.noise_bound";
  s.bench.sweep_values = "0.05,1";
  s.bench.sweep_path2 = "verification.mu";
  s.bench.sweep_values2 = "0.3,1";
  UiDriver d(s, 1400, 1100);
  d.settle();
  d.run_bench_and_sweep();
  const auto record = d.studio().bench().sweep_result();
  REQUIRE(record);
  const SweepResult& r = record->result;
  REQUIRE(r.settings.size() == 4);
  CHECK(r.settings[0].setting.label == "gnc.noise_bound=0.05 m mu=0.3 m");
  CHECK(r.settings[3].setting.config.gnc.noise_bound == 1.0);
  // The settings table fits its window: every row's last column (its "apply") whole, also in a
  // narrower window, where the two parameters' setting wraps.
  for (const int width : {1400, 1000}) {
    d.resize(width, 1100);
    d.frames(3);
    int applies = 0;
    for (const auto& w : d.widgets())
      if (w.label.rfind("apply##sweep", 0) == 0) {
        ++applies;
        INFO(w.label << " at " << width << " px: " << w.min.x << ".." << w.max.x << ", visible to "
                     << w.clip_max.x);
        CHECK(w.max.x <= w.clip_max.x + 0.5f);
      }
    CHECK(applies == 4);
  }
  d.resize(1400, 1100);
  d.frames(2);
  // The flip view between the first and last settings lists the pairs that changed.
  d.state().bench.flip_a = 0;
  d.state().bench.flip_b = 3;
  d.frames(2);
  const auto flips = studio::flipped_pairs(r, 0, 3);
  for (std::size_t i = 0; i < r.settings[0].outcomes.size(); ++i) {
    const PairOutcome& a = r.settings[0].outcomes[i];
    const PairOutcome& b = r.settings[3].outcomes[i];
    const bool changed =
        a.success != b.success || a.accepted != b.accepted || a.diagnosis != b.diagnosis;
    CHECK(changed == (std::find(flips.begin(), flips.end(), i) != flips.end()));
  }
  CHECK_FALSE(d.texts(std::to_string(flips.size()) + " of 3 pairs changed", "Benchmark").empty());
  if (!flips.empty()) {
    const std::string name = r.settings[3].outcomes[flips[0]].name;
    REQUIRE(d.click_widget(name + "##flip" + std::to_string(flips[0]), "Benchmark"));
    d.settle();
    CHECK(d.state().main_view == studio::MainView::pair);
    CHECK(d.state().config.gnc.noise_bound == 1.0);
    CHECK(d.state().config.verification.mu == 1.0);
  } else {
    WARN("no pair changed between the settings: the flip view is empty");
  }
}

TEST_CASE(
    "a value typed into a slider is applied once, when the field is left, not per keystroke") {
  TempDir tmp;
  UiDriver d(synthetic_state(tmp), 900, 1000);
  const auto* mu = &mu_slider(d);
  const ImGuiID id = mu->id;
  const double mu0 = d.state().config.verification.mu;
  REQUIRE(mu0 != 0.35);
  const std::uint64_t submitted = d.studio().worker().status().submitted;
  const std::size_t runs = d.studio().run_history().runs().size();
  const std::size_t undo = d.studio().param_history().undo_steps();
  // Ctrl+click opens the slider's text field; "0.35" typed a character a frame, as a user does.
  REQUIRE(d.reveal(id));
  const auto* w = d.find_id(id);
  REQUIRE(w);
  const ImVec2 at(w->min.x + w->frame_w * 0.5f, (w->min.y + w->max.y) * 0.5f);
  d.set_modifiers(true, false);
  d.click(at);
  d.set_modifiers(false, false);
  d.press_key('A', true);
  for (char32_t c : std::u32string(U"0.35")) {
    d.chars(std::u32string(1, c));
    d.frame();
    // Nothing is applied while typing: not 0, not 0.3; no run, no undo step.
    CHECK(d.state().config.verification.mu == mu0);
    CHECK(d.studio().worker().status().submitted == submitted);
    CHECK(d.studio().param_history().undo_steps() == undo);
  }
  d.press_key(keys::Enter);
  d.frames(2);
  CHECK(d.state().config.verification.mu == 0.35);
  CHECK(d.studio().worker().status().submitted == submitted + 1);  // one run, of 0.35
  d.settle();
  CHECK(d.studio().run_history().runs().size() == runs + 1);
  CHECK(d.studio().worker().snapshot()->config.verification.mu == 0.35);
  CHECK(d.studio().param_history().undo_steps() == undo + 1);
  // The change display compares 0.35 with the run before it (mu0), no run in between.
  const auto& changes = d.studio().run_history().changes();
  CHECK(changes.comparable);
  bool some_delta = false;
  for (const auto& l : changes.levels) some_delta = some_delta || (l.d_delta && *l.d_delta != 0);
  CHECK(some_delta);

  // Escape drops what was typed.
  d.set_modifiers(true, false);
  d.click(at);
  d.set_modifiers(false, false);
  d.press_key('A', true);
  d.chars(U"7");
  d.frame();
  d.press_key(keys::Escape);
  d.frames(2);
  CHECK(d.state().config.verification.mu == 0.35);
  CHECK(d.studio().worker().status().submitted == submitted + 1);

  // A click elsewhere applies it, as Enter does.
  d.set_modifiers(true, false);
  d.click(at);
  d.set_modifiers(false, false);
  d.press_key('A', true);
  d.chars(U"1.5");
  d.frame();
  CHECK(d.state().config.verification.mu == 0.35);
  // The right end of the status bar: no widget there.
  d.click(ImVec2(static_cast<float>(d.width() - 4), static_cast<float>(d.height() - 14)));
  d.frames(2);
  CHECK(d.state().config.verification.mu == 1.5);
  CHECK(d.studio().worker().status().submitted == submitted + 2);

  // A drag still applies while the button is held.
  d.settle();
  w = d.find_id(id);
  REQUIRE(w);
  const double before_drag = d.state().config.verification.mu;
  d.move(ImVec2(w->min.x + w->frame_w * 0.5f, at.y));
  d.frame();
  d.button(0, true);
  d.frame();
  d.move(ImVec2(w->min.x + w->frame_w * 0.9f, at.y));
  d.frame();
  CHECK(d.state().config.verification.mu != before_drag);  // live, the button still down
  d.button(0, false);
  d.frame();
}
